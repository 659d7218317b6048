// The GGX reflection lobe shared by the specular closures (dielectric, conductor, generalized
// Schlick, and the environment term of hair).
#include "mx_closure_type.glsl"
#include "mx_transmission_refract.glsl"

// The lobe with Fresnel `fd` in the current closure context, multiple-scattering compensation
// included; `comp` returns that compensation, which the caller's throughput needs too.
//   REFLECTION    D F G2 / (4 NdotV) towards closureData.L (the light's cosine cancels against the
//                 BRDF's), F and the compensation taken at the half vector.
//   INDIRECT      the environment by filtered importance sampling; F at the view angle.
//   other         no light; the compensation still computed at the view angle.
// N must face V; alpha is the clamped roughness pair.
vec3 mx_specular_lobe(ClosureData closureData, vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd, out vec3 comp)
{
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float avgAlpha = mx_average_alpha(alpha);
    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        vec3 H = normalize(L + V);
        float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
        float VdotH = clamp(dot(V, H), MX_EPS, 1.0);
        vec3 F = mx_fresnel_eval(VdotH, fd);
        comp = mx_ggx_energy_compensation(NdotV, avgAlpha, F);
        float D = mx_ggx_D(H * mx_tangent_frame(N, X), alpha);
        float G = mx_ggx_G2(NdotL, NdotV, avgAlpha);
        return F * comp * (D * G * closureData.occlusion / (4.0 * NdotV));
    }
    comp = mx_ggx_energy_compensation(NdotV, avgAlpha, mx_fresnel_eval(NdotV, fd));
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
        return mx_environment_radiance(N, V, X, alpha, 0, fd) * comp;
    return vec3(0.0);
}

// True for the contexts a scattering closure answers (emission and the default context get nothing).
bool mx_is_scattering_context(int closureType)
{
    return closureType == CLOSURE_TYPE_REFLECTION || closureType == CLOSURE_TYPE_TRANSMISSION ||
           closureType == CLOSURE_TYPE_INDIRECT;
}
