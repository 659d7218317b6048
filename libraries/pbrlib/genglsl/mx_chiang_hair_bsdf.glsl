// <chiang_hair_bsdf>: hair and fur (lib/mx_hair.glsl) for fibres along `curve_direction`. Lights
// are scattered by the full model; the environment by a GGX dielectric lobe standing in for it,
// with the three lobes' mean roughness and tint.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_hair.glsl"
#include "lib/mx_specular.glsl"
#pragma shadergen feature FRESNEL_DIELECTRIC

void mx_chiang_hair_bsdf(ClosureData closureData, vec3 tint_R, vec3 tint_TT, vec3 tint_TRT, float ior,
                         vec2 roughness_R, vec2 roughness_TT, vec2 roughness_TRT, float cuticle_angle,
                         vec3 absorption_coefficient, vec3 N, vec3 X, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        float eta = mx_clamp_finite(ior, 1.0, MX_MAX_IOR);
        FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(eta), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0),
                                         0.0, 0.0, 1.0);
        vec2 alpha = mx_ggx_clamp_alpha((roughness_R + roughness_TT + roughness_TRT) / vec2(3.0));
        vec3 tint = max((tint_R + tint_TT + tint_TRT) / vec3(3.0), 0.0);
        vec3 reflected;
        bsdf.response = mx_environment_radiance(N, V, X, alpha, 0, fd, reflected) * tint;
    }
#ifdef MX_FEATURE_LIGHTS
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 tints[3] = vec3[3](tint_R, tint_TT, tint_TRT);
        vec2 roughness[3] = vec2[3](mx_clamp_finite(roughness_R, 0.001, 1.0), mx_clamp_finite(roughness_TT, 0.001, 1.0),
                                    mx_clamp_finite(roughness_TRT, 0.001, 1.0));
        float alpha = (clamp(cuticle_angle, 0.0, 1.0) - 0.5) * MX_PI;  // [0, 1] -> [-pi/2, pi/2]
        bsdf.response = mx_hair_scattering(closureData.L, V, N, X, tints, roughness, ior, alpha, absorption_coefficient) *
                        closureData.occlusion;
    }
#endif
}
