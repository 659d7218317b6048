// Image-based lighting from a prefiltered environment, by the split sum (Karis 2013, "Real Shading
// in Unreal Engine 4"): the radiance map convolved with the GGX lobe per roughness (computed by the
// renderer, shadergen/render/prefilter.py, with N = V = R), times the BRDF's directional albedo
// from our DFG table (mx_environment_dfg.glsl, tools/fit_dfg.py). One lookup instead of
// u_envRadianceSamples, or, with MX_ENV_HYBRID defined too, that lookup corrected by a few samples
// of the chain. Used when the shader is compiled with MX_ENV_PREFILTER defined, and then
// u_envRadiance must hold the prefiltered chain.
#include "mx_fresnel.glsl"
#include "mx_ggx.glsl"
#include "mx_environment_map.glsl"
#include "mx_environment_dfg.glsl"

// Mip level of the prefiltered chain whose texels are as wide as the GGX lobe of `alpha`: level
// l >= 1 holds the lobe of alpha = 2^(l + 4 - u_envRadianceMips) up to alpha 1 (texels about as wide
// as the lobe), level 0 is the unfiltered map, and in between the chain's trilinear filtering
// blends neighbouring levels.
float mx_prefiltered_roughest_level()
{
    return max(float(u_envRadianceMips - 4), 1.0);
}

float mx_prefiltered_footprint_lod(float alpha)
{
    float roughest = mx_prefiltered_roughest_level();
    float firstAlpha = exp2(1.0 - roughest);
    return alpha < firstAlpha ? alpha / firstAlpha : min(log2(alpha) + roughest, roughest);
}

// The widest lobe the unfiltered map cannot resolve: a third of its texels (alpha1 / 8, alpha1 the
// lobe of level 1, whose texels are half as wide as its lobe).
float mx_prefiltered_sharpest_alpha()
{
    return exp2(1.0 - mx_prefiltered_roughest_level()) / 8.0;
}

// Mip level holding the GGX lobe of `alpha` itself, as mx_prefiltered_footprint_lod() except that
// a lobe narrower than mx_prefiltered_sharpest_alpha() reads the unfiltered map alone, and from
// there the blend with level 1 grows linearly: a fraction alpha / alpha1 of level 1 would spread a
// bright source, the sun, over a near-mirror's pixels, where the map cannot resolve the lobe anyway.
float mx_prefiltered_lod(float alpha)
{
    float firstAlpha = exp2(1.0 - mx_prefiltered_roughest_level());
    float sharpest = mx_prefiltered_sharpest_alpha();
    return alpha < firstAlpha ? max(alpha - sharpest, 0.0) / (firstAlpha - sharpest) : mx_prefiltered_footprint_lod(alpha);
}

// The lobe's Fresnel as the DFG table's two-point quadrature rule in VdotH sees it
// (mx_environment_dfg_rule: cosines x, y, weights z, w), evaluated once per shading point, with
// the slope of the line through its two points (mx_lobe_fresnel_at).
struct LobeFresnel
{
    vec4 rule;
    vec3 F1;     // the reflectance at rule.x
    vec3 F2;     // and at rule.y
    vec3 slope;  // (F2 - F1) / (rule.y - rule.x)
};

LobeFresnel mx_lobe_fresnel(float NdotV, float avgAlpha, FresnelData fd)
{
    vec4 rule = mx_environment_dfg_rule(NdotV, avgAlpha);
    vec3 F1 = mx_fresnel_eval(rule.x, fd);
    vec3 F2 = mx_fresnel_eval(rule.y, fd);
    float span = rule.y - rule.x;
    return LobeFresnel(rule, F1, F2, (F2 - F1) / (abs(span) < 1.0e-3 ? 1.0e-3 : span));
}

// The reflectance at VdotH `cosine` on the line through the rule's two points: what weights a
// sample of the lobe without evaluating the Fresnel model per sample.
vec3 mx_lobe_fresnel_at(LobeFresnel lf, float cosine)
{
    return clamp(lf.F1 + lf.slope * (cosine - lf.rule.x), 0.0, 1.0);
}

// The fraction of the light arriving over the lobe that it reflects (or, with fd.refraction, lets
// through) at NdotV, as mx_environment_radiance() gives it as `albedo`: the table's rule with F
// (reflection, times Turquin's multiple-scattering factor 1 + F (1 - E) / E as the sampled path
// applies it) or with 1 - F averaged over the lobe (refraction). `anisotropy` is what an
// anisotropic lobe reflects beyond the table's isotropic one (mx_environment_corrected_radiance:
// with F, and with F = 1), zero for an isotropic lobe.
vec3 mx_environment_table_albedo(LobeFresnel lf, float NdotV, FresnelData fd, vec4 anisotropy)
{
    vec3 reflected = max(lf.rule.z * lf.F1 + lf.rule.w * lf.F2 + anisotropy.rgb, vec3(0.0));
    float E = max(lf.rule.z + lf.rule.w + anisotropy.a, MX_EPS);  // the albedo with F = 1
#ifdef MX_FEATURE_REFRACTION
    if (fd.refraction)
        return vec3(1.0) - reflected / E;
#endif
    return reflected * (vec3(1.0) + mx_fresnel_eval(NdotV, fd) * ((1.0 - E) / E));
}

