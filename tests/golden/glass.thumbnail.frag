#version 400

struct surfaceshader
{
    vec3 color;
    vec3 transparency;
};
struct BSDF
{
    vec3 response;
    vec3 throughput;
};
// The shading point as a closure sees it: the context, the light direction (REFLECTION only), the
// direction to the viewer, the interpolated normal, the world position and the light's visibility.
struct ClosureData
{
    int closureType;
    vec3 L;
    vec3 V;
    vec3 N;
    vec3 P;
    float occlusion;
};
// How a specular closure reflects: which model with its parameters, an optional thin film on top,
// and whether the environment is to be sampled through the surface (refraction) instead of off it.
struct FresnelData
{
    int model;
    vec3 ior;
    vec3 extinction;
    vec3 F0;
    vec3 F82;
    vec3 F90;
    float exponent;
    float tf_thickness;
    float tf_ior;
    bool refraction;
};
struct SpecularLobe
{
    float weight;
    vec3 tint;
    vec3 surfaceN;
    vec3 N;
    vec3 V;
    vec3 X;
    vec2 alpha;
    int scatterMode;
    int distribution;
    vec3 environment;
    vec3 environmentAlbedo;
    vec3 refracted;
};
// Closure contexts. The surface node evaluates a BSDF graph once per context and every closure
// function branches on it: REFLECTION (one light, closureData.L towards it), TRANSMISSION (what is
// seen through the surface along the view direction), INDIRECT (the environment, sampled by the
// closure itself) and EMISSION (EDF graphs). The numbers are the generator's context ids.
const int CLOSURE_TYPE_DEFAULT = 0;
const int CLOSURE_TYPE_REFLECTION = 1;
const int CLOSURE_TYPE_TRANSMISSION = 2;
const int CLOSURE_TYPE_INDIRECT = 3;
const float MX_PI = 3.1415926535897932;
const float MX_INV_PI = 1.0 / MX_PI;
const float MX_EPS = 1.0e-8;
// Largest index of refraction (real or imaginary part) a lobe takes: far above any material's
// (metals' extinction stays below ~10), low enough that its fourth power is a finite float.
const float MX_MAX_IOR = 1000.0;
const int FRESNEL_MODEL_DIELECTRIC = 0;
// Thickest film taken (nanometres): interference has washed out long before.
const float MX_MAX_FILM_NM = 1.0e5;
// Smallest alpha the lobe uses: a mirror to 1e-4, without the overflow of D at alpha -> 0.
const float MX_GGX_MIN_ALPHA = 1.0e-4;

// Uniform block: PrivateUniforms
uniform mat4 u_envMatrix;
uniform sampler2D u_envRadiance;
uniform float u_envLightIntensity;
uniform int u_envRadianceMips;
uniform int u_envRadianceSamples;
uniform bool u_refractionTwoSided;
uniform vec3 u_viewPosition;

in VertexData
{
    vec3 normalWorld;
    vec3 tangentWorld;
    vec3 positionWorld;
} vd;

out vec4 out1;

vec2 mx_sqr(vec2 x)
{
    return x * x;
}

// x clamped to [lo, hi], NaN taken as lo. A lobe's parameters may be computed by the graph (a
// division by zero, the log of a negative): each lobe passes them through this once, so they
// arrive finite and in range. GLSL leaves clamp() of a NaN undefined, hence the test.
float mx_clamp_finite(float x, float lo, float hi)
{
    return isnan(x) ? lo : clamp(x, lo, hi);
}

vec2 mx_clamp_finite(vec2 x, float lo, float hi)
{
    return vec2(mx_clamp_finite(x.x, lo, hi), mx_clamp_finite(x.y, lo, hi));
}

vec3 mx_clamp_finite(vec3 x, float lo, float hi)
{
    return vec3(mx_clamp_finite(x.x, lo, hi), mx_clamp_finite(x.y, lo, hi), mx_clamp_finite(x.z, lo, hi));
}

