// <conductor_bsdf>: GGX reflection off a metal of complex index ior + i extinction, with an
// optional thin film. Opaque.
#include "lib/mx_specular.glsl"

void mx_conductor_bsdf(ClosureData closureData, float weight, vec3 ior_n, vec3 ior_k, vec2 roughness, bool retroreflective,
                       float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X, int distribution, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    int context = closureData.closureType;
    if (weight < MX_EPS || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    vec3 V = retroreflective ? reflect(-closureData.V, N) : closureData.V;
    N = mx_facing_normal(N, V);
    vec2 alpha = clamp(roughness, MX_EPS, 1.0);
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_CONDUCTOR, ior_n, ior_k, vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);
    vec3 comp;
    bsdf.response = mx_specular_lobe(closureData, N, V, X, alpha, fd, comp) * weight;
}
