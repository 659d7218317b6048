// <dielectric_bsdf>: GGX reflection off, and refraction through, a dielectric interface (exact
// dielectric Fresnel), with an optional thin film. scatter_mode: 0 R, 1 T, 2 RT.
#include "lib/mx_specular.glsl"
#include "lib/mx_albedo_dielectric.glsl"

void mx_dielectric_bsdf(ClosureData closureData, float weight, vec3 tint, float ior, vec2 roughness, bool retroreflective,
                        float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X, int distribution, int scatter_mode,
                        inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (mx_weight_is_zero(weight) || (scatter_mode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;

    // Retro-reflection mirrors the view about the normal (reflection and environment only).
    N = mx_usable_normal(N, closureData.N);
    vec3 V = (retroreflective && !transmission) ? reflect(-closureData.V, N) : closureData.V;
    N = mx_facing_normal(N, V);
    vec2 alpha = mx_ggx_clamp_alpha(roughness);
    float eta = max(ior, 0.0);
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(eta), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);
    // What the interface reflects, multiple scattering included, does not reach the layers below.
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float isoAlpha = mx_ggx_isotropic_alpha(alpha);
    float tableAlbedo = mx_dielectric_albedo(NdotV, isoAlpha, eta);
    vec3 reflected;
    vec3 lobe = mx_specular_lobe(closureData, N, V, X, alpha, fd, vec3(tableAlbedo), reflected);
    bsdf.throughput = max(vec3(1.0) - reflected * weight, 0.0);
    if (context == CLOSURE_TYPE_REFLECTION)  // the light crosses the interface on its way in too
    {
        float NdotL = dot(N, closureData.L);
        vec3 reflectedL = mx_specular_albedo(NdotL, alpha, fd, vec3(mx_dielectric_albedo(NdotL, isoAlpha, eta)));
        bsdf.throughput *= max(vec3(1.0) - reflectedL * weight, 0.0);
    }

    vec3 tintRGB = max(tint, 0.0);
    if (!transmission)
        bsdf.response = lobe * tintRGB * weight;
    else if (scatter_mode != 0)
        bsdf.response = mx_surface_transmission(N, V, X, alpha, distribution, fd, tintRGB) * weight;
}
