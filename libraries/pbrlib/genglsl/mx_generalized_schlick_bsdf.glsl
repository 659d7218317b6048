// <generalized_schlick_bsdf>: GGX reflection (and refraction) with an artist-set Fresnel curve
// through color0 (normal), color82 (about 82 degrees) and color90 (grazing), with `exponent`.
#include "lib/mx_specular.glsl"

void mx_generalized_schlick_bsdf(ClosureData closureData, float weight, vec3 color0, vec3 color82, vec3 color90,
                                 float exponent, vec2 roughness, bool retroreflective, float thinfilm_thickness,
                                 float thinfilm_ior, vec3 N, vec3 X, int distribution, int scatter_mode, inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (mx_weight_is_zero(weight) || (scatter_mode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;

    N = mx_usable_normal(N, closureData.N);
    vec3 V = (retroreflective && !transmission) ? reflect(-closureData.V, N) : closureData.V;
    N = mx_facing_normal(N, V);
    vec2 alpha = mx_ggx_clamp_alpha(roughness);
    vec3 F0 = max(color0, 0.0);
    vec3 F90 = max(color90, 0.0);
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_SCHLICK, vec3(0.0), vec3(0.0), F0, max(color82, 0.0), F90, exponent,
                                     thinfilm_thickness, thinfilm_ior);
    // Each channel passes to the layers below what this lobe does not reflect in that channel.
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float isoAlpha = mx_ggx_isotropic_alpha(alpha);
    vec3 tableAlbedo = mx_ggx_albedo(NdotV, isoAlpha, F0, F90);
    vec3 reflected;
    vec3 lobe = mx_specular_lobe(closureData, N, V, X, alpha, fd, tableAlbedo, reflected);
    bsdf.throughput = max(vec3(1.0) - reflected * weight, 0.0);
    if (context == CLOSURE_TYPE_REFLECTION)  // the light crosses the interface on its way in too
    {
        float NdotL = dot(N, closureData.L);
        vec3 reflectedL = mx_specular_albedo(NdotL, alpha, fd, mx_ggx_albedo(NdotL, isoAlpha, F0, F90));
        bsdf.throughput *= max(vec3(1.0) - reflectedL * weight, 0.0);
    }

    if (!transmission)
        bsdf.response = lobe * weight;
    else if (scatter_mode != 0)
    {
        // Refracted with the index whose normal reflectance is the mean of color0.
        fd.ior = vec3(mx_f0_to_ior(dot(F0, vec3(1.0 / 3.0))));
        bsdf.response = mx_surface_transmission(N, V, X, alpha, distribution, fd, vec3(1.0)) * weight;
    }
}
