// <conductor_bsdf>: GGX reflection off a metal of complex index ior + i extinction (exact
// conductor Fresnel), with an optional thin film. Opaque: nothing passes to a base.
#include "lib/mx_specular.glsl"

void mx_conductor_bsdf(ClosureData closureData, float weight, vec3 ior_n, vec3 ior_k, vec2 roughness, bool retroreflective,
                       float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X, int distribution, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    int context = closureData.closureType;
    if (mx_weight_is_zero(weight) || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    N = mx_usable_normal(N, closureData.N);
    vec3 V = retroreflective ? reflect(-closureData.V, N) : closureData.V;
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_CONDUCTOR, max(ior_n, 0.0), max(ior_k, 0.0), vec3(0.0), vec3(0.0),
                                     vec3(0.0), 0.0, thinfilm_thickness, thinfilm_ior);
    vec3 reflected;  // opaque: no layer below needs it
    vec3 lobe = mx_specular_lobe(closureData, mx_facing_normal(N, V), V, X, mx_ggx_clamp_alpha(roughness), fd, vec3(0.0),
                                 reflected);
    bsdf.response = lobe * weight;
}
