// The GGX reflection lobe shared by the specular closures (dielectric, conductor, generalized
// Schlick, and the environment term of hair).
#include "mx_closure_type.glsl"
#include "mx_transmission_refract.glsl"

// The fraction of light arriving with `cosine` that the lobe reflects, multiple scattering
// included, from its single-scattering albedo there (the caller's table value).
vec3 mx_specular_albedo(float cosine, vec2 alpha, FresnelData fd, vec3 singleScatteringAlbedo)
{
    float c = clamp(cosine, MX_EPS, 1.0);
    return singleScatteringAlbedo * mx_ggx_energy_compensation(c, mx_ggx_isotropic_alpha(alpha), mx_fresnel_eval(c, fd));
}

// The lobe with Fresnel `fd` in the current closure context, multiple scattering included.
// `albedo` returns the fraction of light the lobe reflects at this view, which a layer below does
// not receive: in INDIRECT and TRANSMISSION the sampled value that matches the environment term,
// under lights `singleScatteringAlbedo` (the caller's table value) compensated at the view angle.
//   REFLECTION    D F G2 / (4 NdotV) towards closureData.L (the light's cosine cancels against the
//                 BRDF's), F and the compensation taken at the half vector.
//   INDIRECT      the environment by filtered importance sampling, compensated there.
//   TRANSMISSION  no light of its own; the albedo as in INDIRECT.
// N must face V; alpha is the clamped roughness pair.
vec3 mx_specular_lobe(ClosureData closureData, vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd,
                      vec3 singleScatteringAlbedo, out vec3 albedo)
{
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
        return mx_environment_radiance(N, V, X, alpha, 0, fd, albedo);
    if (closureData.closureType != CLOSURE_TYPE_REFLECTION)
    {
        // What is seen through a layer must lose exactly what its environment term reflects.
        mx_environment_samples(N, V, X, alpha, fd, false, albedo);
        return vec3(0.0);
    }

    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    albedo = mx_specular_albedo(NdotV, alpha, fd, singleScatteringAlbedo);

    mat3 frame = mx_tangent_frame(N, X);
    vec3 Vt = V * frame;
    vec3 Lt = closureData.L * frame;
    Vt.z = max(Vt.z, MX_EPS);
    if (Lt.z <= 0.0)
        return vec3(0.0);
    vec3 H = normalize(Lt + Vt);
    vec3 F = mx_fresnel_eval(clamp(dot(Vt, H), MX_EPS, 1.0), fd);
    float DG = mx_ggx_D(H, alpha) * mx_ggx_G2(Vt, Lt, alpha);
    return F * mx_ggx_energy_compensation(NdotV, mx_ggx_isotropic_alpha(alpha), F) * (DG * closureData.occlusion / (4.0 * Vt.z));
}

// True for the contexts a scattering closure answers (emission and the default context get nothing).
bool mx_is_scattering_context(int closureType)
{
    return closureType == CLOSURE_TYPE_REFLECTION || closureType == CLOSURE_TYPE_TRANSMISSION ||
           closureType == CLOSURE_TYPE_INDIRECT;
}
