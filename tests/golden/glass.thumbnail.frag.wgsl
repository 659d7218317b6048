struct surfaceshader {
    color: vec3f,
    transparency: vec3f,
}
struct BSDF {
    response: vec3f,
    throughput: vec3f,
}
// The shading point as a closure sees it: the context, the light direction (REFLECTION only), the
// direction to the viewer, the interpolated normal, the world position and the light's visibility.
struct ClosureData {
    closureType: i32,
    L: vec3f,
    V: vec3f,
    N: vec3f,
    P: vec3f,
    occlusion: f32,
}
// How a specular closure reflects: which model with its parameters, an optional thin film on top,
// and whether the environment is to be sampled through the surface (refraction) instead of off it.
struct FresnelData {
    model: i32,
    ior: vec3f,
    extinction: vec3f,
    F0: vec3f,
    F82: vec3f,
    F90: vec3f,
    exponent: f32,
    tf_thickness: f32,
    tf_ior: f32,
    refraction: bool,
}
struct SpecularLobe {
    weight: f32,
    tint: vec3f,
    surfaceN: vec3f,
    N: vec3f,
    V: vec3f,
    X: vec3f,
    alpha: vec2f,
    scatterMode: i32,
    distribution: i32,
    environment: vec3f,
    environmentAlbedo: vec3f,
    refracted: vec3f,
}

// Closure contexts. The surface node evaluates a BSDF graph once per context and every closure
// function branches on it: REFLECTION (one light, closureData.L towards it), TRANSMISSION (what is
// seen through the surface along the view direction), INDIRECT (the environment, sampled by the
// closure itself) and EMISSION (EDF graphs). The numbers are the generator's context ids.
const CLOSURE_TYPE_DEFAULT: i32 = 0;
const CLOSURE_TYPE_REFLECTION: i32 = 1;
const CLOSURE_TYPE_TRANSMISSION: i32 = 2;
const CLOSURE_TYPE_INDIRECT: i32 = 3;
const MX_PI: f32 = 3.1415926535897932;
const MX_INV_PI: f32 = 1.0 / MX_PI;
const MX_EPS: f32 = 1.0e-8;
// Largest index of refraction (real or imaginary part) a lobe takes: far above any material's
// (metals' extinction stays below ~10), low enough that its fourth power is a finite float.
const MX_MAX_IOR: f32 = 1000.0;
const FRESNEL_MODEL_DIELECTRIC: i32 = 0;
// Thickest film taken (nanometres): interference has washed out long before.
const MX_MAX_FILM_NM: f32 = 1.0e5;
// Smallest alpha the lobe uses: a mirror to 1e-4, without the overflow of D at alpha -> 0.
const MX_GGX_MIN_ALPHA: f32 = 1.0e-4;

struct PixelUniforms {
    u_envMatrix: mat4x4f,  // offset 0
    u_envLightIntensity: f32,  // offset 64
    u_envRadianceMips: i32,  // offset 68
    u_envRadianceSamples: i32,  // offset 72
    u_refractionTwoSided: i32,  // offset 76
    u_viewPosition: vec3f,  // offset 80
}
@group(1) @binding(0) var<uniform> pu: PixelUniforms;

@group(1) @binding(1) var u_envRadiance: texture_2d<f32>;
@group(1) @binding(2) var u_envRadiance_sampler: sampler;

struct VertexData {
    @builtin(position) position: vec4f,
    @location(0) normalWorld: vec3f,
    @location(1) tangentWorld: vec3f,
    @location(2) positionWorld: vec3f,
}

var<private> vd: VertexData;

fn mx_runtime_f32(value: f32) -> f32 {
    return value;
}

fn mx_sqr(x: vec2f) -> vec2f {
    return x * x;
}