// The normal flipped, where needed, to the side of the surface that `V` sees.
vec3 mx_facing_normal(vec3 N, vec3 V)
{
    return (dot(N, V) < 0.0) ? -N : N;
}

// Any orthonormal frame around the unit vector N, columns (X, Y, N) (Duff et al. 2017).
mat3 mx_frame_from_normal(vec3 N)
{
    float s = (N.z < 0.0) ? -1.0 : 1.0;
    float a = -1.0 / (s + N.z);
    float b = N.x * N.y * a;
    return mat3(vec3(1.0 + s * N.x * N.x * a, s * b, -s * N.x), vec3(b, s + N.y * N.y * a, -N.y), N);
}

// A lobe's weight that scatters nothing: zero, negative, or NaN (a NaN computed in the graph, which
// compares false with everything, is absorbed rather than spread over the image).
bool mx_weight_is_zero(float weight)
{
    return isnan(weight) || weight < MX_EPS;
}

// The normal a closure shades with: N when it is a usable direction, else the interpolated
// surface normal (a normal map whose perturbation cancels to zero, or a NaN from the graph).
vec3 mx_usable_normal(vec3 N, vec3 surfaceNormal)
{
    float len2 = dot(N, N);
    return (isnan(len2) || isinf(len2) || len2 < MX_EPS) ? surfaceNormal : N * inversesqrt(len2);
}

// Columns (X, Y, N): `X` made orthogonal to the unit normal `N`, then Y = N x X; any frame about N
// when X is zero or along N.
mat3 mx_tangent_frame(vec3 N, vec3 X)
{
    vec3 T = X - N * dot(X, N);
    float len2 = dot(T, T);
    if (isnan(len2) || len2 < MX_EPS)
        return mx_frame_from_normal(N);
    T *= inversesqrt(len2);
    return mat3(T, cross(N, T), N);
}

// Point `i` of a `count`-point spherical Fibonacci set in [0, 1)^2: a stratified first coordinate
// and the golden-ratio sequence as the second. Every sampled integral of the library uses it, so
// the sample pattern (and the image) matches the reference renderer's.
vec2 mx_fibonacci_point(int i, int count)
{
    const float GOLDEN_RATIO = 1.6180339887498948;
    return vec2((float(i) + 0.5) / float(count), fract((float(i) + 1.0) * GOLDEN_RATIO));
}

FresnelData mx_fresnel_data(int model, vec3 ior, vec3 extinction, vec3 F0, vec3 F82, vec3 F90, float exponent,
                            float tf_thickness, float tf_ior)
{
    // every specular lobe builds its Fresnel data once: the indices and the film are made finite here
    return FresnelData(model, mx_clamp_finite(ior, 0.0, MX_MAX_IOR),
                       mx_clamp_finite(extinction, 0.0, MX_MAX_IOR), F0, F82, F90, exponent,
                       mx_clamp_finite(tf_thickness, 0.0, MX_MAX_FILM_NM),
                       mx_clamp_finite(tf_ior, 0.0, MX_MAX_IOR), false);
}

// Unpolarised reflectance of a dielectric interface with relative index `eta` (transmitted over
// incident side); 1 under total internal reflection.
float mx_fresnel_dielectric(float cosTheta, float eta)
{
    float c = cosTheta;
    float gg = eta * eta + c * c - 1.0;
    if (gg < 0.0)
        return 1.0;
    float g = sqrt(gg);
    float s = (g - c) / (g + c);
    float p = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * s * s * (1.0 + p * p);
}

// Generation-time features (shadergen/features.py): a shader keeps the models its closures use,
// and the thin film only when some closure's film can be thicker than 0. `withFilm` false leaves
// fd's film out: a caller that knows it has none passes a constant and gets no film code, which
// matters where F is taken per sample, since a CPU rasterizer (Mesa's llvmpipe) runs both sides
// of a branch (mx_environment_reflected).
vec3 mx_fresnel_eval_film(float cosTheta, FresnelData fd, bool withFilm)
{
    if (fd.model == FRESNEL_MODEL_DIELECTRIC)
        return vec3(mx_fresnel_dielectric(cosTheta, fd.ior.x));
    return vec3(0.0);  // no closure of this shader uses another model
}

