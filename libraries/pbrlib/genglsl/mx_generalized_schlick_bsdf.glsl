// <generalized_schlick_bsdf>: GGX reflection (and refraction) with an artist-set Fresnel curve
// through color0 (normal), color82 (about 82 degrees) and color90 (grazing), with `exponent`.
#include "lib/mx_specular.glsl"
#pragma shadergen feature FRESNEL_SCHLICK
#pragma shadergen feature THIN_FILM unless thinfilm_thickness <= 0
#pragma shadergen feature RETROREFLECTIVE unless retroreflective == false
#pragma shadergen feature REFRACTION unless scatter_mode == R

// Once per shading point (lib/mx_specular.glsl); the albedo towards V is needed under lights only.
void mx_generalized_schlick_bsdf_prepare(ClosureData closureData, float weight, vec3 color0, vec3 color82, vec3 color90,
                                         float exponent, vec2 roughness, bool retroreflective, float thinfilm_thickness,
                                         float thinfilm_ior, vec3 N, vec3 X, int distribution, int scatter_mode,
                                         out SpecularLobe lobe)
{
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_SCHLICK, vec3(0.0), vec3(0.0), max(color0, 0.0), max(color82, 0.0),
                                     max(color90, 0.0), exponent, thinfilm_thickness, thinfilm_ior);
    lobe = mx_specular_lobe_prepare(closureData, weight, vec3(1.0), roughness, retroreflective, fd, N, X, distribution,
                                    scatter_mode);
#ifdef MX_FEATURE_TRANSMISSION
#ifdef MX_FEATURE_REFRACTION
    // refracted with the index whose normal reflectance is the mean of color0
    FresnelData refractFd = fd;
    refractFd.ior = vec3(mx_f0_to_ior(dot(fd.F0, vec3(1.0 / 3.0))));
    mx_specular_lobe_refract(closureData, refractFd, vec3(1.0), scatter_mode, lobe);
#endif
#endif
#ifdef MX_FEATURE_LIGHTS
    float NdotV = clamp(dot(lobe.N, lobe.V), MX_EPS, 1.0);
    vec3 tableAlbedo = mx_ggx_albedo(NdotV, mx_ggx_isotropic_alpha(lobe.alpha), fd.F0, fd.F90);
    lobe.albedo = mx_specular_albedo(NdotV, lobe.alpha, fd, tableAlbedo);
#endif
}

// In each context. Each channel passes to the layers below what this lobe does not reflect in
// that channel.
void mx_generalized_schlick_bsdf(ClosureData closureData, SpecularLobe lobe, inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (lobe.weight == 0.0 || (lobe.scatterMode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;

    if (context == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.throughput = mx_specular_throughput(lobe.environmentAlbedo, lobe.weight);
        bsdf.response = lobe.environment * lobe.weight;
    }
#ifdef MX_FEATURE_TRANSMISSION
    else if (transmission)
    {
        bsdf.throughput = mx_specular_throughput(mx_specular_transmission_albedo(closureData, lobe), lobe.weight);
#ifdef MX_FEATURE_REFRACTION
        if (lobe.scatterMode != 0)
            bsdf.response = lobe.refracted * lobe.weight;
#endif
    }
#endif
#ifdef MX_FEATURE_LIGHTS
    else  // REFLECTION
    {
        // the light crosses the interface on its way in too
        float NdotL = dot(lobe.N, closureData.L);
        vec3 tableAlbedoL = mx_ggx_albedo(NdotL, mx_ggx_isotropic_alpha(lobe.alpha), lobe.fd.F0, lobe.fd.F90);
        vec3 reflectedL = mx_specular_albedo(NdotL, lobe.alpha, lobe.fd, tableAlbedoL);
        bsdf.throughput = mx_specular_throughput(lobe.albedo, lobe.weight) * mx_specular_throughput(reflectedL, lobe.weight);
        bsdf.response = mx_specular_reflection(closureData, lobe) * lobe.weight;
    }
#endif
}