// x clamped to [lo, hi], NaN taken as lo. A lobe's parameters may be computed by the graph (a
// division by zero, the log of a negative): each lobe passes them through this once, so they
// arrive finite and in range. GLSL leaves clamp() of a NaN undefined, hence the test.
fn mx_clamp_finite_float_float_float(x: f32, lo: f32, hi: f32) -> f32 {
    return select(clamp(x, lo, hi), lo, (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u);
}

fn mx_clamp_finite_vec2_float_float(x: vec2f, lo: f32, hi: f32) -> vec2f {
    return vec2f(mx_clamp_finite_float_float_float(x.x, lo, hi),
                 mx_clamp_finite_float_float_float(x.y, lo, hi));
}

fn mx_clamp_finite_vec3_float_float(x: vec3f, lo: f32, hi: f32) -> vec3f {
    return vec3f(mx_clamp_finite_float_float_float(x.x, lo, hi),
                 mx_clamp_finite_float_float_float(x.y, lo, hi),
                 mx_clamp_finite_float_float_float(x.z, lo, hi));
}

// The normal flipped, where needed, to the side of the surface that `V` sees.
fn mx_facing_normal(N: vec3f, V: vec3f) -> vec3f {
    return select(N, -N, dot(N, V) < 0.0);
}

// Any orthonormal frame around the unit vector N, columns (X, Y, N) (Duff et al. 2017).
fn mx_frame_from_normal(N: vec3f) -> mat3x3f {
    let s: f32 = select(1.0, -1.0, N.z < 0.0);
    let a: f32 = -1.0 / (s + N.z);
    let b: f32 = N.x * N.y * a;
    return mat3x3f(vec3f(1.0 + s * N.x * N.x * a, s * b, -s * N.x), vec3f(b, s + N.y * N.y * a, -N.y), N);
}

// A lobe's weight that scatters nothing: zero, negative, or NaN (a NaN computed in the graph, which
// compares false with everything, is absorbed rather than spread over the image).
fn mx_weight_is_zero(weight: f32) -> bool {
    return (bitcast<u32>(weight) & 0x7fffffffu) > 0x7f800000u || weight < MX_EPS;
}

// The normal a closure shades with: N when it is a usable direction, else the interpolated
// surface normal (a normal map whose perturbation cancels to zero, or a NaN from the graph).
fn mx_usable_normal(N: vec3f, surfaceNormal: vec3f) -> vec3f {
    let len2: f32 = dot(N, N);
    return select(N * inverseSqrt(len2), surfaceNormal,
                  (bitcast<u32>(len2) & 0x7fffffffu) > 0x7f800000u ||
                  (bitcast<u32>(len2) & 0x7fffffffu) == 0x7f800000u || len2 < MX_EPS);
}

// Columns (X, Y, N): `X` made orthogonal to the unit normal `N`, then Y = N x X; any frame about N
// when X is zero or along N.
fn mx_tangent_frame(N: vec3f, X: vec3f) -> mat3x3f {
    var T: vec3f = X - N * dot(X, N);
    let len2: f32 = dot(T, T);
    if ((bitcast<u32>(len2) & 0x7fffffffu) > 0x7f800000u || len2 < MX_EPS) {
        return mx_frame_from_normal(N);
    }
    T *= inverseSqrt(len2);
    return mat3x3f(T, cross(N, T), N);
}

// Point `i` of a `count`-point spherical Fibonacci set in [0, 1)^2: a stratified first coordinate
// and the golden-ratio sequence as the second. Every sampled integral of the library uses it, so
// the sample pattern (and the image) matches the reference renderer's.
fn mx_fibonacci_point(i: i32, count: i32) -> vec2f {
    let GOLDEN_RATIO: f32 = 1.6180339887498948;
    return vec2f((f32(i) + 0.5) / f32(count), fract((f32(i) + 1.0) * GOLDEN_RATIO));
}

fn mx_fresnel_data(model: i32, ior: vec3f, extinction: vec3f, F0: vec3f, F82: vec3f, F90: vec3f,
                   exponent: f32, tf_thickness: f32, tf_ior: f32) -> FresnelData {
    // every specular lobe builds its Fresnel data once: the indices and the film are made finite here
    return FresnelData(model, mx_clamp_finite_vec3_float_float(ior, 0.0, MX_MAX_IOR),
                       mx_clamp_finite_vec3_float_float(extinction, 0.0, MX_MAX_IOR), F0, F82, F90, exponent,
                       mx_clamp_finite_float_float_float(tf_thickness, 0.0, MX_MAX_FILM_NM),
                       mx_clamp_finite_float_float_float(tf_ior, 0.0, MX_MAX_IOR), false);
}

// Unpolarised reflectance of a dielectric interface with relative index `eta` (transmitted over
// incident side); 1 under total internal reflection.
fn mx_fresnel_dielectric(cosTheta: f32, eta: f32) -> f32 {
    let c: f32 = cosTheta;
    let gg: f32 = eta * eta + c * c - 1.0;
    if (gg < 0.0) { return 1.0; }
    let g: f32 = sqrt(gg);
    let s: f32 = (g - c) / (g + c);
    let p: f32 = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * s * s * (1.0 + p * p);
}

// Generation-time features (shadergen/features.py): a shader keeps the models its closures use,
// and the thin film only when some closure's film can be thicker than 0. `withFilm` false leaves
// fd's film out: a caller that knows it has none passes a constant and gets no film code, which
// matters where F is taken per sample, since a CPU rasterizer (Mesa's llvmpipe) runs both sides
// of a branch (mx_environment_reflected).
fn mx_fresnel_eval_film(cosTheta: f32, fd: FresnelData, withFilm: bool) -> vec3f {
    if (fd.model == FRESNEL_MODEL_DIELECTRIC) { return vec3f(mx_fresnel_dielectric(cosTheta, fd.ior.x)); }
    return vec3f(0.0);  // no closure of this shader uses another model
}

fn mx_ggx_clamp_alpha(alpha: vec2f) -> vec2f {
    return mx_clamp_finite_vec2_float_float(alpha, MX_GGX_MIN_ALPHA, 1.0);
}

// Normal distribution D(H) (Walter et al. 2007, eq. 33, in its anisotropic form).
fn mx_ggx_D(H: vec3f, alpha: vec2f) -> f32 {
    let scaled: vec3f = vec3f(H.xy / alpha, H.z);
    let q: f32 = dot(scaled, scaled);
    return 1.0 / (MX_PI * alpha.x * alpha.y * q * q);
}

// Smith's Lambda of GGX for direction w (Heitz 2014, eq. 86): the mean slope seen along w.
fn mx_ggx_lambda(w: vec3f, alpha: vec2f) -> f32 {
    let z2: f32 = max(w.z * w.z, MX_EPS);
    let slope2: f32 = dot(mx_sqr(w.xy * alpha), vec2f(1.0)) / z2;
    return 0.5 * (sqrt(1.0 + slope2) - 1.0);
}

// Masking of the view, G1 = 1 / (1 + Lambda(V)).
fn mx_ggx_G1(V: vec3f, alpha: vec2f) -> f32 {
    return 1.0 / (1.0 + mx_ggx_lambda(V, alpha));
}

// mx_ggx_sample_weight with the view's Lambda(V) given: the samples of one view share it.
fn mx_ggx_sample_weight_given(lambdaV: f32, L: vec3f, alpha: vec2f) -> f32 {
    if (L.z <= 0.0) { return 0.0; }
    return (1.0 + lambdaV) / (1.0 + lambdaV + mx_ggx_lambda(L, alpha));
}

// What a light direction sampled through a visible normal carries, f cos / pdf with F = 1:
// G2 / G1 (Heitz 2014, sect. 5.3), 0 below the horizon.
fn mx_ggx_sample_weight(V: vec3f, L: vec3f, alpha: vec2f) -> f32 {
    return mx_ggx_sample_weight_given(mx_ggx_lambda(V, alpha), L, alpha);
}

// A visible normal for view V from the uniform point u: the view stretched to the unit-roughness
// configuration, a normal drawn uniformly on the spherical cap it sees (Dupuy & Benyoub 2023),
// then unstretched.
fn mx_ggx_sample_visible_normal(u: vec2f, V: vec3f, alpha: vec2f) -> vec3f {
    let Vs: vec3f = normalize(vec3f(V.xy * alpha, max(V.z, MX_EPS)));
    let phi: f32 = 2.0 * MX_PI * u.x;
    let z: f32 = (1.0 - u.y) * (1.0 + Vs.z) - Vs.z;
    let r: f32 = sqrt(clamp(1.0 - z * z, 0.0, 1.0));
    let Hs: vec3f = vec3f(r * cos(phi), r * sin(phi), z) + Vs;
    return normalize(vec3f(Hs.xy * alpha, max(Hs.z, MX_EPS)));
}

// Density of the reflected direction drawn through visible normal H: D G1(V) / (4 cos(V)).
fn mx_ggx_reflection_pdf(H: vec3f, V: vec3f, alpha: vec2f) -> f32 {
    return mx_ggx_D(H, alpha) * mx_ggx_G1(V, alpha) / (4.0 * max(V.z, MX_EPS));
}

// The texel coordinates of map direction `mapDir`, a unit vector up to rounding.
fn mx_envmap_uv(mapDir: vec3f) -> vec2f {
    return vec2f(atan2(mapDir.x, -mapDir.z) * MX_INV_PI * 0.5 + 0.5,
                 0.5 - asin(clamp(mapDir.y, -1.0, 1.0)) * MX_INV_PI);
}

// The map `envMap` seen along map direction `mapDir`, at mip level `lod`.
fn mx_envmap_lookup(envMap: texture_2d<f32>, envMap_sampler: sampler, mapDir: vec3f, lod: f32) -> vec3f {
    return textureSampleLevel(envMap, envMap_sampler, mx_envmap_uv(mapDir), lod).xyz;
}

// Direction leaving a solid sphere of index `ior` that ray direction R enters where the normal is N.
// Where a refraction is total internal reflection the ray reflects instead, so a direction always
// comes back.
fn mx_refraction_solid_sphere(R: vec3f, N: vec3f, ior: f32) -> vec3f {
    let eta: f32 = max(ior, 1.0e-3);
    let inside: vec3f = refract(R, N, 1.0 / eta);
    if (dot(inside, inside) == 0.0) { return reflect(R, N); }
    let exitNormal: vec3f = normalize(inside * dot(inside, N) - N * 0.5);
    let leaving: vec3f = refract(inside, exitNormal, eta);
    return select(leaving, reflect(inside, exitNormal), dot(leaving, leaving) == 0.0);
}

// Mip level for a sample of density `pdf` along map direction `mapDir` (GPU Gems 3, 20.4, eq. 13),
// with the lat-long map's stretching towards its poles, biased 1.5 levels sharper.
fn mx_envmap_lod(mapDir: vec3f, pdf: f32, sampleCount: i32) -> f32 {
    let coarsest: f32 = f32(pu.u_envRadianceMips - 1) - 1.5;
    let stretch: f32 = sqrt(1.0 - mapDir.y * mapDir.y);
    return max(coarsest - 0.5 * log2(f32(sampleCount) * pdf * stretch), 0.0);
}

// The environment along map direction `Lm` as one of `count` samples of density `pdf` sees it
// (filtered importance sampling): read at the level whose texels cover the solid angle 1 / (count
// pdf) the sample stands for, in the chain the shader reads (the radiance map's mips, or with
// MX_ENV_PREFILTER the prefiltered chain's GGX lobes).
fn mx_environment_sample(Lm: vec3f, pdf: f32, count: i32) -> vec3f {
    return mx_envmap_lookup(u_envRadiance, u_envRadiance_sampler, Lm, mx_envmap_lod(Lm, pdf, count));
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
fn mx_environment_samples(N: vec3f, V: vec3f, X: vec3f, alpha: vec2f, fd: FresnelData, fetch: bool,
                          withFilm: bool, albedo: ptr<function, vec3f>) -> vec3f {
    *albedo = vec3f(0.0);
    let sampleCount: i32 = pu.u_envRadianceSamples;
    if (sampleCount <= 0) { return vec3f(0.0); }
    let frame: mat3x3f = mx_tangent_frame(N, X);
    var Vt: vec3f = V * frame;  // (V.X, V.Y, V.N)
    Vt.z = max(Vt.z, MX_EPS);
    let toMap: mat3x3f = mat3x3f(pu.u_envMatrix[0].xyz, pu.u_envMatrix[1].xyz, pu.u_envMatrix[2].xyz) * frame;  // a sample's direction straight to the map's (a rotation)
    var carried: vec3f = vec3f(0.0);
    var whiteAlbedo: f32 = 0.0;
    for (var i: i32 = 0; i < sampleCount; i++) {
        let H: vec3f = mx_ggx_sample_visible_normal(mx_fibonacci_point(i, sampleCount), Vt, alpha);
        let Lt: vec3f = select(reflect(-Vt, H), mx_refraction_solid_sphere(-Vt, H, fd.ior.x), fd.refraction);
        var Li: vec3f = vec3f(0.0);
        if (fetch) {
            Li = mx_environment_sample(toMap * Lt, mx_ggx_reflection_pdf(H, Vt, alpha), sampleCount);
        }
        let F: vec3f = mx_fresnel_eval_film(clamp(dot(Vt, H), MX_EPS, 1.0), fd, withFilm);
        let weight: f32 = select(mx_ggx_sample_weight(Vt, Lt, alpha), 1.0, fd.refraction);
        let throughput: vec3f = select(F * weight, vec3f(1.0) - F, fd.refraction);
        carried += Li * throughput;
        *albedo += throughput;
        whiteAlbedo += weight;
    }
    let scale: f32 = 1.0 / f32(sampleCount);
    if (!fd.refraction) {
        let E: f32 = whiteAlbedo * scale;
        let compensation: vec3f = vec3f(1.0) +
                                  mx_fresnel_eval_film(Vt.z, fd, withFilm) * ((1.0 - E) / max(E, MX_EPS));
        carried *= compensation;
        *albedo *= compensation;
    }
    *albedo *= scale;
    return carried * (scale * pu.u_envLightIntensity);
}

// The environment seen through the lobe (see mx_environment_samples).
fn mx_environment_radiance(N: vec3f, V: vec3f, X: vec3f, alpha: vec2f, distribution: i32, fd: FresnelData,
                           albedo: ptr<function, vec3f>) -> vec3f {
    return mx_environment_samples(N, V, X, alpha, fd, true, true, albedo);
}

fn mx_surface_transmission(N: vec3f, V: vec3f, X: vec3f, alpha: vec2f, distribution: i32, fd__in: FresnelData,
                           tint: vec3f) -> vec3f {
    var fd: FresnelData = fd__in;
    fd.refraction = true;
    // A two-sided interface filters the light twice.
    let through: vec3f = select(tint, tint * tint, (pu.u_refractionTwoSided != 0));
    var transmitted: vec3f;
    return mx_environment_radiance(N, V, X, alpha, distribution, fd, &transmitted) * through;
}

// What every specular closure prepares alike; the caller sets `albedo` from its own table. The
// environment is fetched unless the lobe only transmits (its albedo is still needed there).
fn mx_specular_lobe_prepare(closureData: ClosureData, weight: f32, tint: vec3f, roughness: vec2f,
                            retroreflective: bool, fd: FresnelData, N: vec3f, X: vec3f, distribution: i32,
                            scatterMode: i32) -> SpecularLobe {
    var lobe: SpecularLobe;
    lobe.weight = select(weight, 0.0, mx_weight_is_zero(weight));
    lobe.tint = max(tint, vec3f(0.0));
    lobe.surfaceN = mx_usable_normal(N, closureData.N);
    lobe.V = select(closureData.V, reflect(-closureData.V, lobe.surfaceN), retroreflective);
    lobe.N = mx_facing_normal(lobe.surfaceN, lobe.V);
    lobe.X = X;
    lobe.alpha = mx_ggx_clamp_alpha(roughness);
    lobe.scatterMode = scatterMode;
    lobe.distribution = distribution;
    lobe.environment = vec3f(0.0);
    lobe.environmentAlbedo = vec3f(0.0);
    lobe.refracted = vec3f(0.0);
    if (lobe.weight > 0.0) {
        var written_0: vec3f = lobe.environmentAlbedo;
        var written_1: vec3f = lobe.environmentAlbedo;
        lobe.environment = mx_environment_samples(lobe.N, lobe.V, X, lobe.alpha, fd, scatterMode != 1, false,
                                                  &written_1);
        lobe.environmentAlbedo = written_0;
        lobe.environmentAlbedo = written_1;
    }
    return lobe;
}

// The environment seen through a prepared lobe's interface, with Fresnel data `fd` and `tint`:
// prepared once per shading point like its reflection. Drivers inline every call, so computed in
// the closure's TRANSMISSION branch it would be compiled into every context's call of the closure,
// and for each lobe of a shader that refracts at all; here a lobe whose scatter mode is a constant
// R (0) drops it at compile time.
fn mx_specular_lobe_refract(closureData: ClosureData, fd: FresnelData, tint: vec3f, scatterMode: i32,
                            lobe: ptr<function, SpecularLobe>) {
    if (scatterMode != 0 && (*lobe).weight > 0.0) {
        (*lobe).refracted = mx_surface_transmission(mx_facing_normal((*lobe).surfaceN, closureData.V),
                                                    closureData.V, (*lobe).X, (*lobe).alpha,
                                                    (*lobe).distribution, fd, tint);
    }
}

// What the lobe reflects of the environment as seen through it along the real view direction:
// the prepared samples, or new ones where retro-reflection prepared them along the mirrored view.
fn mx_specular_transmission_albedo(closureData: ClosureData, lobe: SpecularLobe) -> vec3f {
    return lobe.environmentAlbedo;
}

// What the layers below receive of light from one direction, given what the lobe reflects of it.
fn mx_specular_throughput(reflected: vec3f, weight: f32) -> vec3f {
    return max(vec3f(1.0) - reflected * weight, vec3f(0.0));
}

// True for the contexts a scattering closure answers (emission and the default context get nothing).
fn mx_is_scattering_context(closureType: i32) -> bool {
    return closureType == CLOSURE_TYPE_REFLECTION || closureType == CLOSURE_TYPE_TRANSMISSION ||
           closureType == CLOSURE_TYPE_INDIRECT;
}

// Once per shading point (lib/mx_specular.glsl); the albedo towards V is needed under lights only.
fn mx_dielectric_bsdf_prepare(closureData: ClosureData, weight: f32, tint: vec3f, ior: f32, roughness: vec2f,
                              retroreflective: bool, thinfilm_thickness: f32, thinfilm_ior: f32, N: vec3f,
                              X: vec3f, distribution: i32, scatter_mode: i32,
                              lobe: ptr<function, SpecularLobe>) {
    let fd: FresnelData = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3f(ior), vec3f(0.0), vec3f(0.0),
                                          vec3f(0.0), vec3f(0.0), 0.0, thinfilm_thickness, thinfilm_ior);
    *lobe = mx_specular_lobe_prepare(closureData, weight, tint, roughness, retroreflective, fd, N, X,
                                     distribution, scatter_mode);
    mx_specular_lobe_refract(closureData, fd, (*lobe).tint, scatter_mode, lobe);
}

// In each context. What the interface reflects, multiple scattering included, does not reach the
// layers below.
fn mx_dielectric_bsdf(closureData: ClosureData, lobe: SpecularLobe, bsdf: ptr<function, BSDF>) {
    let context: i32 = closureData.closureType;
    let transmission: bool = context == CLOSURE_TYPE_TRANSMISSION;
    if (lobe.weight == 0.0 || (lobe.scatterMode == 1 && !transmission) || !mx_is_scattering_context(context)) {
        return;
    }
    if (context == CLOSURE_TYPE_INDIRECT) {
        (*bsdf).throughput = mx_specular_throughput(lobe.environmentAlbedo, lobe.weight);
        (*bsdf).response = lobe.environment * lobe.tint * lobe.weight;
    }
    else {
        if (transmission) {
            (*bsdf).throughput = mx_specular_throughput(mx_specular_transmission_albedo(closureData, lobe),
                                                        lobe.weight);
            if (lobe.scatterMode != 0) { (*bsdf).response = lobe.refracted * lobe.weight; }
        }
    }
}

@fragment
fn fragmentMain(vertexData: VertexData) -> @location(0) vec4f {
    vd = vertexData;
    var out1: vec4f;
    var n0_out: vec3f = normalize(vd.normalWorld);
    var n1_out: vec3f = normalize(vd.tangentWorld);
    var n3_out: surfaceshader = surfaceshader(vec3f(0.0), vec3f(0.0));
    {
        var N: vec3f = normalize(vd.normalWorld);
        var V: vec3f = normalize(pu.u_viewPosition - vd.positionWorld);
        var P: vec3f = vd.positionWorld;
        var L: vec3f = vec3f(0.0);
        var occlusion: f32 = 1.0;
        var surfaceOpacity: f32 = 1.0;
        // lobes prepared once per shading point, before any light
        var pointData: ClosureData = ClosureData(CLOSURE_TYPE_DEFAULT, L, V, N, P, occlusion);
        var n2_lobe: SpecularLobe;
        mx_dielectric_bsdf_prepare(pointData, 1.0, vec3f(1.0, 1.0, 1.0), 1.45, vec2f(0.05, 0.05), false,
                                       0.0, 1.5, n0_out, n1_out, 0, 2, &n2_lobe);
        // environment
        {
            var closureData: ClosureData = ClosureData(CLOSURE_TYPE_INDIRECT, L, V, N, P, occlusion);
            var n2_out: BSDF = BSDF(vec3f(0.0), vec3f(1.0));
            mx_dielectric_bsdf(closureData, n2_lobe, &n2_out);
            n3_out.color += occlusion * n2_out.response;
        }
        // transmission, seen along the view direction
        {
            var closureData: ClosureData = ClosureData(CLOSURE_TYPE_TRANSMISSION, L, V, N, P, occlusion);
            var n2_out: BSDF = BSDF(vec3f(0.0), vec3f(1.0));
            mx_dielectric_bsdf(closureData, n2_lobe, &n2_out);
            n3_out.color += n2_out.response;
        }
        n3_out.color *= surfaceOpacity;
        n3_out.transparency = mix(vec3f(1.0), n3_out.transparency, vec3f(surfaceOpacity));
    }
    var n4_out: surfaceshader = n3_out;
    out1 = vec4f(n4_out.color, 1.0 - dot(n4_out.transparency, vec3f(mx_runtime_f32(1.0) / 3.0)));
    return out1;
}
