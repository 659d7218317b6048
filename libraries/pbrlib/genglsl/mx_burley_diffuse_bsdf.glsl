// <burley_diffuse_bsdf>: opaque diffuse reflection with Burley's (Disney) retro-reflection.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_diffuse.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_burley_diffuse_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (weight < MX_EPS)
        return;

    vec3 V = closureData.V;
    N = mx_facing_normal(N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);

    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
        float LdotH = clamp(dot(L, normalize(L + V)), MX_EPS, 1.0);
        bsdf.response = color * (closureData.occlusion * weight * NdotL * MX_INV_PI) *
                        mx_burley(NdotV, NdotL, LdotH, roughness);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * mx_burley_albedo(NdotV, roughness) * color * weight;
    }
}