vec2 mx_ggx_clamp_alpha(vec2 alpha)
{
    return mx_clamp_finite(alpha, MX_GGX_MIN_ALPHA, 1.0);
}

// Normal distribution D(H) (Walter et al. 2007, eq. 33, in its anisotropic form).
float mx_ggx_D(vec3 H, vec2 alpha)
{
    vec3 scaled = vec3(H.xy / alpha, H.z);
    float q = dot(scaled, scaled);
    return 1.0 / (MX_PI * alpha.x * alpha.y * q * q);
}

// Smith's Lambda of GGX for direction w (Heitz 2014, eq. 86): the mean slope seen along w.
float mx_ggx_lambda(vec3 w, vec2 alpha)
{
    float z2 = max(w.z * w.z, MX_EPS);
    float slope2 = dot(mx_sqr(w.xy * alpha), vec2(1.0)) / z2;
    return 0.5 * (sqrt(1.0 + slope2) - 1.0);
}

// Masking of the view, G1 = 1 / (1 + Lambda(V)).
float mx_ggx_G1(vec3 V, vec2 alpha)
{
    return 1.0 / (1.0 + mx_ggx_lambda(V, alpha));
}

// mx_ggx_sample_weight with the view's Lambda(V) given: the samples of one view share it.
float mx_ggx_sample_weight_given(float lambdaV, vec3 L, vec2 alpha)
{
    if (L.z <= 0.0)
        return 0.0;
    return (1.0 + lambdaV) / (1.0 + lambdaV + mx_ggx_lambda(L, alpha));
}

// What a light direction sampled through a visible normal carries, f cos / pdf with F = 1:
// G2 / G1 (Heitz 2014, sect. 5.3), 0 below the horizon.
float mx_ggx_sample_weight(vec3 V, vec3 L, vec2 alpha)
{
    return mx_ggx_sample_weight_given(mx_ggx_lambda(V, alpha), L, alpha);
}

// A visible normal for view V from the uniform point u: the view stretched to the unit-roughness
// configuration, a normal drawn uniformly on the spherical cap it sees (Dupuy & Benyoub 2023),
// then unstretched.
vec3 mx_ggx_sample_visible_normal(vec2 u, vec3 V, vec2 alpha)
{
    vec3 Vs = normalize(vec3(V.xy * alpha, max(V.z, MX_EPS)));
    float phi = 2.0 * MX_PI * u.x;
    float z = (1.0 - u.y) * (1.0 + Vs.z) - Vs.z;
    float r = sqrt(clamp(1.0 - z * z, 0.0, 1.0));
    vec3 Hs = vec3(r * cos(phi), r * sin(phi), z) + Vs;
    return normalize(vec3(Hs.xy * alpha, max(Hs.z, MX_EPS)));
}

// Density of the reflected direction drawn through visible normal H: D G1(V) / (4 cos(V)).
float mx_ggx_reflection_pdf(vec3 H, vec3 V, vec2 alpha)
{
    return mx_ggx_D(H, alpha) * mx_ggx_G1(V, alpha) / (4.0 * max(V.z, MX_EPS));
}

// The texel coordinates of map direction `mapDir`, a unit vector up to rounding.
vec2 mx_envmap_uv(vec3 mapDir)
{
    return vec2(atan(mapDir.x, -mapDir.z) * MX_INV_PI * 0.5 + 0.5,
                0.5 - asin(clamp(mapDir.y, -1.0, 1.0)) * MX_INV_PI);
}

// The map `envMap` seen along map direction `mapDir`, at mip level `lod`.
vec3 mx_envmap_lookup(sampler2D envMap, vec3 mapDir, float lod)
{
    return textureLod(envMap, mx_envmap_uv(mapDir), lod).xyz;
}

