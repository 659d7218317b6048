// <oren_nayar_diffuse_bsdf>: opaque diffuse reflection, Lambert at roughness 0.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_diffuse.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_oren_nayar_diffuse_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N,
                                bool energy_compensation, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);  // opaque: nothing reaches the layers below
    if (weight < MX_EPS)
        return;

    vec3 V = closureData.V;
    N = mx_facing_normal(N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);

    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
        float LdotV = clamp(dot(L, V), MX_EPS, 1.0);
        vec3 f = energy_compensation ? mx_eon(NdotV, NdotL, LdotV, roughness, color)
                                     : color * mx_oren_nayar(NdotV, NdotL, LdotV, roughness);
        bsdf.response = f * (closureData.occlusion * weight * NdotL * MX_INV_PI);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        vec3 albedo = energy_compensation ? mx_eon_albedo(NdotV, roughness, color)
                                          : color * mx_oren_nayar_albedo(NdotV, roughness);
        bsdf.response = mx_environment_irradiance(N) * albedo * weight;
    }
}
