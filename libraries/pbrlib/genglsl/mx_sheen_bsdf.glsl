// <sheen_bsdf>: back-scattering of fibres layered over a base (lib/mx_sheen.glsl). mode 0:
// conty_kulla (microfiber), 1: zeltner (LTC).
#include "lib/mx_closure_type.glsl"
#include "lib/mx_sheen.glsl"
#include "lib/mx_environment_fis.glsl"

// The mean radiance under the sheen lobe towards V (its environment term over its albedo), by
// filtered importance sampling as the GGX lobes' (mx_environment_sample): u_envRadianceSamples
// directions (Fibonacci points) drawn from the LTC lobe exactly, or for the microfiber lobe from
// the cosine lobe (its fibre normals' distribution would mostly reflect V below the horizon at
// facing views: standard_surface_velvet at fis 16, 28.1 dB against the ground truth where the
// cosine lobe gives 31.1), each read at its footprint and weighted by the lobe's BRDF times
// cosine over the density it was drawn with (a ratio estimator: the lobe's albedo comes from its
// table, so a uniform environment gives exactly its radiance). The irradiance at N is the mean
// under the cosine lobe, not this one: the fibres scatter light arriving along the surface, so a
// sphere's sky-facing rim sees more of the horizon and less of the zenith than the cosine lobe, the
// ground-facing rim the reverse (velvet: 25.8 dB as the irradiance, 39.0 dB at fis 256). With
// fewer than two samples (the prefiltered way's one lookup) that irradiance stands in for it.
vec3 mx_sheen_environment(vec3 N, vec3 V, float NdotV, float r, bool ltc)
{
    int count = u_envRadianceSamples;
    if (count < 2)
        return mx_environment_irradiance(N);
    mat3 frame = mx_tangent_frame(N, V);  // x towards V: the LTC's frame (mx_sheen_ltc_frame)
    mat3 toMap = mat3(u_envMatrix) * frame;
    vec3 Vt = V * frame;
    vec3 radiance = vec3(0.0);
    float weights = 0.0;
    for (int i = 0; i < count; i++)
    {
        vec2 u = mx_fibonacci_point(i, count);
        float pdf;
        float w = 1.0;
        vec3 Lt;
        if (ltc)
        {
            Lt = mx_sheen_ltc_sample(u, NdotV, r);
            pdf = mx_sheen_ltc(Lt, Vt, vec3(0.0, 0.0, 1.0), NdotV, r);
        }
        else
        {
            Lt = mx_cosine_sample(u);
            pdf = max(mx_cosine_pdf(Lt.z), MX_EPS);
            w = Lt.z > 0.0 ? mx_sheen_microfiber(Lt.z, NdotV, clamp(normalize(Lt + Vt).z, 0.0, 1.0), r) / max(pdf, MX_EPS)
                           : 0.0;
        }
        radiance += w * mx_environment_sample(toMap * Lt, pdf, count);
        weights += w;
    }
    return radiance * (u_envLightIntensity / max(weights, MX_EPS));
}

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
        bsdf.response = mx_sheen_environment(N, V, NdotV, r, ltc) * tint * (albedo * weight);
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