// Direction leaving a solid sphere of index `ior` that ray direction R enters where the normal is N.
// Where a refraction is total internal reflection the ray reflects instead, so a direction always
// comes back.
vec3 mx_refraction_solid_sphere(vec3 R, vec3 N, float ior)
{
    float eta = max(ior, 1.0e-3);
    vec3 inside = refract(R, N, 1.0 / eta);
    if (dot(inside, inside) == 0.0)
        return reflect(R, N);
    vec3 exitNormal = normalize(inside * dot(inside, N) - N * 0.5);
    vec3 leaving = refract(inside, exitNormal, eta);
    return (dot(leaving, leaving) == 0.0) ? reflect(inside, exitNormal) : leaving;
}

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
    return mx_envmap_lookup(u_envRadiance, Lm, mx_envmap_lod(Lm, pdf, count));
}

// Light leaving a point with normal N towards V (tangent X) after one GGX bounce, or, with
// fd.refraction, after passing through a solid sphere of index fd.ior.x.
// Reflection: each visible normal H carries F(V.H) G2 / G1 (Heitz 2014); the multiple scattering
// that single scattering misses is returned with Turquin's factor 1 + F (1 - E) / E, where E, the
// lobe's albedo with F = 1, is estimated from the same samples: a white lobe in a white
// environment then gives exactly 1 at any sample count or anisotropy.
// Refraction: each visible normal lets through 1 - F(V.H); masked light counts as transmitted,
// so reflection plus refraction of a clear dielectric stays within 1.
// `albedo` returns what the same samples give in a white environment: the fraction of the light
// the lobe reflects (or lets through), consistent with the radiance to the last sample, which is
// what a layer below must not receive again. Without `fetch` only `albedo` is computed (no
// texture reads), so that other contexts see the very albedo the environment term has. Without
// `withFilm` fd's thin film is left out (mx_fresnel_eval_film; the prefiltered way takes it
// where there is one).
vec3 mx_environment_samples(vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd, bool fetch, bool withFilm,
                            out vec3 albedo)
{
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
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
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
        vec3 compensation = vec3(1.0) +
                            mx_fresnel_eval_film(Vt.z, fd, withFilm) * ((1.0 - E) / max(E, MX_EPS));
        carried *= compensation;
        albedo *= compensation;
    }
    albedo *= scale;
    return carried * (scale * u_envLightIntensity);
}

// The environment seen through the lobe (see mx_environment_samples).
vec3 mx_environment_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd,
                             out vec3 albedo)
{
    return mx_environment_samples(N, V, X, alpha, fd, true, true, albedo);
}

vec3 mx_surface_transmission(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, vec3 tint)
{
    fd.refraction = true;
    // A two-sided interface filters the light twice.
    vec3 through = u_refractionTwoSided ? tint * tint : tint;
    vec3 transmitted;
    return mx_environment_radiance(N, V, X, alpha, distribution, fd, transmitted) * through;
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
    lobe.alpha = mx_ggx_clamp_alpha(roughness);
    lobe.scatterMode = scatterMode;
    lobe.distribution = distribution;
    lobe.environment = vec3(0.0);
    lobe.environmentAlbedo = vec3(0.0);
    lobe.refracted = vec3(0.0);
    if (lobe.weight > 0.0)
        lobe.environment = mx_environment_samples(lobe.N, lobe.V, X, lobe.alpha, fd, scatterMode != 1, false,
                                                  lobe.environmentAlbedo);
    return lobe;
}

// The environment seen through a prepared lobe's interface, with Fresnel data `fd` and `tint`:
// prepared once per shading point like its reflection. Drivers inline every call, so computed in
// the closure's TRANSMISSION branch it would be compiled into every context's call of the closure,
// and for each lobe of a shader that refracts at all; here a lobe whose scatter mode is a constant
// R (0) drops it at compile time.
void mx_specular_lobe_refract(ClosureData closureData, FresnelData fd, vec3 tint, int scatterMode,
                              inout SpecularLobe lobe)
{
    if (scatterMode != 0 && lobe.weight > 0.0)
        lobe.refracted = mx_surface_transmission(mx_facing_normal(lobe.surfaceN, closureData.V),
                                                 closureData.V, lobe.X, lobe.alpha, lobe.distribution, fd,
                                                 tint);
}

