// The GGX reflection lobe shared by the specular closures (dielectric, conductor, generalized
// Schlick, and the environment term of hair).
//
// A specular closure is prepared once per shading point, before any light (its `_prepare`
// function, which the generator calls before the shading contexts): normal, frame, Fresnel set-up,
// directional albedo and the environment it reflects do not depend on the light. The closure
// function then answers each context from the prepared SpecularLobe:
//   REFLECTION    D F G2 / (4 NdotV) towards closureData.L (the light's cosine cancels against the
//                 BRDF's), F and the multiple-scattering compensation taken at the half vector.
//   INDIRECT      the environment, sampled once by filtered importance sampling, compensated there.
//   TRANSMISSION  no light of its own: what is seen through a layer loses exactly the albedo its
//                 environment term has (the same samples); a lobe that refracts (scatter modes T
//                 and RT) adds the environment seen through it, prepared too
//                 (mx_specular_lobe_refract).
#include "mx_closure_type.glsl"
#include "mx_transmission_refract.glsl"

struct SpecularLobe
{
    float weight;            // 0 where the lobe scatters nothing
    vec3 tint;
    vec3 surfaceN;           // the usable shading normal, on either side
    vec3 N;                  // the normal facing V
    vec3 V;                  // towards the viewer, mirrored about the normal for retro-reflection
    vec3 X;                  // tangent
    bool retroreflective;
    vec2 alpha;              // clamped roughness pair
    FresnelData fd;
    int scatterMode;         // 0 R, 1 T, 2 RT
    int distribution;
    mat3 frame;              // (X, Y, N) about N
    vec3 Vt;                 // V in that frame
    vec3 albedo;             // what the lobe reflects of light arriving along V (the caller's table value, compensated)
    vec3 environment;        // the environment the lobe reflects towards V
    vec3 environmentAlbedo;  // the fraction of the environment it reflects, from the same samples
    vec3 refracted;          // the environment seen through the interface (scatter modes T and RT)
};

// The fraction of light arriving with `cosine` that the lobe reflects, multiple scattering
// included, from its single-scattering albedo there (the caller's table value).
vec3 mx_specular_albedo(float cosine, vec2 alpha, FresnelData fd, vec3 singleScatteringAlbedo)
{
    float c = clamp(cosine, MX_EPS, 1.0);
    return singleScatteringAlbedo * mx_ggx_energy_compensation(c, mx_ggx_isotropic_alpha(alpha), mx_fresnel_eval(c, fd));
}

// What every specular closure prepares alike; the caller sets `albedo` from its own table. The
// environment is fetched unless the lobe only transmits (its albedo is still needed there).
SpecularLobe mx_specular_lobe_prepare(ClosureData closureData, float weight, vec3 tint, vec2 roughness,
                                      bool retroreflective, FresnelData fd, vec3 N, vec3 X, int distribution,
                                      int scatterMode)
{
    SpecularLobe lobe;
    lobe.weight = mx_weight_is_zero(weight) ? 0.0 : weight;
    lobe.tint = max(tint, 0.0);
    lobe.surfaceN = mx_usable_normal(N, closureData.N);
    lobe.V = retroreflective ? reflect(-closureData.V, lobe.surfaceN) : closureData.V;
    lobe.N = mx_facing_normal(lobe.surfaceN, lobe.V);
    lobe.X = X;
    lobe.retroreflective = retroreflective;
    lobe.alpha = mx_ggx_clamp_alpha(roughness);
    lobe.fd = fd;
    lobe.scatterMode = scatterMode;
    lobe.distribution = distribution;
    lobe.frame = mx_tangent_frame(lobe.N, X);
    lobe.Vt = lobe.V * lobe.frame;
    lobe.Vt.z = max(lobe.Vt.z, MX_EPS);
    lobe.albedo = vec3(0.0);
    lobe.environment = vec3(0.0);
    lobe.environmentAlbedo = vec3(0.0);
    lobe.refracted = vec3(0.0);
    if (lobe.weight > 0.0)
        lobe.environment = mx_environment_reflected(lobe.N, lobe.V, X, lobe.alpha, fd, scatterMode != 1,
                                                    lobe.environmentAlbedo);
    return lobe;
}

#ifdef MX_FEATURE_REFRACTION
// The environment seen through a prepared lobe's interface, with Fresnel data `fd` and `tint`:
// prepared once per shading point like its reflection. Drivers inline every call, so computed in
// the closure's TRANSMISSION branch it would be compiled into every context's call of the closure,
// and for each lobe of a shader that refracts at all; here a lobe whose scatter mode is a constant
// R (0) drops it at compile time.
void mx_specular_lobe_refract(ClosureData closureData, FresnelData fd, vec3 tint, int scatterMode,
                              inout SpecularLobe lobe)
{
    if (scatterMode != 0 && lobe.weight > 0.0)
        lobe.refracted = mx_surface_transmission(mx_facing_normal(lobe.surfaceN, closureData.V), closureData.V,
                                                 lobe.X, lobe.alpha, lobe.distribution, fd, tint);
}
#endif

// The lobe towards closureData.L (REFLECTION), multiple scattering included.
vec3 mx_specular_reflection(ClosureData closureData, SpecularLobe lobe)
{
    vec3 Lt = closureData.L * lobe.frame;
    if (Lt.z <= 0.0)
        return vec3(0.0);
    vec3 H = normalize(Lt + lobe.Vt);
    vec3 F = mx_fresnel_eval(clamp(dot(lobe.Vt, H), MX_EPS, 1.0), lobe.fd);
    float DG = mx_ggx_D(H, lobe.alpha) * mx_ggx_G2(lobe.Vt, Lt, lobe.alpha);
    float NdotV = clamp(dot(lobe.N, lobe.V), MX_EPS, 1.0);
    return F * mx_ggx_energy_compensation(NdotV, mx_ggx_isotropic_alpha(lobe.alpha), F) *
           (DG * closureData.occlusion / (4.0 * lobe.Vt.z));
}

// What the lobe reflects of the environment as seen through it along the real view direction:
// the prepared samples, or new ones where retro-reflection prepared them along the mirrored view.
vec3 mx_specular_transmission_albedo(ClosureData closureData, SpecularLobe lobe)
{
#ifdef MX_FEATURE_RETROREFLECTIVE
    // Written only where a lobe can be retro-reflective (a generation-time feature): compilers fold
    // a flag in a struct late, after their front end has inlined and optimised the loop it guards.
    if (lobe.retroreflective)
    {
        vec3 albedo;
        mx_environment_samples(mx_facing_normal(lobe.surfaceN, closureData.V), closureData.V, lobe.X, lobe.alpha,
                               lobe.fd, false, true, albedo);
        return albedo;
    }
#endif
    return lobe.environmentAlbedo;
}

// What the layers below receive of light from one direction, given what the lobe reflects of it.
vec3 mx_specular_throughput(vec3 reflected, float weight)
{
    return max(vec3(1.0) - reflected * weight, 0.0);
}

// True for the contexts a scattering closure answers (emission and the default context get nothing).
bool mx_is_scattering_context(int closureType)
{
    return closureType == CLOSURE_TYPE_REFLECTION || closureType == CLOSURE_TYPE_TRANSMISSION ||
           closureType == CLOSURE_TYPE_INDIRECT;
}
