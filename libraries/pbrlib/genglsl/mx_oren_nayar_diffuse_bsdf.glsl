// <oren_nayar_diffuse_bsdf>: opaque rough diffuse reflection (lib/mx_diffuse.glsl), Lambert at
// roughness 0; energy_compensation selects EON, the energy-preserving model of OpenPBR.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_diffuse.glsl"
#include "lib/mx_environment_fis.glsl"
#pragma shadergen feature ROUGH_DIFFUSE unless roughness <= 0

void mx_oren_nayar_diffuse_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N,
                                bool energy_compensation, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float sigma = mx_clamp_finite(roughness, 0.0, 1.0);
    vec3 rho = max(color, 0.0);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
#ifdef MX_FEATURE_ROUGH_DIFFUSE
        vec3 albedo = energy_compensation ? mx_eon_albedo(NdotV, sigma, rho)
                                          : rho * mx_oren_nayar_albedo_renormalised(NdotV, sigma);
#else
        vec3 albedo = rho;
#endif
        bsdf.response = mx_environment_irradiance(N) * albedo * weight;
    }
#ifdef MX_FEATURE_LIGHTS
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            return;
        float LdotV = dot(L, V);
#ifdef MX_FEATURE_ROUGH_DIFFUSE
        vec3 f = energy_compensation ? mx_eon(NdotV, NdotL, LdotV, sigma, rho)
                                     : rho * mx_oren_nayar(NdotV, NdotL, LdotV, sigma);
#else
        vec3 f = rho;  // every diffuse lobe of this shader is smooth: both models are Lambert at sigma 0
#endif
        bsdf.response = f * (closureData.occlusion * weight * NdotL * MX_INV_PI);
    }
#endif
}
