// Image-based lighting from a lat-long environment map, by filtered importance sampling (Krivanek
// & Colbert 2008): GGX visible normals drawn from a spherical Fibonacci set, each environment
// sample fetched from the mip level whose texel covers the sample's solid angle. A shader compiled
// with MX_ENV_PREFILTER defined reads a prefiltered map instead (mx_environment_prefilter.glsl), once
// or, with MX_ENV_HYBRID too, corrected by u_envRadianceSamples samples of it.
//
// Uniforms (declared by the generator with the surface node): u_envRadiance (mipmapped radiance),
// u_envIrradiance (irradiance / pi), u_envMatrix (world -> map direction), u_envRadianceMips (levels
// in the radiance map's mip chain), u_envRadianceSamples, u_envLightIntensity.
#include "mx_ggx.glsl"
#include "mx_environment_map.glsl"
#include "mx_environment_prefilter.glsl"

// Mip level for a sample of density `pdf` along map direction `mapDir` (GPU Gems 3, 20.4, eq. 13),
// with the lat-long map's stretching towards its poles, biased 1.5 levels sharper.
float mx_envmap_lod(vec3 mapDir, float pdf, int sampleCount)
{
    float coarsest = float(u_envRadianceMips - 1) - 1.5;
    float stretch = sqrt(1.0 - mapDir.y * mapDir.y);
    return max(coarsest - 0.5 * log2(float(sampleCount) * pdf * stretch), 0.0);
}

// The environment along map direction `Lm` as one of `count` samples of density `pdf` sees it
// (filtered importance sampling): read at the level whose texels cover the solid angle 1 / (count
// pdf) the sample stands for, in the chain the shader reads (the radiance map's mips, or with
// MX_ENV_PREFILTER the prefiltered chain's GGX lobes).
vec3 mx_environment_sample(vec3 Lm, float pdf, int count)
{
#ifdef MX_ENV_PREFILTER
    return mx_envmap_lookup(u_envRadiance, Lm, mx_prefiltered_sample_lod(pdf, count, 1.0));
#else
    return mx_envmap_lookup(u_envRadiance, Lm, mx_envmap_lod(Lm, pdf, count));
#endif
}

// Light leaving a point with normal N towards V (tangent X) after one GGX bounce, or, with
// fd.refraction, after passing through a solid sphere of index fd.ior.x.
//   Reflection: each visible normal H carries F(V.H) G2 / G1 (Heitz 2014); the multiple scattering
//   that single scattering misses is returned with Turquin's factor 1 + F (1 - E) / E, where E, the
//   lobe's albedo with F = 1, is estimated from the same samples: a white lobe in a white
//   environment then gives exactly 1 at any sample count or anisotropy.
//   Refraction: each visible normal lets through 1 - F(V.H); masked light counts as transmitted,
//   so reflection plus refraction of a clear dielectric stays within 1.
// `albedo` returns what the same samples give in a white environment: the fraction of the light
// the lobe reflects (or lets through), consistent with the radiance to the last sample, which is
// what a layer below must not receive again. Without `fetch` only `albedo` is computed (no
// texture reads), so that other contexts see the very albedo the environment term has. Without
// `withFilm` fd's thin film is left out (mx_fresnel_eval_film; the prefiltered way takes it
// where there is one).
vec3 mx_environment_samples(vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd, bool fetch, bool withFilm,
                            out vec3 albedo)
{
#ifdef MX_ENV_PREFILTER
    return mx_environment_prefiltered(N, V, X, alpha, fd, fetch, albedo);
#else
    albedo = vec3(0.0);
    int sampleCount = u_envRadianceSamples;
    if (sampleCount <= 0)
        return vec3(0.0);

    mat3 frame = mx_tangent_frame(N, X);
    vec3 Vt = V * frame;  // (V.X, V.Y, V.N)
    Vt.z = max(Vt.z, MX_EPS);
    mat3 toMap = mat3(u_envMatrix) * frame;  // a sample's direction straight to the map's (a rotation)

    vec3 carried = vec3(0.0);
    float whiteAlbedo = 0.0;
    for (int i = 0; i < sampleCount; i++)
    {
        vec3 H = mx_ggx_sample_visible_normal(mx_fibonacci_point(i, sampleCount), Vt, alpha);
#ifdef MX_FEATURE_REFRACTION
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
#else
        vec3 Lt = reflect(-Vt, H);  // no closure of this shader refracts
#endif
        vec3 Li = vec3(0.0);
        if (fetch)
            Li = mx_environment_sample(toMap * Lt, mx_ggx_reflection_pdf(H, Vt, alpha), sampleCount);
        vec3 F = mx_fresnel_eval_film(clamp(dot(Vt, H), MX_EPS, 1.0), fd, withFilm);
        float weight = fd.refraction ? 1.0 : mx_ggx_sample_weight(Vt, Lt, alpha);
        vec3 throughput = fd.refraction ? vec3(1.0) - F : F * weight;
        carried += Li * throughput;
        albedo += throughput;
        whiteAlbedo += weight;
    }
    float scale = 1.0 / float(sampleCount);
    if (!fd.refraction)
    {
        float E = whiteAlbedo * scale;
        vec3 compensation = vec3(1.0) + mx_fresnel_eval_film(Vt.z, fd, withFilm) * ((1.0 - E) / max(E, MX_EPS));
        carried *= compensation;
        albedo *= compensation;
    }
    albedo *= scale;
    return carried * (scale * u_envLightIntensity);
#endif
}

// The environment a lobe reflects, prepared once per shading point. A film's Fresnel costs more
// than the rest of a sample, and a CPU rasterizer (Mesa's llvmpipe) runs both sides of a branch:
// the samples are written with the film and without, so that a lobe with no film at run time
// runs the film's loop once, masked, rather than the film at every sample.
vec3 mx_environment_reflected(vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd, bool fetch, out vec3 albedo)
{
#ifdef MX_FEATURE_THIN_FILM
#ifndef MX_ENV_PREFILTER
    if (mx_fresnel_has_thinfilm(fd))
        return mx_environment_samples(N, V, X, alpha, fd, fetch, true, albedo);
#endif
#endif
    return mx_environment_samples(N, V, X, alpha, fd, fetch, false, albedo);
}

// The environment seen through the lobe (see mx_environment_samples).
vec3 mx_environment_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, out vec3 albedo)
{
    return mx_environment_samples(N, V, X, alpha, fd, true, true, albedo);
}
