// <subsurface_bsdf>: subsurface scattering approximated at the shading point (lib/mx_subsurface.glsl);
// the environment lights it as a diffuse surface of the same albedo. Opaque.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_subsurface.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_subsurface_bsdf(ClosureData closureData, float weight, vec3 color, vec3 radius, float anisotropy, vec3 N,
                        inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    N = mx_shading_normal(N, closureData.N, closureData.V);
    vec3 albedo = clamp(color, 0.0, 1.0);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * albedo * weight;
    }
#ifdef MX_FEATURE_LIGHTS
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        // Occlusion hides the light that arrives directly, not the light diffused from around.
        float direct = clamp(dot(N, closureData.L), 0.0, 1.0);
        float visible = 1.0 - direct * (1.0 - closureData.occlusion);
        bsdf.response = mx_subsurface_scatter(N, closureData.L, closureData.P, albedo, max(radius, 0.0)) * (visible * weight);
    }
#endif
}
