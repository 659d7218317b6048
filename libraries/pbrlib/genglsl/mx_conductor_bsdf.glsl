// <conductor_bsdf>: GGX reflection off a metal of complex index ior + i extinction (exact
// conductor Fresnel), with an optional thin film. Opaque: nothing passes to a base.
#include "lib/mx_specular.glsl"
#pragma shadergen feature FRESNEL_CONDUCTOR
#pragma shadergen feature THIN_FILM unless thinfilm_thickness <= 0
#pragma shadergen feature RETROREFLECTIVE unless retroreflective == false

// Once per shading point (lib/mx_specular.glsl).
void mx_conductor_bsdf_prepare(ClosureData closureData, float weight, vec3 ior_n, vec3 ior_k, vec2 roughness,
                               bool retroreflective, float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X,
                               int distribution, out SpecularLobe lobe)
{
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_CONDUCTOR, ior_n, ior_k, vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);
    lobe = mx_specular_lobe_prepare(closureData, weight, vec3(1.0), roughness, retroreflective, fd, N, X, distribution, 0);
}

// In each context.
void mx_conductor_bsdf(ClosureData closureData, SpecularLobe lobe, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    int context = closureData.closureType;
    if (lobe.weight == 0.0 || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;
#ifdef MX_FEATURE_LIGHTS
    vec3 reflected = context == CLOSURE_TYPE_REFLECTION ? mx_specular_reflection(closureData, lobe) : lobe.environment;
#else
    vec3 reflected = lobe.environment;
#endif
    bsdf.response = reflected * lobe.weight;
}
