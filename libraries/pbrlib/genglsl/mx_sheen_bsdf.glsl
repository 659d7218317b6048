// <sheen_bsdf>: back-scattering of fibres layered over a base (lib/mx_sheen.glsl). mode 0:
// conty_kulla (microfiber), 1: zeltner (LTC).
#include "lib/mx_closure_type.glsl"
#include "lib/mx_sheen.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_sheen_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N, int mode, inout BSDF bsdf)
{
    int context = closureData.closureType;
    if (mx_weight_is_zero(weight) || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    bool ltc = mode != 0;
    float r = mx_clamp_finite(roughness, ltc ? 0.01 : 0.0, 1.0);  // the LTC fits hold on [0.01, 1]
    float albedo = clamp(ltc ? mx_sheen_ltc_albedo(NdotV, r) : mx_sheen_albedo_renormalised(NdotV, r), 0.0, 1.0);
    vec3 tint = max(color, 0.0);
    // What the fibres reflect (a colourless albedo, as the model's) does not reach the base; light
    // from a lamp crosses them on its way in too.
    bsdf.throughput = vec3(max(1.0 - albedo * weight, 0.0));

    if (context == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * tint * (albedo * weight);
    }
#ifdef MX_FEATURE_LIGHTS
    else  // REFLECTION
    {
        vec3 L = closureData.L;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            return;
        float albedoL = clamp(ltc ? mx_sheen_ltc_albedo(NdotL, r) : mx_sheen_albedo_renormalised(NdotL, r), 0.0, 1.0);
        bsdf.throughput *= max(1.0 - albedoL * weight, 0.0);
        float f = ltc ? albedo * mx_sheen_ltc(L, V, N, NdotV, r)  // the LTC lobe carries the cosine
                      : mx_sheen_microfiber(NdotL, NdotV, clamp(dot(N, normalize(L + V)), 0.0, 1.0), r);
        bsdf.response = tint * (f * closureData.occlusion * weight);
    }
#endif
}