// The direction the split sum reads the lobe along: the mirror direction, or through the sphere.
vec3 mx_prefiltered_direction(vec3 V, vec3 N, FresnelData fd)
{
#ifdef MX_FEATURE_REFRACTION
    if (fd.refraction)
        return mx_refraction_solid_sphere(-V, N, fd.ior.x);
#endif
    return reflect(-V, N);
}

// Mip level of the chain for a sample of density `pdf` out of `count`: filtered importance sampling
// (Colbert & Krivanek 2007) with the chain's GGX lobes as the filter. A sample stands for the solid
// angle 1 / (count pdf) around it, and the level of alpha covers 4 pi alpha^2 (1 / the peak of its
// lobe's density D / 4 at N = V): the level of alpha = sqrt(1 / (4 pi count pdf)). The samples of
// an anisotropic lobe lie `elongation` (sqrt of its alphas' ratio) times farther apart along its
// long axis than that round footprint: the filter covers that axis, so that a small bright source
// (the sun) does not alias between them (standard_surface_carpaint, 16 samples: 44.8 -> 47.1 dB
// against its converged image, bench/accuracy_time.py --size 32), and the symmetric lobe's samples
// are read with the same filter, so that where the two lobes agree their sums still cancel.
float mx_prefiltered_sample_lod(float pdf, int count, float elongation)
{
    return mx_prefiltered_footprint_lod(min(elongation * sqrt(1.0 / (4.0 * MX_PI * float(count) * max(pdf, MX_EPS))), 1.0));
}

#ifdef MX_ENV_HYBRID
// The rotation (in tangent space) taking the pole (0, 0, 1) to unit direction D along the great
// circle between them (Rodrigues), or, for D near the south pole, any frame around D.
mat3 mx_rotation_from_pole(vec3 D)
{
    if (D.z < -0.999)
        return mx_frame_from_normal(D);
    float k = 1.0 / (1.0 + D.z);
    return mat3(vec3(D.z + D.y * D.y * k, -D.x * D.y * k, -D.x),
                vec3(-D.x * D.y * k, D.z + D.x * D.x * k, -D.y),
                D);
}

