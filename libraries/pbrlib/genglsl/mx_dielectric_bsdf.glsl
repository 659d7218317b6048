// <dielectric_bsdf>: GGX reflection off, and refraction through, a dielectric interface (exact
// dielectric Fresnel), with an optional thin film. scatter_mode: 0 R, 1 T, 2 RT.
#include "lib/mx_specular.glsl"
#include "lib/mx_albedo_dielectric.glsl"
#pragma shadergen feature FRESNEL_DIELECTRIC
#pragma shadergen feature THIN_FILM unless thinfilm_thickness <= 0
#pragma shadergen feature RETROREFLECTIVE unless retroreflective == false
#pragma shadergen feature REFRACTION unless scatter_mode == R
#pragma shadergen feature DIELECTRIC_LEAVING unless ior >= 1

// Once per shading point (lib/mx_specular.glsl); the albedo towards V is needed under lights only.
void mx_dielectric_bsdf_prepare(ClosureData closureData, float weight, vec3 tint, float ior, vec2 roughness,
                                bool retroreflective, float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X,
                                int distribution, int scatter_mode, out SpecularLobe lobe)
{
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(ior), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0),
                                     0.0, thinfilm_thickness, thinfilm_ior);
    lobe = mx_specular_lobe_prepare(closureData, weight, tint, roughness, retroreflective, fd, N, X, distribution,
                                    scatter_mode);
#ifdef MX_FEATURE_TRANSMISSION
#ifdef MX_FEATURE_REFRACTION
    mx_specular_lobe_refract(closureData, fd, lobe.tint, scatter_mode, lobe);
#endif
#endif
#ifdef MX_FEATURE_LIGHTS
    float NdotV = clamp(dot(lobe.N, lobe.V), MX_EPS, 1.0);
    float tableAlbedo = mx_dielectric_albedo(NdotV, mx_ggx_isotropic_alpha(lobe.alpha), fd.ior.x);
    lobe.albedo = mx_specular_albedo(NdotV, lobe.alpha, fd, vec3(tableAlbedo));
#endif
}

// In each context. What the interface reflects, multiple scattering included, does not reach the
// layers below.
void mx_dielectric_bsdf(ClosureData closureData, SpecularLobe lobe, inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (lobe.weight == 0.0 || (lobe.scatterMode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;

    if (context == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.throughput = mx_specular_throughput(lobe.environmentAlbedo, lobe.weight);
        bsdf.response = lobe.environment * lobe.tint * lobe.weight;
    }
#ifdef MX_FEATURE_TRANSMISSION
    else if (transmission)
    {
        bsdf.throughput = mx_specular_throughput(mx_specular_transmission_albedo(closureData, lobe), lobe.weight);
#ifdef MX_FEATURE_REFRACTION
        if (lobe.scatterMode != 0)
            bsdf.response = lobe.refracted * lobe.weight;
#endif
    }
#endif
#ifdef MX_FEATURE_LIGHTS
    else  // REFLECTION
    {
        // the light crosses the interface on its way in too
        float NdotL = dot(lobe.N, closureData.L);
        float tableAlbedoL = mx_dielectric_albedo(NdotL, mx_ggx_isotropic_alpha(lobe.alpha), lobe.fd.ior.x);
        vec3 reflectedL = mx_specular_albedo(NdotL, lobe.alpha, lobe.fd, vec3(tableAlbedoL));
        bsdf.throughput = mx_specular_throughput(lobe.albedo, lobe.weight) * mx_specular_throughput(reflectedL, lobe.weight);
        bsdf.response = mx_specular_reflection(closureData, lobe) * lobe.tint * lobe.weight;
    }
#endif
}
