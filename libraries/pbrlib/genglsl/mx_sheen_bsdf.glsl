// <sheen_bsdf>: back-scattering of fibres (cloth, dust) layered over a base. mode: 0 conty_kulla
// (Imageworks), 1 zeltner (LTC, multiple scattering).
#include "lib/mx_closure_type.glsl"
#include "lib/mx_sheen.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_sheen_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N, int mode, inout BSDF bsdf)
{
    int context = closureData.closureType;
    if (weight < MX_EPS || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    vec3 V = closureData.V;
    N = mx_facing_normal(N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    bool ltc = mode != 0;
    float r = ltc ? clamp(roughness, 0.01, 1.0) : roughness;  // the LTC fits hold on [0.01, 1]
    float albedo = ltc ? mx_sheen_ltc_albedo(NdotV, r) : mx_sheen_iw_albedo(NdotV, r);

    if (context == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float f;
        if (ltc)
        {
            f = albedo * mx_sheen_ltc(L, V, N, NdotV, r);  // the LTC lobe carries the cosine
        }
        else
        {
            float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
            float NdotH = clamp(dot(N, normalize(L + V)), MX_EPS, 1.0);
            f = mx_sheen_iw(NdotL, NdotV, NdotH, r) * NdotL;
        }
        bsdf.response = color * (f * closureData.occlusion * weight);
    }
    else
    {
        bsdf.response = mx_environment_irradiance(N) * color * albedo * weight;
    }
    bsdf.throughput = vec3(1.0 - albedo * weight);
}
