// Image-based lighting from a prefiltered environment, by the split sum (Karis 2013, "Real Shading
// in Unreal Engine 4"): the radiance map convolved with the GGX lobe per roughness (computed by the
// renderer, shadergen/render/prefilter.py, with N = V = R), times the BRDF's directional albedo
// from our DFG table (mx_environment_dfg.glsl, tools/fit_dfg.py). One lookup instead of
// u_envRadianceSamples; used when the shader is compiled with MX_ENV_PREFILTER defined, and then
// u_envRadiance must hold the prefiltered chain.
#include "mx_fresnel.glsl"
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
// fd.refraction, after passing through a solid sphere of index fd.ior.x; `albedo` as
// mx_environment_radiance() gives it. The lobe's directional albedo comes from the DFG table's
// quadrature rule, with F (reflection, times Turquin's multiple-scattering factor 1 + F (1 - E) / E
// as the sampled path applies it) or with 1 - F averaged over the lobe (refraction).
vec3 mx_environment_prefiltered_radiance(vec3 N, vec3 V, vec2 alpha, FresnelData fd, out vec3 albedo)
{
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float avgAlpha = clamp(sqrt(alpha.x * alpha.y), 0.0, 1.0);
    vec4 rule = mx_environment_dfg_rule(NdotV, avgAlpha);
    vec3 reflected = rule.z * mx_fresnel_eval(rule.x, fd) + rule.w * mx_fresnel_eval(rule.y, fd);
    float E = max(rule.z + rule.w, MX_EPS);  // the albedo with F = 1
    vec3 L;
#ifdef MX_FEATURE_REFRACTION
    if (fd.refraction)
    {
        albedo = vec3(1.0) - reflected / E;
        L = mx_refraction_solid_sphere(-V, N, fd.ior.x);
    }
    else
#endif
    {
        albedo = reflected * (vec3(1.0) + mx_fresnel_eval(NdotV, fd) * ((1.0 - E) / E));
        L = reflect(-V, N);
    }
    return mx_envmap_fetch(u_envRadiance, L, mx_prefiltered_lod(avgAlpha)) * albedo * u_envLightIntensity;
}