// The light of the single lookup (mx_environment_prefiltered), corrected by u_envRadianceSamples
// samples where the lobe differs from the split sum's. The lookup is the mean radiance over the
// lobe Karis 2013 assumes (N = V = R: symmetric about the mirror direction R, isotropic); the true
// lobe is stretched and pulled towards N at grazing views, where its error concentrates. The
// difference of the two lobes' mean radiances is estimated with correlated samples (a control
// variate, Veach 1997, sect. 2.5.4): each Fibonacci point is drawn through the true lobe (visible
// normals, weighted by what the sample carries: F G2 / G1, or 1 - F through the surface) and
// through the symmetric lobe turned from N to R (weighted by its cosine to R, as the chain was
// convolved), both read at their filtered level. Where the lobes agree (facing views) the two sums
// cancel and the smooth lookup is kept; at grazing views the samples add what it misses. The table
// gives the albedo the mean radiance is multiplied by (a ratio estimator: the samples' own albedo
// estimate, whose error dominates at a few samples, is replaced by its known value); the samples'
// F only shapes the mean, so it is read off the line through the table's two Fresnel values
// (mx_lobe_fresnel_at) instead of evaluating the Fresnel model per sample.
//   The table holds isotropic lobes: an anisotropic one reflects up to a few percent more or less
// at grazing views, as the view's azimuth meets its long or its short axis. The same points drawn
// through the isotropic lobe of its mean roughness estimate the difference (correlated samples of
// two close integrals; no texture reads), returned in `anisotropy`: (with F, with F = 1).
// Without `fetch` only that, and no texture reads at all.
vec3 mx_environment_corrected_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, float avgAlpha, FresnelData fd,
                                       LobeFresnel lf, bool fetch, out vec4 anisotropy)
{
    anisotropy = vec4(0.0);
    mat3 frame = mx_tangent_frame(N, X);
    vec3 Vt = V * frame;  // (V.X, V.Y, V.N)
    Vt.z = max(Vt.z, MX_EPS);
    mat3 toMap = mat3(u_envMatrix) * frame;  // a direction in the frame straight to the map's (a rotation)
    vec3 Rt = normalize(mx_prefiltered_direction(Vt, vec3(0.0, 0.0, 1.0), fd));
    vec3 lookup = fetch ? mx_envmap_lookup(u_envRadiance, toMap * Rt, mx_prefiltered_lod(avgAlpha)) : vec3(0.0);
    bool anisotropic = alpha.x != alpha.y && !fd.refraction;
    // A lobe narrower than the unfiltered map resolves reads it along R at any view: no samples.
    bool corrected = fetch && max(alpha.x, alpha.y) >= mx_prefiltered_sharpest_alpha();
    int sampleCount = corrected || anisotropic ? max(u_envRadianceSamples, 1) : 0;
    float elongation = sqrt(max(alpha.x, alpha.y) / max(min(alpha.x, alpha.y), MX_EPS));
    mat3 splitToMap = toMap * mx_rotation_from_pole(Rt);
    // What every sample of the view shares, computed once: Lambda(V) of both lobes, and G1(V) / (4 V.z)
    // of the reflection pdf (mx_ggx_reflection_pdf).
    float lambdaV = mx_ggx_lambda(Vt, alpha);
    float lambdaVIsotropic = mx_ggx_lambda(Vt, vec2(avgAlpha));
    float pdfScale = 1.0 / ((1.0 + lambdaV) * 4.0 * Vt.z);
    vec3 lobeRadiance = vec3(0.0), lobeWeights = vec3(0.0), splitRadiance = vec3(0.0);
    float splitWeights = 0.0;
    for (int i = 0; i < sampleCount; i++)
    {
        vec2 u = mx_fibonacci_point(i, sampleCount);
        vec3 H = mx_ggx_sample_visible_normal(u, Vt, alpha);
        vec3 F = mx_lobe_fresnel_at(lf, clamp(dot(Vt, H), MX_EPS, 1.0));
#ifdef MX_FEATURE_REFRACTION
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
#else
        vec3 Lt = reflect(-Vt, H);
#endif
        float weight = mx_ggx_sample_weight_given(lambdaV, Lt, alpha);
        if (anisotropic)
        {
            vec3 Hi = mx_ggx_sample_visible_normal(u, Vt, vec2(avgAlpha));
            float weightIsotropic = mx_ggx_sample_weight_given(lambdaVIsotropic, reflect(-Vt, Hi), vec2(avgAlpha));
            anisotropy += vec4(F * weight - mx_lobe_fresnel_at(lf, clamp(dot(Vt, Hi), MX_EPS, 1.0)) * weightIsotropic,
                               weight - weightIsotropic);
        }
        if (!corrected)
            continue;
        // A sample below the horizon keeps a token weight, so that a lobe whose every sample falls
        // there still reads the environment around it.
        vec3 w = fd.refraction ? vec3(1.0) - F : F * max(weight, 1.0e-4);
        float pdf = mx_ggx_D(H, alpha) * pdfScale;
        lobeRadiance += w * mx_envmap_lookup(u_envRadiance, toMap * Lt, mx_prefiltered_sample_lod(pdf, sampleCount, elongation));
        lobeWeights += w;

        vec3 Hs = mx_ggx_sample_visible_normal(u, vec3(0.0, 0.0, 1.0), vec2(avgAlpha));
        vec3 Ls = reflect(vec3(0.0, 0.0, -1.0), Hs);
        float cosine = max(Ls.z, 1.0e-4);  // a token weight below R's horizon, as above
        float pdfs = mx_ggx_reflection_pdf(Hs, vec3(0.0, 0.0, 1.0), vec2(avgAlpha));
        splitRadiance += cosine * mx_envmap_lookup(u_envRadiance, splitToMap * Ls, mx_prefiltered_sample_lod(pdfs, sampleCount, elongation));
        splitWeights += cosine;
    }
    anisotropy /= float(max(sampleCount, 1));
    if (!corrected)
        return lookup;
    vec3 correction = lobeRadiance / max(lobeWeights, vec3(MX_EPS)) - splitRadiance / max(splitWeights, MX_EPS);
    return max(lookup + correction, vec3(0.0));
}
#endif

// Light leaving a point with normal N towards V (tangent X) after one GGX bounce of roughness
// alpha, or, with fd.refraction, after passing through a solid sphere of index fd.ior.x; `albedo`
// as mx_environment_radiance() gives it: one lookup along the mirror (or refracted) direction, or
// with MX_ENV_HYBRID that lookup corrected by samples. Without `fetch` only the albedo, from the
// table (with MX_ENV_HYBRID, an anisotropic lobe's corrected by samples), and no texture reads.
vec3 mx_environment_prefiltered(vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd, bool fetch, out vec3 albedo)
{
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float avgAlpha = clamp(sqrt(alpha.x * alpha.y), 0.0, 1.0);
    LobeFresnel lf = mx_lobe_fresnel(NdotV, avgAlpha, fd);
#ifdef MX_ENV_HYBRID
    vec4 anisotropy;
    vec3 radiance = mx_environment_corrected_radiance(N, V, X, alpha, avgAlpha, fd, lf, fetch, anisotropy);
    albedo = mx_environment_table_albedo(lf, NdotV, fd, anisotropy);
#else
    vec3 radiance = fetch ? mx_envmap_fetch(u_envRadiance, mx_prefiltered_direction(V, N, fd), mx_prefiltered_lod(avgAlpha))
                          : vec3(0.0);
    albedo = mx_environment_table_albedo(lf, NdotV, fd, vec4(0.0));
#endif
    return radiance * albedo * u_envLightIntensity;
}
