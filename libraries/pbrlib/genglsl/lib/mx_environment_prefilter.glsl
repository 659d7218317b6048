// Image-based lighting from a prefiltered environment, by the split sum (Karis 2013, "Real Shading
// in Unreal Engine 4"): the radiance map convolved with the GGX lobe per roughness (computed by the
// renderer, shadergen/render/prefilter.py, with N = V = R), times the BRDF's directional albedo
// from our DFG table (mx_environment_dfg.glsl, tools/fit_dfg.py). One lookup instead of
// u_envRadianceSamples; used when the shader is compiled with MX_ENV_PREFILTER defined, and then
// u_envRadiance must hold the prefiltered chain.
#include "mx_environment_map.glsl"
#include "mx_environment_dfg.glsl"

// Mip level of the prefiltered chain holding the GGX lobe of `alpha`: level 0 is the unfiltered
// map, level l >= 1 the lobe of alpha = 2^(l + 4 - u_envRadianceMips) up to alpha 1 (texels about
// as wide as the lobe), in between the chain's trilinear filtering blends neighbouring lobes.
float mx_prefiltered_lod(float alpha)
{
    float roughest = max(float(u_envRadianceMips - 4), 1.0);
    float firstAlpha = exp2(1.0 - roughest);
    return alpha < firstAlpha ? alpha / firstAlpha : min(log2(alpha) + roughest, roughest);
}

// Light leaving a point with normal N towards V after one GGX bounce of roughness alpha, or, with
// fd.refraction, after passing through a solid sphere of index fd.ior.x.
vec3 mx_environment_prefiltered_radiance(vec3 N, vec3 V, vec2 alpha, FresnelData fd)
{
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float avgAlpha = clamp(sqrt(alpha.x * alpha.y), 0.0, 1.0);
    float lod = mx_prefiltered_lod(avgAlpha);
    if (fd.refraction)
    {
        // what the interface does not reflect, its Fresnel averaged by the reflection's own rule
        vec4 rule = mx_environment_dfg_rule(NdotV, avgAlpha);
        vec3 F = (rule.z * mx_fresnel_eval(rule.x, fd) + rule.w * mx_fresnel_eval(rule.y, fd)) / max(rule.z + rule.w, MX_EPS);
        vec3 L = mx_refraction_solid_sphere(-V, N, fd.ior.x);
        return mx_envmap_fetch(u_envRadiance, L, lod) * (vec3(1.0) - F) * u_envLightIntensity;
    }
    vec3 Li = mx_envmap_fetch(u_envRadiance, reflect(-V, N), lod);
    return Li * mx_environment_dfg(NdotV, avgAlpha, fd) * u_envLightIntensity;
}
