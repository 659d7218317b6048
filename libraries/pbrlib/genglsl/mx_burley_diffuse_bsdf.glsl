// <burley_diffuse_bsdf>: opaque diffuse reflection with Burley's retro-reflection, renormalised
// so that it never reflects more light than arrives (lib/mx_diffuse.glsl).
#include "lib/mx_closure_type.glsl"
#include "lib/mx_diffuse.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_burley_diffuse_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float r = mx_clamp_finite(roughness, 0.0, 1.0);
    vec3 rho = max(color, 0.0);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * rho * (mx_burley_albedo_renormalised(NdotV, r) * weight);
    }
#ifdef MX_FEATURE_LIGHTS
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            return;
        float LdotH = clamp(dot(L, normalize(L + V)), 0.0, 1.0);
        bsdf.response = rho * (mx_burley(NdotV, NdotL, LdotH, r) * closureData.occlusion * weight * NdotL * MX_INV_PI);
    }
#endif
}