// What the lobe reflects of the environment as seen through it along the real view direction:
// the prepared samples, or new ones where retro-reflection prepared them along the mirrored view.
vec3 mx_specular_transmission_albedo(ClosureData closureData, SpecularLobe lobe)
{
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

// Once per shading point (lib/mx_specular.glsl); the albedo towards V is needed under lights only.
void mx_dielectric_bsdf_prepare(ClosureData closureData, float weight, vec3 tint, float ior, vec2 roughness,
                                bool retroreflective, float thinfilm_thickness, float thinfilm_ior, vec3 N,
                                vec3 X, int distribution, int scatter_mode, out SpecularLobe lobe)
{
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(ior), vec3(0.0), vec3(0.0), vec3(0.0),
                                     vec3(0.0), 0.0, thinfilm_thickness, thinfilm_ior);
    lobe = mx_specular_lobe_prepare(closureData, weight, tint, roughness, retroreflective, fd, N, X,
                                    distribution, scatter_mode);
    mx_specular_lobe_refract(closureData, fd, lobe.tint, scatter_mode, lobe);
}

// In each context. What the interface reflects, multiple scattering included, does not reach the
// layers below.
void mx_dielectric_bsdf(ClosureData closureData, SpecularLobe lobe, inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (lobe.weight == 0.0 || (lobe.scatterMode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;
    if (context == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.throughput = mx_specular_throughput(lobe.environmentAlbedo, lobe.weight);
        bsdf.response = lobe.environment * lobe.tint * lobe.weight;
    }
    else if (transmission)
    {
        bsdf.throughput = mx_specular_throughput(mx_specular_transmission_albedo(closureData, lobe),
                                                 lobe.weight);
        if (lobe.scatterMode != 0)
            bsdf.response = lobe.refracted * lobe.weight;
    }
}

void main()
{
    vec3 n0_out = normalize(vd.normalWorld);
    vec3 n1_out = normalize(vd.tangentWorld);
    surfaceshader n3_out = surfaceshader(vec3(0.0), vec3(0.0));
    {
        vec3 N = normalize(vd.normalWorld);
        vec3 V = normalize(u_viewPosition - vd.positionWorld);
        vec3 P = vd.positionWorld;
        vec3 L = vec3(0.0);
        float occlusion = 1.0;
        float surfaceOpacity = 1.0;
        // lobes prepared once per shading point, before any light
        ClosureData pointData = ClosureData(CLOSURE_TYPE_DEFAULT, L, V, N, P, occlusion);
        SpecularLobe n2_lobe;
        mx_dielectric_bsdf_prepare(pointData, 1.0, vec3(1.0, 1.0, 1.0), 1.45, vec2(0.05, 0.05), false, 0.0,
                                   1.5, n0_out, n1_out, 0, 2, n2_lobe);
        // environment
        {
            ClosureData closureData = ClosureData(CLOSURE_TYPE_INDIRECT, L, V, N, P, occlusion);
            BSDF n2_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n2_lobe, n2_out);
            n3_out.color += occlusion * n2_out.response;
        }
        // transmission, seen along the view direction
        {
            ClosureData closureData = ClosureData(CLOSURE_TYPE_TRANSMISSION, L, V, N, P, occlusion);
            BSDF n2_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n2_lobe, n2_out);
            n3_out.color += n2_out.response;
        }
        n3_out.color *= surfaceOpacity;
        n3_out.transparency = mix(vec3(1.0), n3_out.transparency, surfaceOpacity);
    }
    surfaceshader n4_out = n3_out;
    out1 = vec4(n4_out.color, 1.0 - dot(n4_out.transparency, vec3(1.0 / 3.0)));
}
