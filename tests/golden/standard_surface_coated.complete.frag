#version 400

struct surfaceshader { vec3 color; vec3 transparency; };
struct displacementshader { vec3 offset; float scale; };
struct lightshader { vec3 intensity; vec3 direction; };
struct BSDF { vec3 response; vec3 throughput; };
#define EDF vec3
struct VDF { vec3 response; vec3 throughput; };
#define material surfaceshader
#define MAX_LIGHT_SOURCES 3
struct LightData { int type; vec3 position; vec3 direction; vec3 color; float intensity; float decay_rate; float inner_angle; float outer_angle; };

// Uniform block: PrivateUniforms
uniform mat4 u_envMatrix;
uniform sampler2D u_envRadiance;
uniform float u_envLightIntensity;
uniform int u_envRadianceMips;
uniform int u_envRadianceSamples;
uniform sampler2D u_envIrradiance;
uniform bool u_refractionTwoSided;
uniform vec3 u_viewPosition;
uniform int u_numActiveLightSources;
uniform LightData u_lightData[MAX_LIGHT_SOURCES];

// Uniform block: PublicUniforms
uniform float u_n70_diffuse_roughness = 0.0;
uniform float u_n70_metalness = 0.0;
uniform float u_n70_specular = 1.0;
uniform vec3 u_n70_specular_color = vec3(1.0, 1.0, 1.0);
uniform float u_n70_specular_roughness = 0.2;
uniform float u_n70_specular_IOR = 1.5;
uniform float u_n70_specular_anisotropy = 0.0;
uniform float u_n70_specular_rotation = 0.0;
uniform float u_n70_transmission = 0.0;
uniform vec3 u_n70_transmission_color = vec3(1.0, 1.0, 1.0);
uniform float u_n70_transmission_depth = 0.0;
uniform vec3 u_n70_transmission_scatter = vec3(0.0, 0.0, 0.0);
uniform float u_n70_transmission_scatter_anisotropy = 0.0;
uniform float u_n70_transmission_dispersion = 0.0;
uniform float u_n70_transmission_extra_roughness = 0.0;
uniform float u_n70_subsurface = 0.0;
uniform vec3 u_n70_subsurface_color = vec3(1.0, 1.0, 1.0);
uniform vec3 u_n70_subsurface_radius = vec3(1.0, 1.0, 1.0);
uniform float u_n70_subsurface_scale = 1.0;
uniform float u_n70_subsurface_anisotropy = 0.0;
uniform float u_n70_sheen = 0.0;
uniform vec3 u_n70_sheen_color = vec3(1.0, 1.0, 1.0);
uniform float u_n70_sheen_roughness = 0.3;
uniform float u_n70_coat = 0.0;
uniform vec3 u_n70_coat_color = vec3(1.0, 1.0, 1.0);
uniform float u_n70_coat_roughness = 0.1;
uniform float u_n70_coat_anisotropy = 0.0;
uniform float u_n70_coat_rotation = 0.0;
uniform float u_n70_coat_IOR = 1.5;
uniform float u_n70_coat_affect_color = 0.0;
uniform float u_n70_coat_affect_roughness = 0.0;
uniform float u_n70_thin_film_thickness = 0.0;
uniform float u_n70_thin_film_IOR = 1.5;
uniform float u_n70_emission = 0.0;
uniform vec3 u_n70_emission_color = vec3(1.0, 1.0, 1.0);
uniform vec3 u_n70_opacity = vec3(1.0, 1.0, 1.0);
uniform bool u_n70_thin_walled = false;
uniform float u_n70_base = 1.0;
uniform vec3 u_n70_base_color = vec3(0.8, 0.8, 0.8);
uniform surfaceshader u_n69_backsurfaceshader;
uniform displacementshader u_n69_displacementshader;

in VertexData
{
    vec3 normalWorld;
    vec3 tangentWorld;
    vec3 positionWorld;
} vd;

out vec4 out1;

const float MX_PI = 3.1415926535897932;
const float MX_INV_PI = 1.0 / MX_PI;
const float MX_EPS = 1.0e-8;  // floor for cosines and weights, as in MaterialX's hardware shading

float mx_sqr(float x) { return x * x; }
vec2 mx_sqr(vec2 x) { return x * x; }
vec3 mx_sqr(vec3 x) { return x * x; }

// x^y for x >= 0 and any y: GLSL leaves pow(0, y <= 0) undefined; here 0^y is 1 for y <= 0.
float mx_power(float x, float y)
{
    return (y <= 0.0) ? 1.0 : pow(max(x, 0.0), y);
}

// Largest index of refraction (real or imaginary part) a lobe takes: far above any material's
// (metals' extinction stays below ~10), low enough that its fourth power is a finite float.
const float MX_MAX_IOR = 1000.0;

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
    return mat3(vec3(1.0 + s * N.x * N.x * a, s * b, -s * N.x),
                vec3(b, s + N.y * N.y * a, -N.y),
                N);
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

// The normal a closure shades with, on the side of the surface that V sees.
vec3 mx_shading_normal(vec3 N, vec3 surfaceNormal, vec3 V)
{
    return mx_facing_normal(mx_usable_normal(N, surfaceNormal), V);
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

// Density of a cosine-distributed direction with cosine `cosTheta` to the pole.
float mx_cosine_pdf(float cosTheta)
{
    return max(cosTheta, 0.0) * MX_INV_PI;
}

// <roughness_anisotropy>: GGX alpha along the tangent and bitangent from a perceptual roughness
// (squared) and an anisotropy that stretches the lobe along the tangent.
void mx_roughness_anisotropy(float roughness, float anisotropy, out vec2 result)
{
    float alpha = clamp(roughness * roughness, MX_EPS, 1.0);
    if (anisotropy > 0.0)
    {
        float aspect = sqrt(1.0 - clamp(anisotropy, 0.0, 0.98));
        result = vec2(min(alpha / aspect, 1.0), alpha * aspect);
    }
    else
    {
        result = vec2(alpha);
    }
}

// <artistic_ior>: complex index of refraction (n, k) of a metal from its reflectivity at normal
// incidence and its edge tint (Gulbrandsen 2014).
void mx_artistic_ior(vec3 reflectivity, vec3 edge_color, out vec3 ior, out vec3 extinction)
{
    vec3 r = clamp(reflectivity, 0.0, 0.99);
    vec3 sr = sqrt(r);
    vec3 nFromEdge = (1.0 - r) / (1.0 + r);      // the n that gives r with k = 0
    vec3 nFromFacing = (1.0 + sr) / (1.0 - sr);  // the largest n that gives r
    ior = mix(nFromFacing, nFromEdge, edge_color);
    vec3 k2 = ((ior + 1.0) * (ior + 1.0) * r - (ior - 1.0) * (ior - 1.0)) / (1.0 - r);
    extinction = sqrt(max(k2, 0.0));
}

// rotate3d: turn a vector by `degrees` about `axis` (normalized here).
// MaterialX multiplies row vectors (v' = v * M), so the sense of rotation is that of
// Rodrigues' formula with the cross product taken as v x k.
void mx_rotate3d_vector3(vec3 v, float degrees, vec3 axis, out vec3 result)
{
    vec3 k = normalize(axis);
    float angle = radians(degrees);
    float c = cos(angle);
    float s = sin(angle);
    result = v * c + cross(v, k) * s + k * (dot(k, v) * (1.0 - c));
}

// Closure contexts. The surface node evaluates a BSDF graph once per context and every closure
// function branches on it: REFLECTION (one light, closureData.L towards it), TRANSMISSION (what is
// seen through the surface along the view direction), INDIRECT (the environment, sampled by the
// closure itself) and EMISSION (EDF graphs). The numbers are the generator's context ids.
#define CLOSURE_TYPE_DEFAULT 0
#define CLOSURE_TYPE_REFLECTION 1
#define CLOSURE_TYPE_TRANSMISSION 2
#define CLOSURE_TYPE_INDIRECT 3
#define CLOSURE_TYPE_EMISSION 4

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

#ifndef AIRY_FRESNEL_ITERATIONS
#define AIRY_FRESNEL_ITERATIONS 2
#endif

#define FRESNEL_MODEL_DIELECTRIC 0
#define FRESNEL_MODEL_CONDUCTOR 1
#define FRESNEL_MODEL_SCHLICK 2

// Thickest film taken (nanometres): interference has washed out long before.
const float MX_MAX_FILM_NM = 1.0e5;

// How a specular closure reflects: which model with its parameters, an optional thin film on top,
// and whether the environment is to be sampled through the surface (refraction) instead of off it.
struct FresnelData
{
    int model;           // FRESNEL_MODEL_*
    vec3 ior;            // dielectric: ior in every channel; conductor: n
    vec3 extinction;     // conductor: k
    vec3 F0;             // Schlick: reflectance at 0, 82 and 90 degrees, and the exponent
    vec3 F82;
    vec3 F90;
    float exponent;
    float tf_thickness;  // thin film in nanometres; none when <= 0
    float tf_ior;
    bool refraction;
};

FresnelData mx_fresnel_data(int model, vec3 ior, vec3 extinction, vec3 F0, vec3 F82, vec3 F90, float exponent,
                            float tf_thickness, float tf_ior)
{
    // every specular lobe builds its Fresnel data once: the indices and the film are made finite here
    return FresnelData(model, mx_clamp_finite(ior, 0.0, MX_MAX_IOR), mx_clamp_finite(extinction, 0.0, MX_MAX_IOR),
                       F0, F82, F90, exponent, mx_clamp_finite(tf_thickness, 0.0, MX_MAX_FILM_NM),
                       mx_clamp_finite(tf_ior, 0.0, MX_MAX_IOR), false);
}

bool mx_fresnel_has_thinfilm(FresnelData fd)
{
    return fd.tf_thickness > 0.0;
}

// mix(F0, F90, (1 - cos)^exponent), the generalised form (exponent 5 is Schlick's).
vec3 mx_fresnel_schlick_exp(float cosTheta, vec3 F0, vec3 F90, float exponent)
{
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    return mix(F0, F90, mx_power(m, exponent));
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

// Reflectance per polarisation, (parallel, perpendicular).
vec2 mx_fresnel_dielectric_pol(float cosTheta, float eta)
{
    float c2 = mx_sqr(clamp(cosTheta, 0.0, 1.0));
    float s2 = 1.0 - c2;
    float a2 = max(eta * eta - s2, 0.0);
    float twoAc = 2.0 * sqrt(a2) * cosTheta;
    float perp = (a2 + c2 - twoAc) / (a2 + c2 + twoAc);
    float u = c2 * a2 + s2 * s2;
    float w = twoAc * s2;
    return vec2(perp * (u - w) / (u + w), perp);
}

// Reflectance of a conductor with complex index n + ik, per polarisation.
void mx_fresnel_conductor_pol(float cosTheta, vec3 n, vec3 k, out vec3 parallel, out vec3 perpendicular)
{
    float c2 = mx_sqr(clamp(cosTheta, 0.0, 1.0));
    float s2 = 1.0 - c2;
    vec3 d = n * n - k * k - vec3(s2);
    vec3 mag = sqrt(d * d + 4.0 * n * n * k * k);  // a^2 + b^2
    vec3 a = sqrt(max(0.5 * (mag + d), 0.0));
    vec3 twoAc = 2.0 * a * cosTheta;
    vec3 sum = mag + vec3(c2);
    perpendicular = (sum - twoAc) / (sum + twoAc);
    vec3 u = c2 * mag + vec3(s2 * s2);
    vec3 w = twoAc * s2;
    parallel = perpendicular * (u - w) / (u + w);
}

vec3 mx_fresnel_conductor(float cosTheta, vec3 n, vec3 k)
{
    vec3 par, perp;
    mx_fresnel_conductor_pol(cosTheta, n, k, par, perp);
    return 0.5 * (par + perp);
}

// Phase shifts on reflection at a conductor (Belcour & Barla 2017), per polarisation.
void mx_fresnel_conductor_phase(float cosTheta, float eta1, vec3 eta2, vec3 kappa2, out vec3 phiP, out vec3 phiS)
{
    vec3 k = kappa2 / eta2;
    vec3 s2 = vec3(1.0) - cosTheta * cosTheta;
    vec3 oneMinusK2 = vec3(1.0) - k * k;
    vec3 A = eta2 * eta2 * oneMinusK2 - eta1 * eta1 * s2;
    vec3 B = sqrt(A * A + mx_sqr(2.0 * eta2 * eta2 * k));
    vec3 U = sqrt((A + B) / 2.0);
    vec3 V = max(vec3(0.0), sqrt((B - A) / 2.0));
    phiS = atan(2.0 * eta1 * V * cosTheta, U * U + V * V - mx_sqr(eta1 * cosTheta));
    phiP = atan(2.0 * eta1 * eta2 * eta2 * cosTheta * (2.0 * k * U - oneMinusK2 * V),
                mx_sqr(eta2 * eta2 * (vec3(1.0) + k * k) * cosTheta) - eta1 * eta1 * (U * U + V * V));
}

float mx_f0_to_ior(float F0)
{
    float r = sqrt(clamp(F0, 0.01, 0.99));
    return (1.0 + r) / (1.0 - r);
}

vec3 mx_f0_to_ior(vec3 F0)
{
    vec3 r = sqrt(clamp(F0, 0.01, 0.99));
    return (vec3(1.0) + r) / (vec3(1.0) - r);
}

// Colour matching (XYZ) of one harmonic cos(2 pi opd k + phase) over the visible wavenumbers k.
vec3 mx_thinfilm_harmonic_xyz(float opd, vec3 phase)
{
    const vec3 AMPLITUDE = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 CENTRE = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 VARIANCE = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    const float X2_AMPLITUDE = 9.7470e-14;
    const float X2_CENTRE = 2.2399e+06;
    const float X2_VARIANCE = 4.5282e+09;
    const float Y_INTEGRAL = 1.0685e-7;
    float w = 2.0 * MX_PI * opd;
    vec3 xyz = AMPLITUDE * sqrt(2.0 * MX_PI * VARIANCE) * cos(CENTRE * w + phase) * exp(-VARIANCE * w * w);
    xyz.x += X2_AMPLITUDE * sqrt(2.0 * MX_PI * X2_VARIANCE) * cos(X2_CENTRE * w + phase.x) * exp(-X2_VARIANCE * w * w);
    return xyz / Y_INTEGRAL;
}

// Reflectance (XYZ) of one polarisation: R12 + T121^2 R23 / (1 - R12 R23) for the incoherent sum,
// plus the interfering harmonics m = 1, 2, ... with amplitudes (Rdc - T121) r^m, r = sqrt(R12 R23),
// and phase m (phi21 + phi23) (Belcour & Barla 2017, eqs. 9-11).
vec3 mx_thinfilm_polarisation(float R12, vec3 R23, vec3 phase, float opd)
{
    float T121 = 1.0 - R12;
    vec3 Rdc = T121 * T121 * R23 / max(vec3(1.0) - R12 * R23, MX_EPS);
    vec3 r = sqrt(max(R12 * R23, 0.0));
    vec3 amplitude = Rdc - vec3(T121);
    vec3 xyz = vec3(R12) + Rdc;
    for (int m = 1; m <= AIRY_FRESNEL_ITERATIONS; m++)
    {
        amplitude *= r;
        xyz += 2.0 * amplitude * mx_thinfilm_harmonic_xyz(float(m) * opd, float(m) * phase);
    }
    return xyz;
}

// Reflectance of the film (fd.tf_thickness nm, index fd.tf_ior) in vacuum over the base `fd`:
// a dielectric, a conductor, or generalised Schlick read as the dielectric of the same F0.
vec3 mx_fresnel_airy(float cosTheta, FresnelData fd)
{
    // CIE XYZ to linear RGB with an equal-energy white (columns).
    const mat3 XYZ_TO_RGB = mat3(2.3706743, -0.5138850, 0.0052982,
                                 -0.9000405, 1.4253036, -0.0146949,
                                 -0.4706338, 0.0885814, 1.0093968);
    bool schlick = fd.model == FRESNEL_MODEL_SCHLICK;
    float n2 = max(fd.tf_ior, 1.0);
    vec3 n3 = schlick ? mx_f0_to_ior(fd.F0) : max(fd.ior, vec3(MX_EPS));
    vec3 k3 = schlick ? vec3(0.0) : fd.extinction;
    float c1 = clamp(cosTheta, 0.0, 1.0);
    float c2 = sqrt(max(1.0 - (1.0 - c1 * c1) / (n2 * n2), 0.0));  // Snell into the film

    // Top interface, (parallel, perpendicular); reflection from inside the film has phase pi,
    // except for parallel polarisation below Brewster's angle.
    vec2 R12 = mx_fresnel_dielectric_pol(c1, n2);
    vec2 phi21 = vec2((c1 < 1.0 / sqrt(1.0 + n2 * n2)) ? 0.0 : MX_PI, MX_PI);

    // Bottom interface, film to base, with its phase shifts.
    vec3 R23p, R23s, phi23p, phi23s;
    {
        mx_fresnel_conductor_pol(c2, n3 / n2, k3 / n2, R23p, R23s);
        mx_fresnel_conductor_phase(c2, n2, n3, k3, phi23p, phi23s);
    }

    float opd = 2.0 * n2 * c2 * fd.tf_thickness * 1.0e-9;
    vec3 xyz = mx_thinfilm_polarisation(R12.x, R23p, phi23p + phi21.x, opd) +
               mx_thinfilm_polarisation(R12.y, R23s, phi23s + phi21.y, opd);
    return clamp(XYZ_TO_RGB * (0.5 * xyz), 0.0, 1.0);
}

// Generation-time features (shadergen/features.py): a shader keeps the models its closures use,
// and the thin film only when some closure's film can be thicker than 0. `withFilm` false leaves
// fd's film out: a caller that knows it has none passes a constant and gets no film code, which
// matters where F is taken per sample, since a CPU rasterizer (Mesa's llvmpipe) runs both sides
// of a branch (mx_environment_reflected).
vec3 mx_fresnel_eval_film(float cosTheta, FresnelData fd, bool withFilm)
{
    if (withFilm && mx_fresnel_has_thinfilm(fd))
        return mx_fresnel_airy(cosTheta, fd);
    if (fd.model == FRESNEL_MODEL_DIELECTRIC)
        return vec3(mx_fresnel_dielectric(cosTheta, fd.ior.x));
    if (fd.model == FRESNEL_MODEL_CONDUCTOR)
        return mx_fresnel_conductor(cosTheta, fd.ior, fd.extinction);
    return vec3(0.0);  // no closure of this shader uses another model
}

// The cell of a grid of `size` (columns, rows) nodes that holds point p (clamped to the grid):
// xy its lower node, zw the interpolation weights along each axis.
vec4 mx_albedo_cell(vec2 p, vec2 size)
{
    vec2 x = clamp(p, 0.0, 1.0) * (size - 1.0);
    vec2 i = min(floor(x), size - 2.0);
    return vec4(i, x - i);
}

int mx_albedo_index(ivec2 node, int columns)
{
    return node.y * columns + node.x;
}

// (A, B) at alpha = (row / 15)^2, mu = (column / 15)^2 (mu 0 evaluated at 0.001); 96^2 visible normals each
const float MX_ALBEDO_GGX_SCHLICK[512] = float[512](
    0.005132, 0.988860, 0.022059, 0.977813, 0.085792, 0.914200, 0.184630, 0.815368,
    0.308459, 0.691541, 0.445072, 0.554928, 0.581788, 0.418212, 0.707146, 0.292854,
    0.812407, 0.187593, 0.892626, 0.107374, 0.947078, 0.052922, 0.978901, 0.021099,
    0.993953, 0.006047, 0.999045, 0.000955, 0.999964, 0.000036, 1.000000, 0.000000,
    0.079148, 0.877516, 0.063672, 0.828301, 0.098129, 0.866280, 0.189697, 0.802978,
    0.310741, 0.686812, 0.446248, 0.553331, 0.582307, 0.417501, 0.707329, 0.292571,
    0.812429, 0.187514, 0.892586, 0.107381, 0.947028, 0.052952, 0.978864, 0.021124,
    0.993933, 0.006060, 0.999037, 0.000959, 0.999963, 0.000036, 1.000000, 0.000000,
    0.232338, 0.756016, 0.216641, 0.735876, 0.194949, 0.696966, 0.236487, 0.685582,
    0.333805, 0.630529, 0.457493, 0.527004, 0.587185, 0.405494, 0.708720, 0.287516,
    0.811891, 0.185691, 0.891882, 0.107377, 0.946302, 0.053352, 0.978320, 0.021478,
    0.993634, 0.006249, 0.998920, 0.001017, 0.999932, 0.000042, 0.999999, 0.000000,
    0.385230, 0.609612, 0.375781, 0.601585, 0.350622, 0.574243, 0.347867, 0.543735,
    0.395277, 0.510189, 0.486475, 0.451669, 0.598525, 0.365641, 0.710732, 0.268737,
    0.809532, 0.178378, 0.887347, 0.105250, 0.941752, 0.053524, 0.974566, 0.022168,
    0.990877, 0.006752, 0.998113, 0.001284, 0.999734, 0.000091, 0.999979, 0.000000,
    0.519127, 0.477906, 0.513425, 0.473251, 0.495518, 0.455900, 0.481812, 0.429242,
    0.493344, 0.396594, 0.541668, 0.355351, 0.620469, 0.299652, 0.712902, 0.231493,
    0.802037, 0.160969, 0.876428, 0.099078, 0.930899, 0.052559, 0.965526, 0.022915,
    0.984101, 0.007531, 0.992225, 0.001588, 0.994445, 0.000143, 0.993450, 0.000008,
    0.628627, 0.369310, 0.624751, 0.366038, 0.611612, 0.353223, 0.596892, 0.332305,
    0.591785, 0.304770, 0.607698, 0.271311, 0.651083, 0.231388, 0.714188, 0.184632,
    0.784951, 0.134489, 0.851097, 0.087277, 0.904353, 0.049071, 0.941602, 0.022916,
    0.964223, 0.008272, 0.976287, 0.002027, 0.982432, 0.000266, 0.987373, 0.000011,
    0.714420, 0.283877, 0.711169, 0.281253, 0.699552, 0.270821, 0.683768, 0.254078,
    0.675503, 0.232142, 0.677888, 0.205435, 0.696120, 0.174934, 0.730949, 0.141229,
    0.777661, 0.105893, 0.828129, 0.071882, 0.874292, 0.042862, 0.910808, 0.021565,
    0.935965, 0.008593, 0.951397, 0.002431, 0.961427, 0.000392, 0.967333, 0.000015,
    0.779756, 0.218608, 0.776362, 0.216373, 0.763789, 0.207444, 0.749269, 0.193898,
    0.737552, 0.176122, 0.729649, 0.154897, 0.732352, 0.131306, 0.746506, 0.106165,
    0.771163, 0.080642, 0.803029, 0.056372, 0.837010, 0.035232, 0.868311, 0.018946,
    0.894064, 0.008275, 0.913677, 0.002662, 0.927464, 0.000514, 0.937054, 0.000023,
    0.828584, 0.169659, 0.824518, 0.167682, 0.809146, 0.159830, 0.794448, 0.148721,
    0.777869, 0.134078, 0.765669, 0.117121, 0.757504, 0.098578, 0.757392, 0.079436,
    0.764648, 0.060597, 0.779377, 0.043015, 0.799405, 0.027739, 0.821279, 0.015698,
    0.842297, 0.007395, 0.860957, 0.002650, 0.876873, 0.000594, 0.890075, 0.000032,
    0.864636, 0.133347, 0.859505, 0.131538, 0.841563, 0.124663, 0.823437, 0.115064,
    0.803745, 0.102888, 0.785316, 0.089087, 0.769920, 0.074411, 0.759217, 0.059605,
    0.754244, 0.045388, 0.754704, 0.032421, 0.760846, 0.021293, 0.770807, 0.012478,
    0.783407, 0.006224, 0.797151, 0.002431, 0.811037, 0.000616, 0.824610, 0.000040,
    0.891062, 0.106547, 0.884551, 0.104833, 0.863960, 0.098715, 0.840455, 0.090197,
    0.816101, 0.079885, 0.792353, 0.068487, 0.770481, 0.056651, 0.751619, 0.045008,
    0.736634, 0.034093, 0.726037, 0.024355, 0.719942, 0.016136, 0.718331, 0.009664,
    0.720466, 0.005017, 0.725676, 0.002091, 0.733387, 0.000586, 0.742964, 0.000045,
    0.910357, 0.086783, 0.902195, 0.085101, 0.878182, 0.079503, 0.849899, 0.071876,
    0.819698, 0.062931, 0.789671, 0.053322, 0.761108, 0.043603, 0.734897, 0.034288,
    0.711615, 0.025765, 0.691745, 0.018330, 0.675704, 0.012171, 0.663475, 0.007375,
    0.655061, 0.003930, 0.650290, 0.001718, 0.648937, 0.000521, 0.650631, 0.000047,
    0.924416, 0.072168, 0.914360, 0.070466, 0.886260, 0.065202, 0.852192, 0.058212,
    0.816112, 0.050338, 0.779601, 0.042083, 0.744257, 0.033969, 0.710920, 0.026390,
    0.680148, 0.019625, 0.652311, 0.013859, 0.627650, 0.009178, 0.606377, 0.005588,
    0.588478, 0.003025, 0.573997, 0.001367, 0.562910, 0.000441, 0.555150, 0.000047,
    0.934646, 0.061305, 0.922471, 0.059538, 0.889693, 0.054457, 0.849885, 0.047991,
    0.807152, 0.040885, 0.763988, 0.033676, 0.721624, 0.026789, 0.681423, 0.020526,
    0.643631, 0.015079, 0.608683, 0.010544, 0.576759, 0.006940, 0.547901, 0.004225,
    0.522119, 0.002306, 0.499427, 0.001065, 0.479747, 0.000361, 0.463002, 0.000044,
    0.942072, 0.053173, 0.927568, 0.051302, 0.889577, 0.046291, 0.844065, 0.040225,
    0.794329, 0.033704, 0.744272, 0.027312, 0.695097, 0.021381, 0.648030, 0.016134,
    0.603770, 0.011689, 0.562484, 0.008078, 0.524360, 0.005271, 0.489431, 0.003196,
    0.457589, 0.001751, 0.428724, 0.000821, 0.402706, 0.000288, 0.379350, 0.000039,
    0.947439, 0.047033, 0.930406, 0.045026, 0.887822, 0.040109, 0.835409, 0.034238,
    0.778899, 0.028187, 0.721677, 0.022432, 0.665791, 0.017260, 0.612347, 0.012811,
    0.562052, 0.009140, 0.515254, 0.006231, 0.472094, 0.004024, 0.432534, 0.002424,
    0.396411, 0.001327, 0.363600, 0.000628, 0.333787, 0.000226, 0.306833, 0.000034);

// Albedo = F0 A + F90 B of the GGX lobe at view cosine mu and isotropic alpha.
vec2 mx_ggx_albedo_schlick_scale_bias(float mu, float roughness)
{
    vec4 c = mx_albedo_cell(vec2(sqrt(max(mu, 0.0)), sqrt(max(roughness, 0.0))), vec2(16.0, 16.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix(vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 0), 16) + 1]), vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 0), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 0), 16) + 1]), c.z),
               mix(vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 1), 16) + 1]), vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 1), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 1), 16) + 1]), c.z), c.w);
}

// Smallest alpha the lobe uses: a mirror to 1e-4, without the overflow of D at alpha -> 0.
const float MX_GGX_MIN_ALPHA = 1.0e-4;

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

// Height-correlated masking-shadowing, G2 = 1 / (1 + Lambda(V) + Lambda(L)) (Heitz 2014, eq. 99).
float mx_ggx_G2(vec3 V, vec3 L, vec2 alpha)
{
    return 1.0 / (1.0 + mx_ggx_lambda(V, alpha) + mx_ggx_lambda(L, alpha));
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

// One isotropic alpha standing for an anisotropic pair in the tables.
float mx_ggx_isotropic_alpha(vec2 alpha)
{
    return sqrt(alpha.x * alpha.y);
}

// Turquin 2019: the lobe scaled by 1 + F (1 - E) / E returns the energy that single scattering
// loses between microfacets (1 - E with a white Fresnel), tinted by the Fresnel colour F.
vec3 mx_ggx_energy_compensation(float NdotV, float alpha, vec3 F)
{
    vec2 scaleBias = mx_ggx_albedo_schlick_scale_bias(NdotV, alpha);
    float E = max(scaleBias.x + scaleBias.y, MX_EPS);
    return vec3(1.0) + F * ((1.0 - E) / E);
}

// The texel coordinates of map direction `mapDir`, a unit vector up to rounding.
vec2 mx_envmap_uv(vec3 mapDir)
{
    return vec2(atan(mapDir.x, -mapDir.z) * MX_INV_PI * 0.5 + 0.5, 0.5 - asin(clamp(mapDir.y, -1.0, 1.0)) * MX_INV_PI);
}

// The map `envMap` seen along map direction `mapDir`, at mip level `lod`.
vec3 mx_envmap_lookup(sampler2D envMap, vec3 mapDir, float lod)
{
    return textureLod(envMap, mx_envmap_uv(mapDir), lod).rgb;
}

// The map `envMap` seen along world direction `dir`, at mip level `lod`.
vec3 mx_envmap_fetch(sampler2D envMap, vec3 dir, float lod)
{
    return mx_envmap_lookup(envMap, normalize((u_envMatrix * vec4(dir, 0.0)).xyz), lod);
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

// Irradiance / pi arriving at a point with normal N: what a white Lambert surface reflects.
vec3 mx_environment_irradiance(vec3 N)
{
    return mx_envmap_fetch(u_envIrradiance, N, 0.0) * u_envLightIntensity;
}

const float MX_DFG_C1[256] = float[](
    0.0010, 0.0147, 0.0428, 0.0749, 0.1084, 0.1420, 0.1744, 0.2050, 0.2334, 0.2591, 0.2820, 0.3021, 0.3193, 0.3339, 0.3461, 0.3562,
    0.0044, 0.0133, 0.0420, 0.0749, 0.1089, 0.1427, 0.1752, 0.2060, 0.2344, 0.2602, 0.2832, 0.3034, 0.3209, 0.3358, 0.3483, 0.3588,
    0.0177, 0.0208, 0.0428, 0.0762, 0.1114, 0.1461, 0.1793, 0.2104, 0.2390, 0.2650, 0.2882, 0.3088, 0.3267, 0.3422, 0.3556, 0.3670,
    0.0399, 0.0412, 0.0544, 0.0830, 0.1178, 0.1530, 0.1867, 0.2182, 0.2471, 0.2734, 0.2970, 0.3180, 0.3365, 0.3525, 0.3665, 0.3787,
    0.0710, 0.0714, 0.0793, 0.1000, 0.1309, 0.1650, 0.1985, 0.2301, 0.2592, 0.2855, 0.3092, 0.3303, 0.3491, 0.3656, 0.3802, 0.3933,
    0.1109, 0.1108, 0.1156, 0.1292, 0.1536, 0.1841, 0.2161, 0.2469, 0.2756, 0.3018, 0.3253, 0.3465, 0.3653, 0.3820, 0.3969, 0.4104,
    0.1598, 0.1591, 0.1622, 0.1702, 0.1873, 0.2122, 0.2407, 0.2696, 0.2972, 0.3226, 0.3457, 0.3664, 0.3850, 0.4017, 0.4167, 0.4301,
    0.2176, 0.2163, 0.2181, 0.2218, 0.2321, 0.2502, 0.2736, 0.2991, 0.3244, 0.3484, 0.3704, 0.3905, 0.4085, 0.4248, 0.4395, 0.4527,
    0.2843, 0.2824, 0.2831, 0.2832, 0.2874, 0.2985, 0.3156, 0.3363, 0.3582, 0.3797, 0.4001, 0.4188, 0.4359, 0.4514, 0.4654, 0.4781,
    0.3598, 0.3573, 0.3570, 0.3538, 0.3524, 0.3565, 0.3668, 0.3816, 0.3990, 0.4171, 0.4350, 0.4518, 0.4674, 0.4816, 0.4946, 0.5063,
    0.4443, 0.4412, 0.4390, 0.4329, 0.4262, 0.4237, 0.4269, 0.4352, 0.4472, 0.4610, 0.4755, 0.4898, 0.5033, 0.5158, 0.5273, 0.5377,
    0.5376, 0.5339, 0.5295, 0.5192, 0.5076, 0.4990, 0.4954, 0.4971, 0.5030, 0.5118, 0.5222, 0.5332, 0.5440, 0.5543, 0.5639, 0.5727,
    0.6399, 0.6355, 0.6269, 0.6117, 0.5948, 0.5808, 0.5712, 0.5666, 0.5666, 0.5700, 0.5758, 0.5829, 0.5905, 0.5980, 0.6053, 0.6120,
    0.7510, 0.7461, 0.7278, 0.7068, 0.6844, 0.6671, 0.6531, 0.6434, 0.6380, 0.6363, 0.6374, 0.6402, 0.6442, 0.6486, 0.6532, 0.6575,
    0.8711, 0.8657, 0.8291, 0.7911, 0.7751, 0.7552, 0.7398, 0.7278, 0.7191, 0.7136, 0.7107, 0.7096, 0.7100, 0.7111, 0.7128, 0.7147,
    1.0000, 0.9957, 0.9386, 0.7953, 0.8307, 0.8398, 0.8393, 0.8345, 0.8297, 0.8256, 0.8217, 0.8184, 0.8154, 0.8130, 0.8109, 0.8093);
const float MX_DFG_C2[256] = float[](
    0.0075, 0.5866, 0.6189, 0.6477, 0.6741, 0.6982, 0.7203, 0.7405, 0.7590, 0.7757, 0.7907, 0.8042, 0.8162, 0.8270, 0.8365, 0.8450,
    0.0055, 0.5778, 0.6147, 0.6453, 0.6723, 0.6967, 0.7191, 0.7394, 0.7581, 0.7750, 0.7902, 0.8038, 0.8160, 0.8269, 0.8365, 0.8451,
    0.0181, 0.4944, 0.6000, 0.6360, 0.6650, 0.6924, 0.7162, 0.7376, 0.7568, 0.7741, 0.7897, 0.8037, 0.8162, 0.8273, 0.8373, 0.8461,
    0.0402, 0.3171, 0.5801, 0.6219, 0.6568, 0.6868, 0.7129, 0.7358, 0.7560, 0.7741, 0.7903, 0.8047, 0.8176, 0.8291, 0.8393, 0.8484,
    0.0713, 0.2208, 0.5589, 0.6058, 0.6463, 0.6807, 0.7097, 0.7345, 0.7561, 0.7752, 0.7920, 0.8070, 0.8203, 0.8321, 0.8426, 0.8520,
    0.1113, 0.1962, 0.5392, 0.5907, 0.6351, 0.6740, 0.7068, 0.7341, 0.7575, 0.7777, 0.7953, 0.8109, 0.8246, 0.8367, 0.8474, 0.8569,
    0.1602, 0.2141, 0.5238, 0.5790, 0.6253, 0.6686, 0.7048, 0.7350, 0.7602, 0.7818, 0.8003, 0.8164, 0.8304, 0.8427, 0.8536, 0.8631,
    0.2180, 0.2551, 0.5152, 0.5731, 0.6196, 0.6656, 0.7050, 0.7377, 0.7648, 0.7877, 0.8070, 0.8236, 0.8379, 0.8502, 0.8611, 0.8705,
    0.2846, 0.3116, 0.5173, 0.5752, 0.6204, 0.6673, 0.7085, 0.7431, 0.7718, 0.7957, 0.8157, 0.8325, 0.8469, 0.8592, 0.8697, 0.8789,
    0.3602, 0.3804, 0.5343, 0.5877, 0.6303, 0.6757, 0.7170, 0.7524, 0.7818, 0.8062, 0.8265, 0.8433, 0.8575, 0.8694, 0.8795, 0.8881,
    0.4446, 0.4599, 0.5615, 0.6125, 0.6513, 0.6932, 0.7325, 0.7669, 0.7959, 0.8199, 0.8397, 0.8561, 0.8696, 0.8808, 0.8901, 0.8979,
    0.5379, 0.5494, 0.6127, 0.6506, 0.6853, 0.7219, 0.7569, 0.7883, 0.8151, 0.8375, 0.8559, 0.8709, 0.8832, 0.8932, 0.9013, 0.9080,
    0.6401, 0.6484, 0.6812, 0.7068, 0.7343, 0.7638, 0.7923, 0.8183, 0.8409, 0.8599, 0.8755, 0.8881, 0.8983, 0.9065, 0.9130, 0.9182,
    0.7512, 0.7567, 0.7683, 0.7832, 0.8009, 0.8211, 0.8408, 0.8588, 0.8747, 0.8881, 0.8991, 0.9080, 0.9150, 0.9205, 0.9248, 0.9280,
    0.8711, 0.8739, 0.8761, 0.8802, 0.8884, 0.8964, 0.9045, 0.9120, 0.9184, 0.9236, 0.9278, 0.9311, 0.9336, 0.9354, 0.9368, 0.9378,
    1.0000, 1.0000, 0.9994, 0.9973, 0.9943, 0.9902, 0.9854, 0.9801, 0.9748, 0.9699, 0.9655, 0.9618, 0.9588, 0.9565, 0.9548, 0.9537);
const float MX_DFG_W1[256] = float[](
    0.9913, 0.9435, 0.9355, 0.8891, 0.8320, 0.7714, 0.7111, 0.6536, 0.6002, 0.5517, 0.5083, 0.4701, 0.4367, 0.4077, 0.3828, 0.3614,
    0.9665, 0.8848, 0.9073, 0.8780, 0.8267, 0.7681, 0.7084, 0.6508, 0.5971, 0.5483, 0.5045, 0.4658, 0.4318, 0.4024, 0.3771, 0.3553,
    0.7713, 0.9615, 0.8646, 0.8456, 0.8085, 0.7570, 0.7000, 0.6429, 0.5886, 0.5387, 0.4935, 0.4534, 0.4181, 0.3874, 0.3606, 0.3375,
    0.6387, 0.9896, 0.9049, 0.8326, 0.7908, 0.7434, 0.6890, 0.6325, 0.5776, 0.5263, 0.4797, 0.4379, 0.4010, 0.3686, 0.3403, 0.3156,
    0.5802, 0.9922, 0.9514, 0.8592, 0.7893, 0.7340, 0.6785, 0.6214, 0.5654, 0.5126, 0.4641, 0.4205, 0.3818, 0.3477, 0.3178, 0.2917,
    0.5514, 0.9870, 0.9726, 0.8977, 0.8084, 0.7354, 0.6720, 0.6115, 0.5533, 0.4984, 0.4479, 0.4024, 0.3618, 0.3261, 0.2947, 0.2672,
    0.5352, 0.9743, 0.9801, 0.9244, 0.8358, 0.7479, 0.6721, 0.6045, 0.5421, 0.4844, 0.4315, 0.3840, 0.3417, 0.3044, 0.2717, 0.2430,
    0.5252, 0.9529, 0.9810, 0.9360, 0.8568, 0.7644, 0.6776, 0.6009, 0.5326, 0.4710, 0.4155, 0.3658, 0.3218, 0.2831, 0.2493, 0.2198,
    0.5185, 0.9210, 0.9772, 0.9353, 0.8641, 0.7750, 0.6832, 0.5989, 0.5242, 0.4582, 0.3997, 0.3479, 0.3023, 0.2625, 0.2279, 0.1979,
    0.5136, 0.8767, 0.9677, 0.9224, 0.8540, 0.7716, 0.6817, 0.5943, 0.5151, 0.4451, 0.3837, 0.3300, 0.2832, 0.2425, 0.2074, 0.1773,
    0.5099, 0.8183, 0.9414, 0.8914, 0.8215, 0.7469, 0.6650, 0.5811, 0.5015, 0.4299, 0.3668, 0.3118, 0.2641, 0.2231, 0.1880, 0.1581,
    0.5067, 0.7437, 0.8876, 0.8225, 0.7542, 0.6915, 0.6242, 0.5516, 0.4783, 0.4093, 0.3470, 0.2922, 0.2447, 0.2040, 0.1694, 0.1402,
    0.5038, 0.6491, 0.7499, 0.6788, 0.6286, 0.5915, 0.5488, 0.4971, 0.4387, 0.3788, 0.3217, 0.2698, 0.2242, 0.1849, 0.1515, 0.1236,
    0.5007, 0.5258, 0.4265, 0.4195, 0.4215, 0.4334, 0.4285, 0.4082, 0.3747, 0.3325, 0.2870, 0.2425, 0.2015, 0.1653, 0.1344, 0.1085,
    0.5000, 0.3488, 0.1168, 0.1262, 0.1927, 0.2334, 0.2647, 0.2803, 0.2794, 0.2643, 0.2391, 0.2085, 0.1768, 0.1467, 0.1198, 0.0968,
    0.5000, 0.0063, 0.0067, 0.0085, 0.0244, 0.0535, 0.0915, 0.1315, 0.1669, 0.1917, 0.2019, 0.1978, 0.1828, 0.1613, 0.1375, 0.1142);
const float MX_DFG_W2[256] = float[](
    0.0029, 0.0133, 0.0530, 0.1057, 0.1650, 0.2264, 0.2869, 0.3444, 0.3976, 0.4457, 0.4885, 0.5262, 0.5589, 0.5870, 0.6111, 0.6314,
    0.0334, 0.0073, 0.0453, 0.0992, 0.1596, 0.2219, 0.2829, 0.3404, 0.3935, 0.4413, 0.4836, 0.5204, 0.5520, 0.5790, 0.6018, 0.6207,
    0.2287, 0.0030, 0.0274, 0.0787, 0.1411, 0.2062, 0.2692, 0.3281, 0.3814, 0.4286, 0.4694, 0.5041, 0.5330, 0.5567, 0.5758, 0.5906,
    0.3612, 0.0032, 0.0172, 0.0584, 0.1182, 0.1847, 0.2502, 0.3110, 0.3651, 0.4119, 0.4514, 0.4836, 0.5093, 0.5292, 0.5440, 0.5541,
    0.4198, 0.0057, 0.0132, 0.0457, 0.0985, 0.1630, 0.2294, 0.2918, 0.3470, 0.3938, 0.4320, 0.4620, 0.4845, 0.5004, 0.5104, 0.5154,
    0.4486, 0.0125, 0.0120, 0.0401, 0.0864, 0.1460, 0.2109, 0.2735, 0.3293, 0.3759, 0.4129, 0.4406, 0.4598, 0.4715, 0.4769, 0.4770,
    0.4648, 0.0255, 0.0127, 0.0395, 0.0822, 0.1369, 0.1982, 0.2591, 0.3142, 0.3600, 0.3955, 0.4207, 0.4365, 0.4441, 0.4448, 0.4400,
    0.4748, 0.0470, 0.0153, 0.0434, 0.0854, 0.1368, 0.1938, 0.2514, 0.3040, 0.3479, 0.3811, 0.4034, 0.4155, 0.4188, 0.4149, 0.4053,
    0.4815, 0.0790, 0.0207, 0.0525, 0.0970, 0.1466, 0.1996, 0.2526, 0.3011, 0.3413, 0.3710, 0.3895, 0.3974, 0.3962, 0.3876, 0.3733,
    0.4864, 0.1233, 0.0310, 0.0701, 0.1197, 0.1688, 0.2177, 0.2649, 0.3074, 0.3421, 0.3666, 0.3801, 0.3830, 0.3767, 0.3631, 0.3442,
    0.4901, 0.1817, 0.0582, 0.1037, 0.1603, 0.2084, 0.2517, 0.2912, 0.3255, 0.3522, 0.3694, 0.3761, 0.3727, 0.3606, 0.3417, 0.3181,
    0.4933, 0.2563, 0.1122, 0.1743, 0.2327, 0.2746, 0.3080, 0.3360, 0.3585, 0.3740, 0.3810, 0.3786, 0.3672, 0.3481, 0.3233, 0.2948,
    0.4962, 0.3509, 0.2500, 0.3189, 0.3616, 0.3824, 0.3960, 0.4056, 0.4110, 0.4108, 0.4038, 0.3892, 0.3673, 0.3396, 0.3078, 0.2742,
    0.4993, 0.4742, 0.5735, 0.5787, 0.5709, 0.5458, 0.5261, 0.5081, 0.4890, 0.4670, 0.4407, 0.4095, 0.3739, 0.3352, 0.2951, 0.2557,
    0.5000, 0.6512, 0.8832, 0.8726, 0.8011, 0.7496, 0.6973, 0.6475, 0.5980, 0.5473, 0.4949, 0.4410, 0.3866, 0.3334, 0.2832, 0.2372,
    0.5000, 0.9937, 0.9933, 0.9913, 0.9709, 0.9323, 0.8760, 0.8056, 0.7230, 0.6328, 0.5411, 0.4529, 0.3724, 0.3017, 0.2419, 0.1926);

// (c1, c2, w1, w2) at NdotV and alpha, interpolated bilinearly.
vec4 mx_environment_dfg_rule(float NdotV, float alpha)
{
    vec2 p = clamp(vec2(sqrt(NdotV), sqrt(alpha)), 0.0, 1.0) * 15.0;
    ivec2 i = min(ivec2(p), ivec2(14));
    vec2 f = p - vec2(i);
    int k = i.x * 16 + i.y;
    vec4 low = mix(vec4(MX_DFG_C1[k], MX_DFG_C2[k], MX_DFG_W1[k], MX_DFG_W2[k]), vec4(MX_DFG_C1[k + 1], MX_DFG_C2[k + 1], MX_DFG_W1[k + 1], MX_DFG_W2[k + 1]), f.y);
    vec4 high = mix(vec4(MX_DFG_C1[k + 16], MX_DFG_C2[k + 16], MX_DFG_W1[k + 16], MX_DFG_W2[k + 16]), vec4(MX_DFG_C1[k + 17], MX_DFG_C2[k + 17], MX_DFG_W1[k + 17], MX_DFG_W2[k + 17]), f.y);
    return mix(low, high, f.x);
}

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
    vec3 F1 = mx_fresnel_eval_film(rule.x, fd, true);
    vec3 F2 = mx_fresnel_eval_film(rule.y, fd, true);
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
    if (fd.refraction)
        return vec3(1.0) - reflected / E;
    return reflected * (vec3(1.0) + mx_fresnel_eval_film(NdotV, fd, true) * ((1.0 - E) / E));
}

// The direction the split sum reads the lobe along: the mirror direction, or through the sphere.
vec3 mx_prefiltered_direction(vec3 V, vec3 N, FresnelData fd)
{
    if (fd.refraction)
        return mx_refraction_solid_sphere(-V, N, fd.ior.x);
    return reflect(-V, N);
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
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
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

// Mip level for a sample of density `pdf` along map direction `mapDir` (GPU Gems 3, 20.4, eq. 13),
// with the lat-long map's stretching towards its poles, biased 1.5 levels sharper.
float mx_envmap_lod(vec3 mapDir, float pdf, int sampleCount)
{
    float coarsest = float(u_envRadianceMips - 1) - 1.5;
    float stretch = sqrt(1.0 - mapDir.y * mapDir.y);
    return max(coarsest - 0.5 * log2(float(sampleCount) * pdf * stretch), 0.0);
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
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
        vec3 Li = vec3(0.0);
        if (fetch)
        {
            vec3 Lm = toMap * Lt;
            Li = mx_envmap_lookup(u_envRadiance, Lm, mx_envmap_lod(Lm, mx_ggx_reflection_pdf(H, Vt, alpha), sampleCount));
        }
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
#ifndef MX_ENV_PREFILTER
    if (mx_fresnel_has_thinfilm(fd))
        return mx_environment_samples(N, V, X, alpha, fd, fetch, true, albedo);
#endif
    return mx_environment_samples(N, V, X, alpha, fd, fetch, false, albedo);
}

// The environment seen through the lobe (see mx_environment_samples).
vec3 mx_environment_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, out vec3 albedo)
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

struct SpecularLobe
{
    float weight;            // 0 where the lobe scatters nothing
    vec3 tint;
    vec3 surfaceN;           // the usable shading normal, on either side
    vec3 N;                  // the normal facing V
    vec3 V;                  // towards the viewer, mirrored about the normal for retro-reflection
    vec3 X;                  // tangent
    vec2 alpha;              // clamped roughness pair
    FresnelData fd;
    int scatterMode;         // 0 R, 1 T, 2 RT
    int distribution;
    mat3 frame;              // (X, Y, N) about N
    vec3 Vt;                 // V in that frame
    vec3 albedo;             // what the lobe reflects of light arriving along V (the caller's table value, compensated)
    vec3 environment;        // the environment the lobe reflects towards V
    vec3 environmentAlbedo;  // the fraction of the environment it reflects, from the same samples
};

// The fraction of light arriving with `cosine` that the lobe reflects, multiple scattering
// included, from its single-scattering albedo there (the caller's table value).
vec3 mx_specular_albedo(float cosine, vec2 alpha, FresnelData fd, vec3 singleScatteringAlbedo)
{
    float c = clamp(cosine, MX_EPS, 1.0);
    return singleScatteringAlbedo * mx_ggx_energy_compensation(c, mx_ggx_isotropic_alpha(alpha), mx_fresnel_eval_film(c, fd, true));
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
    lobe.fd = fd;
    lobe.scatterMode = scatterMode;
    lobe.distribution = distribution;
    lobe.frame = mx_tangent_frame(lobe.N, X);
    lobe.Vt = lobe.V * lobe.frame;
    lobe.Vt.z = max(lobe.Vt.z, MX_EPS);
    lobe.albedo = vec3(0.0);
    lobe.environment = vec3(0.0);
    lobe.environmentAlbedo = vec3(0.0);
    if (lobe.weight > 0.0)
        lobe.environment = mx_environment_reflected(lobe.N, lobe.V, X, lobe.alpha, fd, scatterMode != 1,
                                                    lobe.environmentAlbedo);
    return lobe;
}

// The lobe towards closureData.L (REFLECTION), multiple scattering included.
vec3 mx_specular_reflection(ClosureData closureData, SpecularLobe lobe)
{
    vec3 Lt = closureData.L * lobe.frame;
    if (Lt.z <= 0.0)
        return vec3(0.0);
    vec3 H = normalize(Lt + lobe.Vt);
    vec3 F = mx_fresnel_eval_film(clamp(dot(lobe.Vt, H), MX_EPS, 1.0), lobe.fd, true);
    float DG = mx_ggx_D(H, lobe.alpha) * mx_ggx_G2(lobe.Vt, Lt, lobe.alpha);
    float NdotV = clamp(dot(lobe.N, lobe.V), MX_EPS, 1.0);
    return F * mx_ggx_energy_compensation(NdotV, mx_ggx_isotropic_alpha(lobe.alpha), F) *
           (DG * closureData.occlusion / (4.0 * lobe.Vt.z));
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

// [F0 of eta = t / 4, t = slab / 7][alpha = (row / 7)^2][mu = (column / 15)^2]
const float MX_ALBEDO_DIELECTRIC_ENTERING[1024] = float[1024](
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.987971, 0.974103, 0.901442, 0.793312, 0.665493, 0.533586, 0.410155, 0.303353,
    0.216956, 0.151256, 0.104237, 0.072693, 0.053087, 0.042121, 0.037039, 0.035714,
    0.723329, 0.705516, 0.664295, 0.644464, 0.593919, 0.501624, 0.396107, 0.297380,
    0.214704, 0.150631, 0.104430, 0.072959, 0.053292, 0.042242, 0.037088, 0.035715,
    0.445566, 0.441128, 0.424328, 0.398596, 0.367414, 0.331466, 0.288093, 0.237582,
    0.185422, 0.138216, 0.100080, 0.072179, 0.053654, 0.042675, 0.037232, 0.035381,
    0.273083, 0.270569, 0.260623, 0.245265, 0.225966, 0.203427, 0.178975, 0.153688,
    0.128359, 0.104059, 0.082207, 0.064136, 0.050580, 0.041547, 0.036447, 0.034458,
    0.178622, 0.176647, 0.169002, 0.158749, 0.145682, 0.131035, 0.115707, 0.100371,
    0.085724, 0.072246, 0.060337, 0.050278, 0.042299, 0.036507, 0.032822, 0.031045,
    0.128268, 0.126340, 0.119923, 0.111339, 0.101353, 0.090643, 0.079867, 0.069467,
    0.059833, 0.051222, 0.043781, 0.037585, 0.032644, 0.028923, 0.026352, 0.024838,
    0.101103, 0.098923, 0.092681, 0.084762, 0.076081, 0.067241, 0.058686, 0.050746,
    0.043609, 0.037376, 0.032068, 0.027658, 0.024084, 0.021267, 0.019119, 0.017552,
    0.085988, 0.083345, 0.076819, 0.068942, 0.060694, 0.052670, 0.045227, 0.038542,
    0.032696, 0.027692, 0.023484, 0.019994, 0.017126, 0.014792, 0.012897, 0.011368,
    0.988196, 0.975084, 0.905423, 0.802346, 0.681298, 0.557034, 0.440940, 0.340059,
    0.257479, 0.193377, 0.146129, 0.113211, 0.091816, 0.079243, 0.073106, 0.071429,
    0.735710, 0.717204, 0.674884, 0.656896, 0.611370, 0.525759, 0.427043, 0.333972,
    0.255028, 0.192570, 0.146228, 0.113436, 0.092016, 0.079373, 0.073164, 0.071430,
    0.471974, 0.467346, 0.449956, 0.423825, 0.393261, 0.359491, 0.319584, 0.272870,
    0.223793, 0.178314, 0.140461, 0.111747, 0.091862, 0.079513, 0.073080, 0.070727,
    0.306989, 0.304357, 0.293985, 0.278086, 0.258497, 0.235948, 0.211917, 0.187475,
    0.163207, 0.139841, 0.118476, 0.100343, 0.086293, 0.076588, 0.070915, 0.068711,
    0.215446, 0.213282, 0.204938, 0.194008, 0.180151, 0.164737, 0.148757, 0.132873,
    0.117811, 0.104018, 0.091862, 0.081553, 0.073313, 0.067287, 0.063449, 0.061703,
    0.165891, 0.163645, 0.156266, 0.146534, 0.135299, 0.123294, 0.111253, 0.099624,
    0.088830, 0.079154, 0.070755, 0.063723, 0.058086, 0.053823, 0.050886, 0.049202,
    0.138749, 0.136083, 0.128515, 0.118960, 0.108502, 0.097845, 0.087479, 0.077786,
    0.068976, 0.061173, 0.054410, 0.048672, 0.043907, 0.040043, 0.036995, 0.034682,
    0.123433, 0.120102, 0.111842, 0.101818, 0.091242, 0.080849, 0.071084, 0.062170,
    0.054225, 0.047269, 0.041266, 0.036137, 0.031785, 0.028117, 0.025024, 0.022427,
    0.988099, 0.974699, 0.904373, 0.801465, 0.682403, 0.562219, 0.451806, 0.357255,
    0.280676, 0.221541, 0.177899, 0.147248, 0.127033, 0.114909, 0.108844, 0.107143,
    0.738730, 0.719782, 0.676411, 0.658188, 0.614117, 0.532033, 0.438527, 0.351448,
    0.278302, 0.220709, 0.177954, 0.147433, 0.127208, 0.115029, 0.108900, 0.107144,
    0.484599, 0.479780, 0.461771, 0.435061, 0.404601, 0.372188, 0.335078, 0.292287,
    0.247575, 0.206168, 0.171576, 0.145108, 0.126524, 0.114764, 0.108496, 0.106062,
    0.328263, 0.325529, 0.314794, 0.298465, 0.278726, 0.256385, 0.233125, 0.210103,
    0.187829, 0.166770, 0.147661, 0.131439, 0.118795, 0.109989, 0.104811, 0.102899,
    0.242271, 0.239967, 0.231112, 0.219753, 0.205458, 0.189728, 0.173658, 0.157910,
    0.143249, 0.130091, 0.118751, 0.109323, 0.101940, 0.096680, 0.093469, 0.092236,
    0.195847, 0.193359, 0.185264, 0.174722, 0.162660, 0.149859, 0.137114, 0.124874,
    0.113580, 0.103527, 0.094865, 0.087679, 0.081986, 0.077756, 0.074925, 0.073414,
    0.170393, 0.167340, 0.158732, 0.147923, 0.136138, 0.124155, 0.112498, 0.101579,
    0.091618, 0.082750, 0.075005, 0.068371, 0.062796, 0.058212, 0.054533, 0.051678,
    0.155976, 0.152079, 0.142408, 0.130650, 0.118206, 0.105920, 0.094301, 0.083609,
    0.073980, 0.065447, 0.057977, 0.051493, 0.045892, 0.041080, 0.036940, 0.033389,
    0.987873, 0.973769, 0.901354, 0.796803, 0.678045, 0.560751, 0.455470, 0.367351,
    0.297437, 0.244342, 0.205605, 0.178543, 0.160676, 0.149883, 0.144414, 0.142857,
    0.738223, 0.718925, 0.674515, 0.655300, 0.611428, 0.531799, 0.442966, 0.361956,
    0.295232, 0.243542, 0.205640, 0.178693, 0.160821, 0.149984, 0.144463, 0.142858,
    0.492101, 0.487092, 0.468463, 0.441125, 0.410601, 0.379265, 0.344707, 0.305843,
    0.265877, 0.229295, 0.198976, 0.175863, 0.159618, 0.149274, 0.143697, 0.141391,
    0.344801, 0.341970, 0.330899, 0.314186, 0.294352, 0.272299, 0.249927, 0.228508,
    0.208527, 0.190230, 0.173988, 0.160396, 0.149897, 0.142641, 0.138432, 0.137053,
    0.265279, 0.262853, 0.253558, 0.241864, 0.227259, 0.211376, 0.195415, 0.180044,
    0.166070, 0.153881, 0.143742, 0.135618, 0.129528, 0.125447, 0.123203, 0.122708,
    0.222823, 0.220119, 0.211401, 0.200178, 0.187448, 0.174035, 0.160794, 0.148170,
    0.136621, 0.126446, 0.117782, 0.110705, 0.105213, 0.101251, 0.098731, 0.097551,
    0.199669, 0.196265, 0.186727, 0.174813, 0.161871, 0.148750, 0.135999, 0.124055,
    0.113144, 0.103404, 0.094862, 0.087503, 0.081275, 0.076108, 0.071913, 0.068607,
    0.186565, 0.182149, 0.171192, 0.157861, 0.143727, 0.129732, 0.116443, 0.104147,
    0.092998, 0.083036, 0.074231, 0.066506, 0.059754, 0.053879, 0.048757, 0.044303,
    0.987566, 0.972502, 0.897160, 0.790003, 0.670793, 0.555973, 0.455733, 0.374203,
    0.311291, 0.264704, 0.231419, 0.208519, 0.193530, 0.184493, 0.179893, 0.178571,
    0.735832, 0.716223, 0.670762, 0.650162, 0.605921, 0.528352, 0.444082, 0.369276,
    0.309295, 0.263960, 0.231444, 0.208636, 0.193644, 0.184572, 0.179932, 0.178573,
    0.497074, 0.491878, 0.472631, 0.444653, 0.414013, 0.383666, 0.351603, 0.316713,
    0.281685, 0.250257, 0.224643, 0.205369, 0.191933, 0.183400, 0.178784, 0.176716,
    0.359083, 0.356161, 0.344772, 0.327704, 0.307814, 0.286104, 0.264688, 0.244969,
    0.227421, 0.212084, 0.198974, 0.188328, 0.180309, 0.174912, 0.171909, 0.171190,
    0.286489, 0.283951, 0.274252, 0.262268, 0.247419, 0.231465, 0.215711, 0.200830,
    0.187672, 0.176603, 0.167834, 0.161202, 0.156605, 0.153896, 0.152787, 0.153146,
    0.248393, 0.245488, 0.236192, 0.224348, 0.211026, 0.197090, 0.183450, 0.170549,
    0.158855, 0.148674, 0.140128, 0.133280, 0.128107, 0.124526, 0.122416, 0.121648,
    0.227823, 0.224086, 0.213673, 0.200722, 0.186705, 0.172534, 0.158782, 0.145906,
    0.134138, 0.123616, 0.114362, 0.106358, 0.099550, 0.093864, 0.089210, 0.085501,
    0.216224, 0.211313, 0.199130, 0.184301, 0.168561, 0.152945, 0.138072, 0.124254,
    0.111661, 0.100340, 0.090262, 0.081350, 0.073494, 0.066595, 0.060522, 0.055191,
    0.987195, 0.970969, 0.892080, 0.781704, 0.661696, 0.549307, 0.454255, 0.379532,
    0.323848, 0.283990, 0.256384, 0.237880, 0.226000, 0.218917, 0.215323, 0.214286,
    0.732228, 0.712325, 0.665781, 0.643556, 0.598679, 0.523101, 0.443504, 0.375098,
    0.322074, 0.283312, 0.256404, 0.237967, 0.226081, 0.218973, 0.215350, 0.214286,
    0.500645, 0.495262, 0.475400, 0.446789, 0.416035, 0.386685, 0.357156, 0.326328,
    0.296369, 0.270254, 0.249529, 0.234294, 0.223871, 0.217332, 0.213810, 0.212039,
    0.372225, 0.369214, 0.357522, 0.340124, 0.320213, 0.298891, 0.278489, 0.260536,
    0.245497, 0.233215, 0.223350, 0.215784, 0.210390, 0.206993, 0.205311, 0.205317,
    0.306828, 0.304183, 0.294100, 0.281856, 0.266801, 0.250823, 0.235328, 0.220996,
    0.208719, 0.198835, 0.191511, 0.186454, 0.183436, 0.182189, 0.182295, 0.183566,
    0.273293, 0.270195, 0.260343, 0.247911, 0.234035, 0.219621, 0.205631, 0.192503,
    0.180717, 0.170582, 0.162208, 0.155642, 0.150840, 0.147692, 0.146041, 0.145723,
    0.255445, 0.251385, 0.240121, 0.226169, 0.211115, 0.195938, 0.181229, 0.167467,
    0.154885, 0.143620, 0.133693, 0.125080, 0.117726, 0.111552, 0.106465, 0.102377,
    0.245442, 0.240048, 0.226667, 0.210377, 0.193072, 0.175877, 0.159461, 0.144159,
    0.130158, 0.117509, 0.106188, 0.096113, 0.087173, 0.079268, 0.072261, 0.066065,
    0.986764, 0.969194, 0.886224, 0.772193, 0.651279, 0.541501, 0.451933, 0.384281,
    0.335996, 0.302960, 0.281088, 0.267031, 0.258322, 0.253261, 0.250728, 0.250000,
    0.727739, 0.707545, 0.659875, 0.635861, 0.590257, 0.516790, 0.442115, 0.380348,
    0.334446, 0.302348, 0.281103, 0.267088, 0.258371, 0.253293, 0.250745, 0.250000,
    0.503410, 0.497840, 0.477370, 0.448141, 0.417309, 0.389022, 0.362127, 0.335477,
    0.310686, 0.289957, 0.274171, 0.263022, 0.255667, 0.251183, 0.248809, 0.247361,
    0.384831, 0.381735, 0.369752, 0.352049, 0.332151, 0.311262, 0.291926, 0.275790,
    0.263305, 0.254116, 0.247529, 0.243077, 0.240347, 0.238997, 0.238681, 0.239440,
    0.326808, 0.324058, 0.313605, 0.301118, 0.285882, 0.269908, 0.254703, 0.240950,
    0.229580, 0.220907, 0.215049, 0.211589, 0.210177, 0.210421, 0.211771, 0.213978,
    0.297933, 0.294644, 0.284249, 0.271245, 0.256835, 0.241964, 0.227646, 0.214312,
    0.202453, 0.192382, 0.184195, 0.177927, 0.173513, 0.170815, 0.169640, 0.169788,
    0.282864, 0.278485, 0.266382, 0.251444, 0.235373, 0.219206, 0.203558, 0.188926,
    0.175544, 0.163553, 0.152965, 0.143754, 0.135863, 0.129212, 0.123702, 0.119243,
    0.274494, 0.268620, 0.254055, 0.236320, 0.217466, 0.198708, 0.180763, 0.163993,
    0.148596, 0.134630, 0.122074, 0.110846, 0.100830, 0.091926, 0.083989, 0.076933);

// the same for 1 / eta: from the dense side
const float MX_ALBEDO_DIELECTRIC_LEAVING[1024] = float[1024](
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.255511, 0.046752, 0.035714,
    0.979119, 0.948151, 0.888831, 0.908699, 0.953415, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.997794, 0.994089, 0.329966, 0.049314, 0.035720,
    0.951327, 0.943865, 0.917425, 0.885676, 0.866380, 0.870482, 0.891655, 0.916948,
    0.937826, 0.951644, 0.958277, 0.954666, 0.912903, 0.444561, 0.074119, 0.035724,
    0.895304, 0.891290, 0.876298, 0.854685, 0.833292, 0.814806, 0.803686, 0.802159,
    0.808727, 0.817671, 0.820798, 0.803229, 0.716827, 0.427786, 0.127498, 0.041602,
    0.819737, 0.815375, 0.798924, 0.779917, 0.756490, 0.732394, 0.709050, 0.687577,
    0.668316, 0.649062, 0.624391, 0.581742, 0.496383, 0.339233, 0.154016, 0.040922,
    0.733121, 0.726896, 0.707170, 0.681546, 0.652100, 0.620003, 0.586555, 0.552285,
    0.517117, 0.479868, 0.437628, 0.386377, 0.319956, 0.232770, 0.131188, 0.036816,
    0.646991, 0.638214, 0.612971, 0.580361, 0.543129, 0.503385, 0.462098, 0.420091,
    0.377976, 0.336190, 0.292061, 0.246507, 0.198350, 0.146637, 0.090826, 0.028955,
    0.570367, 0.558650, 0.528053, 0.489728, 0.447192, 0.401997, 0.356746, 0.311944,
    0.269245, 0.228949, 0.190893, 0.154909, 0.121066, 0.088574, 0.056825, 0.019973,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.115988, 0.071429,
    0.982952, 0.952009, 0.891377, 0.909838, 0.955408, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.999727, 0.998348, 0.992860, 0.129355, 0.071445,
    0.968723, 0.960608, 0.932203, 0.897583, 0.875932, 0.878063, 0.898231, 0.922858,
    0.943816, 0.958500, 0.967522, 0.970736, 0.965236, 0.905528, 0.226586, 0.072555,
    0.933948, 0.929392, 0.912423, 0.887703, 0.863672, 0.842264, 0.829253, 0.826542,
    0.833828, 0.846005, 0.857377, 0.861405, 0.842441, 0.730202, 0.326227, 0.095993,
    0.885406, 0.880495, 0.861967, 0.840731, 0.815036, 0.788581, 0.764037, 0.742872,
    0.726043, 0.712671, 0.700263, 0.681926, 0.641439, 0.539648, 0.327934, 0.118710,
    0.826867, 0.819947, 0.797855, 0.769751, 0.737935, 0.703955, 0.669759, 0.635721,
    0.602765, 0.569865, 0.535367, 0.496637, 0.444969, 0.370417, 0.259885, 0.123405,
    0.763930, 0.754029, 0.725683, 0.689236, 0.648368, 0.605011, 0.560745, 0.516480,
    0.472665, 0.429530, 0.386865, 0.342000, 0.293649, 0.240461, 0.178027, 0.103880,
    0.702902, 0.689332, 0.654059, 0.609020, 0.559213, 0.507790, 0.457411, 0.405979,
    0.357283, 0.311763, 0.268163, 0.227118, 0.188074, 0.150531, 0.112791, 0.074122,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.320193, 0.107143,
    0.984959, 0.953510, 0.892034, 0.910636, 0.955408, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.999727, 0.999843, 0.997728, 0.437082, 0.107174,
    0.977319, 0.968788, 0.939301, 0.903559, 0.880449, 0.881726, 0.901543, 0.925622,
    0.946316, 0.961276, 0.970844, 0.975547, 0.975278, 0.958400, 0.536781, 0.116376,
    0.953132, 0.948305, 0.929939, 0.904018, 0.878056, 0.855204, 0.840974, 0.837312,
    0.844530, 0.857548, 0.871284, 0.880955, 0.878283, 0.831376, 0.531530, 0.155625,
    0.918446, 0.913191, 0.893227, 0.870822, 0.843703, 0.815785, 0.790300, 0.768505,
    0.752165, 0.740844, 0.733310, 0.723808, 0.702710, 0.640384, 0.463574, 0.197910,
    0.875652, 0.868245, 0.844796, 0.815153, 0.781814, 0.746560, 0.711682, 0.677448,
    0.645035, 0.614249, 0.583974, 0.551689, 0.512273, 0.452637, 0.353719, 0.206912,
    0.827936, 0.817342, 0.786953, 0.748454, 0.705423, 0.660416, 0.614693, 0.569608,
    0.525529, 0.482656, 0.439406, 0.396817, 0.351278, 0.301949, 0.242904, 0.174492,
    0.779161, 0.764712, 0.726699, 0.678552, 0.625411, 0.570751, 0.515252, 0.461161,
    0.411113, 0.362539, 0.316145, 0.273770, 0.232797, 0.193847, 0.155964, 0.121825,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.142857,
    0.986042, 0.954785, 0.892517, 0.911427, 0.955408, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.999727, 0.999843, 0.998621, 0.971573, 0.142908,
    0.982540, 0.973918, 0.943647, 0.907034, 0.883573, 0.884005, 0.903032, 0.927263,
    0.948153, 0.962942, 0.972462, 0.978123, 0.979488, 0.972534, 0.814542, 0.154727,
    0.964867, 0.959972, 0.940687, 0.913740, 0.886847, 0.862968, 0.847794, 0.843794,
    0.850620, 0.863972, 0.878738, 0.891004, 0.895014, 0.873276, 0.684692, 0.208341,
    0.938896, 0.933386, 0.912619, 0.889268, 0.861057, 0.832313, 0.806271, 0.784150,
    0.767648, 0.757308, 0.751775, 0.747034, 0.735663, 0.697245, 0.562386, 0.269381,
    0.906623, 0.898831, 0.874159, 0.843531, 0.809211, 0.773212, 0.737616, 0.703318,
    0.671226, 0.641655, 0.613957, 0.585903, 0.553976, 0.506141, 0.424563, 0.280732,
    0.869475, 0.858260, 0.826557, 0.786472, 0.741965, 0.695818, 0.649253, 0.603589,
    0.559306, 0.516760, 0.474627, 0.433565, 0.391433, 0.345356, 0.293043, 0.229550,
    0.830276, 0.814780, 0.774793, 0.724522, 0.669086, 0.612114, 0.554627, 0.498820,
    0.446688, 0.396631, 0.349753, 0.306074, 0.265538, 0.226597, 0.190720, 0.159744,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.178571,
    0.987027, 0.955800, 0.892925, 0.912104, 0.955408, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.999727, 0.999843, 0.999643, 0.992783, 0.178647,
    0.985907, 0.977170, 0.946651, 0.909243, 0.885010, 0.885458, 0.904221, 0.928583,
    0.949172, 0.964032, 0.973960, 0.979454, 0.981955, 0.978989, 0.914583, 0.195842,
    0.972757, 0.967543, 0.947935, 0.920142, 0.892785, 0.868201, 0.852470, 0.848177,
    0.854821, 0.868113, 0.883476, 0.897083, 0.904419, 0.895087, 0.779190, 0.264241,
    0.952868, 0.947146, 0.925696, 0.901691, 0.872827, 0.843327, 0.816801, 0.794563,
    0.778143, 0.768083, 0.763796, 0.761682, 0.756421, 0.732763, 0.633956, 0.339548,
    0.927576, 0.919461, 0.894326, 0.862784, 0.827709, 0.791039, 0.755080, 0.720804,
    0.689231, 0.660815, 0.634767, 0.609983, 0.582060, 0.544240, 0.477377, 0.345553,
    0.898029, 0.886457, 0.853876, 0.812812, 0.767141, 0.720011, 0.672743, 0.626799,
    0.582454, 0.540096, 0.499805, 0.461056, 0.420991, 0.379380, 0.332994, 0.275245,
    0.866180, 0.850193, 0.808853, 0.756715, 0.699470, 0.640617, 0.582384, 0.526309,
    0.473384, 0.422078, 0.375028, 0.331404, 0.289754, 0.252508, 0.218504, 0.188583,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.214286,
    0.988063, 0.956185, 0.893308, 0.912104, 0.955408, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.999727, 0.999843, 0.999916, 0.996628, 0.214392,
    0.988662, 0.979741, 0.948909, 0.911287, 0.886684, 0.886509, 0.905497, 0.929239,
    0.949681, 0.964578, 0.974554, 0.980549, 0.983720, 0.982832, 0.950390, 0.238106,
    0.978617, 0.973374, 0.953395, 0.925049, 0.896961, 0.872124, 0.855797, 0.851189,
    0.857691, 0.871052, 0.886826, 0.900876, 0.910473, 0.908329, 0.836021, 0.318715,
    0.963218, 0.957400, 0.935478, 0.911041, 0.881538, 0.851561, 0.824544, 0.801868,
    0.785280, 0.775809, 0.772218, 0.771872, 0.770507, 0.756861, 0.684995, 0.401614,
    0.943401, 0.935148, 0.909176, 0.877094, 0.841485, 0.804317, 0.768135, 0.733675,
    0.701971, 0.673939, 0.648994, 0.626328, 0.603410, 0.573431, 0.519244, 0.398000,
    0.920150, 0.908145, 0.874626, 0.832653, 0.786507, 0.738730, 0.691126, 0.644729,
    0.600395, 0.558244, 0.518453, 0.480408, 0.442862, 0.405532, 0.364132, 0.314774,
    0.894394, 0.877795, 0.835457, 0.782246, 0.723594, 0.663288, 0.603860, 0.546514,
    0.492535, 0.442156, 0.394574, 0.350739, 0.310081, 0.273411, 0.241013, 0.212025,
    0.993992, 0.999872, 0.999992, 0.999998, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.250000,
    0.988372, 0.956421, 0.893554, 0.912104, 0.955408, 0.979653, 0.990189, 0.994699,
    0.996937, 0.998095, 0.999504, 0.999727, 0.999843, 0.999916, 0.998217, 0.250145,
    0.990601, 0.981656, 0.950333, 0.912325, 0.887655, 0.887341, 0.905941, 0.929685,
    0.950244, 0.965120, 0.975013, 0.981331, 0.984555, 0.985310, 0.966433, 0.279864,
    0.982970, 0.977621, 0.957188, 0.928401, 0.900205, 0.874758, 0.858293, 0.853373,
    0.859815, 0.873137, 0.889211, 0.903897, 0.914669, 0.916963, 0.870402, 0.372611,
    0.970773, 0.964718, 0.942312, 0.917500, 0.887639, 0.857325, 0.830329, 0.807166,
    0.790818, 0.781259, 0.778331, 0.779451, 0.780622, 0.774245, 0.722724, 0.459622,
    0.954992, 0.946501, 0.920183, 0.887601, 0.851451, 0.813866, 0.777429, 0.742975,
    0.711522, 0.683854, 0.659905, 0.638899, 0.619158, 0.594713, 0.551423, 0.445165,
    0.936139, 0.923784, 0.889682, 0.847023, 0.800283, 0.752063, 0.704112, 0.657856,
    0.613867, 0.572415, 0.533030, 0.496071, 0.461278, 0.425914, 0.388681, 0.343620,
    0.915068, 0.898122, 0.854743, 0.800601, 0.741364, 0.680651, 0.620647, 0.562508,
    0.507757, 0.457397, 0.409480, 0.365696, 0.325847, 0.290266, 0.258870, 0.229881);

float mx_albedo_dielectric_entering(vec4 c, ivec2 i, int slab)
{
    return mix(mix(MX_ALBEDO_DIELECTRIC_ENTERING[slab * 128 + mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_DIELECTRIC_ENTERING[slab * 128 + mx_albedo_index(i + ivec2(1, 0), 16)], c.z),
               mix(MX_ALBEDO_DIELECTRIC_ENTERING[slab * 128 + mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_DIELECTRIC_ENTERING[slab * 128 + mx_albedo_index(i + ivec2(1, 1), 16)], c.z), c.w);
}

float mx_albedo_dielectric_leaving(vec4 c, ivec2 i, int slab)
{
    return mix(mix(MX_ALBEDO_DIELECTRIC_LEAVING[slab * 128 + mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_DIELECTRIC_LEAVING[slab * 128 + mx_albedo_index(i + ivec2(1, 0), 16)], c.z),
               mix(MX_ALBEDO_DIELECTRIC_LEAVING[slab * 128 + mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_DIELECTRIC_LEAVING[slab * 128 + mx_albedo_index(i + ivec2(1, 1), 16)], c.z), c.w);
}

// Reflection albedo of a GGX dielectric interface at view cosine mu, isotropic alpha and relative
// index eta (transmitted side over incident side), eta clamped to [1/3, 3]. The table of the dense
// side is read only in shaders where some dielectric's index may be below 1 (shadergen/features.py).
float mx_dielectric_albedo(float mu, float alpha, float eta)
{
    bool leaving = eta < 1.0;
    float above = leaving ? 1.0 / max(eta, 1.0e-6) : eta;
    float r = (above - 1.0) / (above + 1.0);
    float t = clamp(4.0 * r * r, 0.0, 1.0) * 7.0;  // slabs evenly spaced in F0
    int slab = min(int(t), 6);
    vec4 c = mx_albedo_cell(sqrt(max(vec2(mu, alpha), 0.0)), vec2(16.0, 8.0));
    ivec2 i = ivec2(c.xy);
    if (leaving)
        return mix(mx_albedo_dielectric_leaving(c, i, slab), mx_albedo_dielectric_leaving(c, i, slab + 1), t - float(slab));
    return mix(mx_albedo_dielectric_entering(c, i, slab), mx_albedo_dielectric_entering(c, i, slab + 1), t - float(slab));
}

// Once per shading point (lib/mx_specular.glsl); the albedo towards V is needed under lights only.
void mx_dielectric_bsdf_prepare(ClosureData closureData, float weight, vec3 tint, float ior, vec2 roughness,
                                bool retroreflective, float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X,
                                int distribution, int scatter_mode, out SpecularLobe lobe)
{
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(ior), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0),
                                     0.0, thinfilm_thickness, thinfilm_ior);
    lobe = mx_specular_lobe_prepare(closureData, weight, tint, roughness, retroreflective, fd, N, X, distribution,
                                    scatter_mode);
    float NdotV = clamp(dot(lobe.N, lobe.V), MX_EPS, 1.0);
    float tableAlbedo = mx_dielectric_albedo(NdotV, mx_ggx_isotropic_alpha(lobe.alpha), fd.ior.x);
    lobe.albedo = mx_specular_albedo(NdotV, lobe.alpha, fd, vec3(tableAlbedo));
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
        bsdf.throughput = mx_specular_throughput(mx_specular_transmission_albedo(closureData, lobe), lobe.weight);
        if (lobe.scatterMode != 0)
            bsdf.response = mx_surface_transmission(mx_facing_normal(lobe.surfaceN, closureData.V), closureData.V, lobe.X,
                                                    lobe.alpha, lobe.distribution, lobe.fd, lobe.tint) * lobe.weight;
    }
    else  // REFLECTION
    {
        // the light crosses the interface on its way in too
        float NdotL = dot(lobe.N, closureData.L);
        float tableAlbedoL = mx_dielectric_albedo(NdotL, mx_ggx_isotropic_alpha(lobe.alpha), lobe.fd.ior.x);
        vec3 reflectedL = mx_specular_albedo(NdotL, lobe.alpha, lobe.fd, vec3(tableAlbedoL));
        bsdf.throughput = mx_specular_throughput(lobe.albedo, lobe.weight) * mx_specular_throughput(reflectedL, lobe.weight);
        bsdf.response = mx_specular_reflection(closureData, lobe) * lobe.tint * lobe.weight;
    }
}

// the model as published, at roughness = row / 15, mu = (column / 15)^2; 96^2 cosine-distributed directions each
const float MX_ALBEDO_SHEEN[256] = float[256](
    4.030692, 3.772839, 2.937267, 1.956994, 1.114014, 0.531712, 0.204997, 0.060256,
    0.012420, 0.001592, 0.000106, 0.000003, 0.000000, 0.000000, 0.000000, 0.000000,
    1.479285, 1.444526, 1.323638, 1.157729, 0.974239, 0.791344, 0.620047, 0.466943,
    0.335824, 0.228433, 0.144840, 0.083677, 0.042372, 0.017436, 0.004812, 0.000286,
    1.118386, 1.098133, 1.027224, 0.928473, 0.816701, 0.701559, 0.588835, 0.482107,
    0.383722, 0.295284, 0.217874, 0.152154, 0.098406, 0.056553, 0.026160, 0.006444,
    0.960071, 0.945024, 0.892234, 0.818366, 0.734102, 0.646281, 0.558893, 0.474330,
    0.394135, 0.319389, 0.250893, 0.189269, 0.135003, 0.088473, 0.049953, 0.019618,
    0.868044, 0.855692, 0.812326, 0.751541, 0.681975, 0.609092, 0.536002, 0.464499,
    0.395694, 0.330330, 0.268954, 0.211995, 0.159819, 0.112752, 0.071098, 0.035155,
    0.807028, 0.796325, 0.758747, 0.706050, 0.645662, 0.582237, 0.518370, 0.455511,
    0.394507, 0.335895, 0.280039, 0.227211, 0.177638, 0.131523, 0.089067, 0.050487,
    0.763297, 0.753709, 0.720049, 0.672852, 0.618748, 0.561861, 0.504452, 0.447748,
    0.392431, 0.338896, 0.287388, 0.238064, 0.191037, 0.146401, 0.104244, 0.064665,
    0.730282, 0.721498, 0.690668, 0.647455, 0.597928, 0.545833, 0.493204, 0.441113,
    0.390128, 0.340551, 0.292542, 0.246175, 0.201480, 0.158465, 0.117123, 0.077447,
    0.704408, 0.696231, 0.667542, 0.627349, 0.581304, 0.532876, 0.483930, 0.435427,
    0.387855, 0.341451, 0.296312, 0.252455, 0.209852, 0.168440, 0.128141, 0.088860,
    0.683550, 0.675847, 0.648834, 0.611010, 0.567704, 0.522173, 0.476153, 0.430523,
    0.385711, 0.341906, 0.299164, 0.257458, 0.216714, 0.176824, 0.137650, 0.099028,
    0.666357, 0.659036, 0.633370, 0.597455, 0.556359, 0.513176, 0.469538, 0.426260,
    0.383727, 0.342093, 0.301380, 0.261533, 0.222445, 0.183969, 0.145926, 0.108100,
    0.651929, 0.644922, 0.620364, 0.586018, 0.546746, 0.505503, 0.463841, 0.422526,
    0.381909, 0.342114, 0.303143, 0.264916, 0.227303, 0.190131, 0.153187, 0.116216,
    0.639642, 0.632897, 0.609265, 0.576234, 0.538491, 0.498878, 0.458884, 0.419232,
    0.380246, 0.342032, 0.304571, 0.267768, 0.231476, 0.195500, 0.159605, 0.123504,
    0.629046, 0.622524, 0.599679, 0.567765, 0.531322, 0.493100, 0.454531, 0.416307,
    0.378728, 0.341885, 0.305746, 0.270205, 0.235098, 0.200220, 0.165315, 0.130074,
    0.619813, 0.613482, 0.591312, 0.560359, 0.525036, 0.488014, 0.450678, 0.413692,
    0.377340, 0.341699, 0.306727, 0.272310, 0.238274, 0.204403, 0.170426, 0.136021,
    0.611692, 0.605527, 0.583945, 0.553827, 0.519479, 0.483502, 0.447243, 0.411342,
    0.376068, 0.341489, 0.307557, 0.274147, 0.241081, 0.208134, 0.175027, 0.141425);

// Directional albedo of the model as published, at view cosine mu.
float mx_sheen_albedo(float mu, float roughness)
{
    vec4 c = mx_albedo_cell(vec2(sqrt(max(mu, 0.0)), roughness), vec2(16.0, 16.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix(MX_ALBEDO_SHEEN[mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_SHEEN[mx_albedo_index(i + ivec2(1, 0), 16)], c.z),
               mix(MX_ALBEDO_SHEEN[mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_SHEEN[mx_albedo_index(i + ivec2(1, 1), 16)], c.z), c.w);
}

// the model divided by max(1, E(mu_l), E(mu_v)), at roughness = row / 15, mu = (column / 15)^2; 96^2 cosine-distributed directions each
const float MX_ALBEDO_SHEEN_RENORMALISED[256] = float[256](
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.505960, 0.194522, 0.056956,
    0.011685, 0.001490, 0.000099, 0.000003, 0.000000, 0.000000, 0.000000, 0.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 0.974239, 0.791344, 0.620047, 0.466943,
    0.335824, 0.228433, 0.144840, 0.083677, 0.042372, 0.017436, 0.004812, 0.000286,
    1.000000, 1.000000, 1.000000, 0.928473, 0.816701, 0.701559, 0.588835, 0.482107,
    0.383722, 0.295284, 0.217874, 0.152154, 0.098406, 0.056553, 0.026160, 0.006444,
    0.960071, 0.945024, 0.892234, 0.818366, 0.734102, 0.646281, 0.558893, 0.474330,
    0.394135, 0.319389, 0.250893, 0.189269, 0.135003, 0.088473, 0.049953, 0.019618,
    0.868044, 0.855692, 0.812326, 0.751541, 0.681975, 0.609092, 0.536002, 0.464499,
    0.395694, 0.330330, 0.268954, 0.211995, 0.159819, 0.112752, 0.071098, 0.035155,
    0.807028, 0.796325, 0.758747, 0.706050, 0.645662, 0.582237, 0.518370, 0.455511,
    0.394507, 0.335895, 0.280039, 0.227211, 0.177638, 0.131523, 0.089067, 0.050487,
    0.763297, 0.753709, 0.720049, 0.672852, 0.618748, 0.561861, 0.504452, 0.447748,
    0.392431, 0.338896, 0.287388, 0.238064, 0.191037, 0.146401, 0.104244, 0.064665,
    0.730282, 0.721498, 0.690668, 0.647455, 0.597928, 0.545833, 0.493204, 0.441113,
    0.390128, 0.340551, 0.292542, 0.246175, 0.201480, 0.158465, 0.117123, 0.077447,
    0.704408, 0.696231, 0.667542, 0.627349, 0.581304, 0.532876, 0.483930, 0.435427,
    0.387855, 0.341451, 0.296312, 0.252455, 0.209852, 0.168440, 0.128141, 0.088860,
    0.683550, 0.675847, 0.648834, 0.611010, 0.567704, 0.522173, 0.476153, 0.430523,
    0.385711, 0.341906, 0.299164, 0.257458, 0.216714, 0.176824, 0.137650, 0.099028,
    0.666357, 0.659036, 0.633370, 0.597455, 0.556359, 0.513176, 0.469538, 0.426260,
    0.383727, 0.342093, 0.301380, 0.261533, 0.222445, 0.183969, 0.145926, 0.108100,
    0.651929, 0.644922, 0.620364, 0.586018, 0.546746, 0.505503, 0.463841, 0.422526,
    0.381909, 0.342114, 0.303143, 0.264916, 0.227303, 0.190131, 0.153187, 0.116216,
    0.639642, 0.632897, 0.609265, 0.576234, 0.538491, 0.498878, 0.458884, 0.419232,
    0.380246, 0.342032, 0.304571, 0.267768, 0.231476, 0.195500, 0.159605, 0.123504,
    0.629046, 0.622524, 0.599679, 0.567765, 0.531322, 0.493100, 0.454531, 0.416307,
    0.378728, 0.341885, 0.305746, 0.270205, 0.235098, 0.200220, 0.165315, 0.130074,
    0.619813, 0.613482, 0.591312, 0.560359, 0.525036, 0.488014, 0.450678, 0.413692,
    0.377340, 0.341699, 0.306727, 0.272310, 0.238274, 0.204403, 0.170426, 0.136021,
    0.611692, 0.605527, 0.583945, 0.553827, 0.519479, 0.483502, 0.447243, 0.411342,
    0.376068, 0.341489, 0.307557, 0.274147, 0.241081, 0.208134, 0.175027, 0.141425);

// Directional albedo of the model divided by max(1, E(mu_l), E(mu_v)), at view cosine mu.
float mx_sheen_albedo_renormalised(float mu, float roughness)
{
    vec4 c = mx_albedo_cell(vec2(sqrt(max(mu, 0.0)), roughness), vec2(16.0, 16.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix(MX_ALBEDO_SHEEN_RENORMALISED[mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_SHEEN_RENORMALISED[mx_albedo_index(i + ivec2(1, 0), 16)], c.z),
               mix(MX_ALBEDO_SHEEN_RENORMALISED[mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_SHEEN_RENORMALISED[mx_albedo_index(i + ivec2(1, 1), 16)], c.z), c.w);
}

// The shaders' floor on r: 1/r is an exponent.
const float MX_SHEEN_MIN_ROUGHNESS = 0.005;

float mx_sheen_microfiber_D(float NdotH, float r)
{
    float inv = 1.0 / max(r, MX_SHEEN_MIN_ROUGHNESS);
    float sin2 = max(1.0 - NdotH * NdotH, 0.0);
    return (2.0 + inv) * pow(sin2, 0.5 * inv) / (2.0 * MX_PI);
}

// BRDF times NdotL.
float mx_sheen_microfiber(float NdotL, float NdotV, float NdotH, float r)
{
    float f = mx_sheen_microfiber_D(NdotH, r) / (4.0 * (NdotL + NdotV - NdotL * NdotV));
    return f * NdotL / max(1.0, max(mx_sheen_albedo(NdotL, r), mx_sheen_albedo(NdotV, r)));
}

float mx_sheen_ltc_albedo(float x, float y)
{
    float s = y * (0.0206607 + 1.58491 * y) / (0.0379424 + y * (1.32227 + y));
    float m = y * (-0.193854 + y * (-1.14885 + y * (1.7932 - 0.95943 * y * y))) / (0.046391 + y);
    float o = y * (0.000654023 + (-0.0207818 + 0.119681 * y) * y) / (1.26264 + y * (-1.92021 + y));
    return exp(-0.5 * mx_sqr((x - m) / s)) / (s * sqrt(2.0 * MX_PI)) + o;
}

// Entries a and b of the inverse LTC matrix [[a 0 b] [0 a 0] [0 0 1]].
vec2 mx_sheen_ltc_inverse(float x, float y)
{
    float a = (2.58126 * x + 0.813703 * y) * y / (1.0 + 0.310327 * x * x + 2.60994 * x * y);
    float b = sqrt(1.0 - x) * (y - 1.0) * y * y * y / (0.0000254053 + 1.71228 * x - 1.71506 * x * y + 1.34174 * y * y);
    return vec2(a, b);
}

// The LTC's frame: x in the plane of V and N, z = N.
mat3 mx_sheen_ltc_frame(vec3 V, vec3 N, float NdotV)
{
    vec3 X = V - N * NdotV;
    float len2 = dot(X, X);
    if (len2 > 0.0)
    {
        X *= inversesqrt(len2);
        return mat3(X, cross(N, X), N);
    }
    return mx_frame_from_normal(N);
}

// The LTC lobe's density towards L, without the albedo factor (the caller applies it).
float mx_sheen_ltc(vec3 L, vec3 V, vec3 N, float NdotV, float roughness)
{
    vec3 w = L * mx_sheen_ltc_frame(V, N, NdotV);  // L in the LTC frame
    vec2 inv = mx_sheen_ltc_inverse(NdotV, roughness);
    vec3 wo = vec3(inv.x * w.x + inv.y * w.z, inv.x * w.y, w.z);  // back to the clamped cosine
    float len2 = dot(wo, wo);
    return mx_cosine_pdf(wo.z) * mx_sqr(inv.x / len2);
}

void mx_sheen_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N, int mode, inout BSDF bsdf)
{
    int context = closureData.closureType;
    if (mx_weight_is_zero(weight) || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    bool ltc = mode != 0;
    float r = mx_clamp_finite(roughness, ltc ? 0.01 : 0.0, 1.0);  // the LTC fits hold on [0.01, 1]
    float albedo = clamp(ltc ? mx_sheen_ltc_albedo(NdotV, r) : mx_sheen_albedo_renormalised(NdotV, r), 0.0, 1.0);
    vec3 tint = max(color, 0.0);
    // What the fibres reflect (a colourless albedo, as the model's) does not reach the base; light
    // from a lamp crosses them on its way in too.
    bsdf.throughput = vec3(max(1.0 - albedo * weight, 0.0));

    if (context == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * tint * (albedo * weight);
    }
    else  // REFLECTION
    {
        vec3 L = closureData.L;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            return;
        float albedoL = clamp(ltc ? mx_sheen_ltc_albedo(NdotL, r) : mx_sheen_albedo_renormalised(NdotL, r), 0.0, 1.0);
        bsdf.throughput *= max(1.0 - albedoL * weight, 0.0);
        float f = ltc ? albedo * mx_sheen_ltc(L, V, N, NdotV, r)  // the LTC lobe carries the cosine
                      : mx_sheen_microfiber(NdotL, NdotV, clamp(dot(N, normalize(L + V)), 0.0, 1.0), r);
        bsdf.response = tint * (f * closureData.occlusion * weight);
    }
}

// Once per shading point (lib/mx_specular.glsl).
void mx_conductor_bsdf_prepare(ClosureData closureData, float weight, vec3 ior_n, vec3 ior_k, vec2 roughness,
                               bool retroreflective, float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X,
                               int distribution, out SpecularLobe lobe)
{
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_CONDUCTOR, ior_n, ior_k, vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);
    lobe = mx_specular_lobe_prepare(closureData, weight, vec3(1.0), roughness, retroreflective, fd, N, X, distribution, 0);
}

// In each context.
void mx_conductor_bsdf(ClosureData closureData, SpecularLobe lobe, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    int context = closureData.closureType;
    if (lobe.weight == 0.0 || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;
    vec3 reflected = context == CLOSURE_TYPE_REFLECTION ? mx_specular_reflection(closureData, lobe) : lobe.environment;
    bsdf.response = reflected * lobe.weight;
}

// <absorption_vdf>: a purely absorbing medium.
void mx_absorption_vdf(ClosureData closureData, vec3 absorption, inout VDF result)
{
    if (closureData.closureType == CLOSURE_TYPE_TRANSMISSION)
    {
        result.response = vec3(0.0);
        result.throughput = exp(-absorption);
    }
}

// <anisotropic_vdf>: absorption and Henyey-Greenstein scattering; scattering is not rendered by the
// hardware targets, so only absorption filters the light (as in MaterialX's GLSL).
void mx_anisotropic_vdf(ClosureData closureData, vec3 absorption, vec3 scattering, float anisotropy, inout VDF result)
{
    mx_absorption_vdf(closureData, absorption, result);
}

void mx_layer_bsdf(ClosureData closureData, BSDF top, BSDF base, out BSDF result)
{
    result.response = top.response + base.response * top.throughput;
    result.throughput = top.throughput * base.throughput;
    // What a transmitting top lets through enters the base, so what is seen through the layers is
    // the base's view through the top, not the top's own view through itself.
    if (closureData.closureType == CLOSURE_TYPE_TRANSMISSION)
        result.response = base.response * top.throughput;
}

// A BSDF over a medium: the medium filters what the top layer scatters and lets through.
void mx_layer_vdf(ClosureData closureData, BSDF top, VDF base, out BSDF result)
{
    result.response = top.response * base.throughput;
    result.throughput = top.throughput * base.throughput;
}

void mx_mix_bsdf(ClosureData closureData, BSDF fg, BSDF bg, float mixValue, out BSDF result)
{
    result.response = mix(bg.response, fg.response, mixValue);
    result.throughput = mix(bg.throughput, fg.throughput, mixValue);
}

void mx_translucent_bsdf(ClosureData closureData, float weight, vec3 color, vec3 N, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    vec3 back = -mx_usable_normal(N, closureData.N);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(back) * max(color, 0.0) * weight;
    }
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        float cosine = clamp(dot(back, closureData.L), 0.0, 1.0);
        bsdf.response = max(color, 0.0) * (weight * cosine * MX_INV_PI);
    }
}

// Profile shape s d for surface albedo A (Christensen & Burley 2015, eq. 6: the fit of s to their
// Monte Carlo references when d is the mean free path).
vec3 mx_diffusion_shape(vec3 albedo)
{
    vec3 A = clamp(albedo, 0.0, 1.0);
    return vec3(1.9) - A + 3.5 * mx_sqr(A - vec3(0.8));
}

// The profile R(r) up to the factor A s / (8 pi), which cancels in the normalised wrap below.
vec3 mx_diffusion_profile(float r, vec3 s)
{
    return (exp(-s * r) + exp(-s * r / 3.0)) / max(r, 1.0e-4);
}

// Irradiance (relative to the light's) diffused to a point whose normal makes angle theta with the
// light, on a circle of radius `radius`, for mean free path `mfp`: the profile-weighted average of
// the clamped cosine over the circle, chord distances between points.
vec3 mx_diffusion_wrap(float cosTheta, float radius, vec3 mfp, vec3 albedo)
{
    const int STEPS = 24;
    vec3 s = mx_diffusion_shape(albedo) / max(mfp, vec3(1.0e-3));
    float theta = acos(clamp(cosTheta, -1.0, 1.0));
    vec3 lit = vec3(0.0);
    vec3 total = vec3(0.0);
    for (int i = 0; i < STEPS; i++)
    {
        float x = MX_PI * ((float(i) + 0.5) / float(STEPS) * 2.0 - 1.0);  // angle along the circle
        vec3 w = mx_diffusion_profile(2.0 * radius * abs(sin(0.5 * x)), s);
        lit += w * max(cos(theta + x), 0.0);
        total += w;
    }
    return lit / max(total, vec3(MX_EPS));
}

// Subsurface reflectance towards L, cosine included, with the radius of curvature estimated from
// screen-space derivatives of the normal and the position.
vec3 mx_subsurface_scatter(vec3 N, vec3 L, vec3 P, vec3 albedo, vec3 mfp)
{
    float curvature = length(fwidth(N)) / max(length(fwidth(P)), MX_EPS);
    float radius = 1.0 / max(curvature, 0.01);
    return albedo * mx_diffusion_wrap(dot(N, L), radius, mfp, albedo) * MX_INV_PI;
}

void mx_subsurface_bsdf(ClosureData closureData, float weight, vec3 color, vec3 radius, float anisotropy, vec3 N,
                        inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    N = mx_shading_normal(N, closureData.N, closureData.V);
    vec3 albedo = clamp(color, 0.0, 1.0);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * albedo * weight;
    }
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        // Occlusion hides the light that arrives directly, not the light diffused from around.
        float direct = clamp(dot(N, closureData.L), 0.0, 1.0);
        float visible = 1.0 - direct * (1.0 - closureData.occlusion);
        bsdf.response = mx_subsurface_scatter(N, closureData.L, closureData.P, albedo, max(radius, 0.0)) * (visible * weight);
    }
}

// the model as published, at roughness = row / 15, mu = (column / 15)^2; 96^2 cosine-distributed directions each
const float MX_ALBEDO_OREN_NAYAR[256] = float[256](
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.003530, 1.003530, 1.003528, 1.003521, 1.003504, 1.003129, 1.002752, 1.002266,
    1.001682, 1.000997, 1.000203, 0.999303, 0.998296, 0.997172, 0.995873, 0.993355,
    1.010103, 1.010102, 1.010097, 1.010074, 1.010012, 1.008697, 1.007378, 1.005675,
    1.003628, 1.001225, 0.998444, 0.995289, 0.991758, 0.987818, 0.983264, 0.974441,
    1.012469, 1.012468, 1.012459, 1.012416, 1.012301, 1.009847, 1.007386, 1.004210,
    1.000391, 0.995908, 0.990720, 0.984837, 0.978249, 0.970899, 0.962404, 0.945946,
    1.006784, 1.006783, 1.006768, 1.006707, 1.006542, 1.003022, 0.999492, 0.994936,
    0.989458, 0.983027, 0.975585, 0.967145, 0.957696, 0.947152, 0.934966, 0.911357,
    0.993503, 0.993502, 0.993484, 0.993407, 0.993201, 0.988794, 0.984376, 0.978674,
    0.971816, 0.963766, 0.954451, 0.943887, 0.932059, 0.918860, 0.903608, 0.874055,
    0.975103, 0.975101, 0.975081, 0.974992, 0.974752, 0.969648, 0.964531, 0.957924,
    0.949980, 0.940656, 0.929865, 0.917627, 0.903926, 0.888637, 0.870968, 0.836735,
    0.954196, 0.954195, 0.954172, 0.954074, 0.953809, 0.948166, 0.942508, 0.935204,
    0.926421, 0.916112, 0.904182, 0.890651, 0.875503, 0.858600, 0.839065, 0.801217,
    0.932770, 0.932769, 0.932744, 0.932639, 0.932355, 0.926296, 0.920222, 0.912381,
    0.902951, 0.891884, 0.879076, 0.864550, 0.848288, 0.830140, 0.809168, 0.768535,
    0.912090, 0.912089, 0.912063, 0.911952, 0.911653, 0.905272, 0.898875, 0.890617,
    0.880687, 0.869032, 0.855544, 0.840246, 0.823120, 0.804008, 0.781922, 0.739130,
    0.892848, 0.892846, 0.892820, 0.892704, 0.892393, 0.885761, 0.879111, 0.870527,
    0.860204, 0.848089, 0.834068, 0.818166, 0.800363, 0.780496, 0.757538, 0.713056,
    0.875346, 0.875344, 0.875317, 0.875198, 0.874877, 0.868045, 0.861195, 0.852353,
    0.841719, 0.829239, 0.814796, 0.798415, 0.780076, 0.759612, 0.735962, 0.690141,
    0.859648, 0.859646, 0.859618, 0.859497, 0.859168, 0.852177, 0.845166, 0.836116,
    0.825234, 0.812461, 0.797679, 0.780915, 0.762146, 0.741202, 0.716998, 0.670103,
    0.845687, 0.845685, 0.845657, 0.845533, 0.845198, 0.838077, 0.830936, 0.821718,
    0.810633, 0.797623, 0.782567, 0.765491, 0.746373, 0.725040, 0.700387, 0.652621,
    0.833327, 0.833326, 0.833297, 0.833171, 0.832831, 0.825603, 0.818355, 0.809000,
    0.797749, 0.784544, 0.769263, 0.751932, 0.732528, 0.710876, 0.685853, 0.637373,
    0.822409, 0.822407, 0.822377, 0.822250, 0.821907, 0.814590, 0.807254, 0.797784,
    0.786396, 0.773030, 0.757562, 0.740018, 0.720378, 0.698461, 0.673133, 0.624060);

// Directional albedo of the model as published, at view cosine mu.
float mx_oren_nayar_albedo(float mu, float roughness)
{
    vec4 c = mx_albedo_cell(vec2(sqrt(max(mu, 0.0)), roughness), vec2(16.0, 16.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix(MX_ALBEDO_OREN_NAYAR[mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_OREN_NAYAR[mx_albedo_index(i + ivec2(1, 0), 16)], c.z),
               mix(MX_ALBEDO_OREN_NAYAR[mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_OREN_NAYAR[mx_albedo_index(i + ivec2(1, 1), 16)], c.z), c.w);
}

// the model divided by max(1, E(mu_l), E(mu_v)), at roughness = row / 15, mu = (column / 15)^2; 96^2 cosine-distributed directions each
const float MX_ALBEDO_OREN_NAYAR_RENORMALISED[256] = float[256](
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.999996, 0.999989, 0.999972,
    0.999934, 0.999863, 0.999734, 0.998997, 0.997990, 0.996866, 0.995568, 0.993052,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.999985, 0.999960, 0.999896,
    0.999763, 0.999511, 0.997782, 0.994635, 0.991109, 0.987173, 0.982624, 0.973809,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.999968, 0.999918, 0.999795,
    0.999541, 0.995429, 0.990252, 0.984377, 0.977797, 0.970453, 0.961965, 0.945517,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.999948, 0.999379, 0.994833,
    0.989360, 0.982934, 0.975495, 0.967057, 0.957610, 0.947068, 0.934884, 0.911278,
    0.993503, 0.993502, 0.993484, 0.993407, 0.993201, 0.988794, 0.984376, 0.978674,
    0.971816, 0.963766, 0.954451, 0.943887, 0.932059, 0.918860, 0.903608, 0.874055,
    0.975103, 0.975101, 0.975081, 0.974992, 0.974752, 0.969648, 0.964531, 0.957924,
    0.949980, 0.940656, 0.929865, 0.917627, 0.903926, 0.888637, 0.870968, 0.836735,
    0.954196, 0.954195, 0.954172, 0.954074, 0.953809, 0.948166, 0.942508, 0.935204,
    0.926421, 0.916112, 0.904182, 0.890651, 0.875503, 0.858600, 0.839065, 0.801217,
    0.932770, 0.932769, 0.932744, 0.932639, 0.932355, 0.926296, 0.920222, 0.912381,
    0.902951, 0.891884, 0.879076, 0.864550, 0.848288, 0.830140, 0.809168, 0.768535,
    0.912090, 0.912089, 0.912063, 0.911952, 0.911653, 0.905272, 0.898875, 0.890617,
    0.880687, 0.869032, 0.855544, 0.840246, 0.823120, 0.804008, 0.781922, 0.739130,
    0.892848, 0.892846, 0.892820, 0.892704, 0.892393, 0.885761, 0.879111, 0.870527,
    0.860204, 0.848089, 0.834068, 0.818166, 0.800363, 0.780496, 0.757538, 0.713056,
    0.875346, 0.875344, 0.875317, 0.875198, 0.874877, 0.868045, 0.861195, 0.852353,
    0.841719, 0.829239, 0.814796, 0.798415, 0.780076, 0.759612, 0.735962, 0.690141,
    0.859648, 0.859646, 0.859618, 0.859497, 0.859168, 0.852177, 0.845166, 0.836116,
    0.825234, 0.812461, 0.797679, 0.780915, 0.762146, 0.741202, 0.716998, 0.670103,
    0.845687, 0.845685, 0.845657, 0.845533, 0.845198, 0.838077, 0.830936, 0.821718,
    0.810633, 0.797623, 0.782567, 0.765491, 0.746373, 0.725040, 0.700387, 0.652621,
    0.833327, 0.833326, 0.833297, 0.833171, 0.832831, 0.825603, 0.818355, 0.809000,
    0.797749, 0.784544, 0.769263, 0.751932, 0.732528, 0.710876, 0.685853, 0.637373,
    0.822409, 0.822407, 0.822377, 0.822250, 0.821907, 0.814590, 0.807254, 0.797784,
    0.786396, 0.773030, 0.757562, 0.740018, 0.720378, 0.698461, 0.673133, 0.624060);

// Directional albedo of the model divided by max(1, E(mu_l), E(mu_v)), at view cosine mu.
float mx_oren_nayar_albedo_renormalised(float mu, float roughness)
{
    vec4 c = mx_albedo_cell(vec2(sqrt(max(mu, 0.0)), roughness), vec2(16.0, 16.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix(MX_ALBEDO_OREN_NAYAR_RENORMALISED[mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_OREN_NAYAR_RENORMALISED[mx_albedo_index(i + ivec2(1, 0), 16)], c.z),
               mix(MX_ALBEDO_OREN_NAYAR_RENORMALISED[mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_OREN_NAYAR_RENORMALISED[mx_albedo_index(i + ivec2(1, 1), 16)], c.z), c.w);
}

float mx_renormalisation(float albedoL, float albedoV)
{
    return 1.0 / max(1.0, max(albedoL, albedoV));
}

// sigma: the standard deviation of the facet slope angle, in radians.
float mx_oren_nayar(float NdotV, float NdotL, float LdotV, float sigma)
{
    float sigma2 = sigma * sigma;
    float A = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float B = 0.45 * sigma2 / (sigma2 + 0.09);
    // sin(alpha) tan(beta) cos(phi_i - phi_o) with alpha, beta the larger and smaller polar angles.
    float projected = LdotV - NdotL * NdotV;
    float retro = max(projected, 0.0) / max(max(NdotL, NdotV), MX_EPS);
    float renorm = mx_renormalisation(mx_oren_nayar_albedo(NdotL, sigma), mx_oren_nayar_albedo(NdotV, sigma));
    return (A + B * retro) * renorm;
}

// Fujii's model f = rho / pi * A (1 + sigma s / t) has the closed-form directional albedo below;
// the constants are its analytic integrals (OpenPBR specification, "EON" diffuse).
const float MX_EON_C1 = 0.5 - 2.0 / (3.0 * MX_PI);
const float MX_EON_C2 = 2.0 / 3.0 - 28.0 / (15.0 * MX_PI);

float mx_eon_single_albedo(float mu, float sigma)
{
    float A = 1.0 / (1.0 + MX_EON_C1 * sigma);
    float s = sqrt(max(0.0, 1.0 - mu * mu));
    float theta = acos(clamp(mu, -1.0, 1.0));
    float G = s * (theta - s * mu) + 2.0 * ((s / max(mu, MX_EPS)) * (1.0 - s * s * s) - s) / 3.0;
    return A * (1.0 + sigma * G * MX_INV_PI);
}

float mx_eon_mean_albedo(float sigma)
{
    return (1.0 + MX_EON_C2 * sigma) / (1.0 + MX_EON_C1 * sigma);
}

// Colour of the multiple-scattering lobe: the energy single scattering misses, bounced again with
// the surface's colour rho (a geometric series of bounces).
vec3 mx_eon_multiple_colour(vec3 rho, float meanAlbedo)
{
    return rho * rho * meanAlbedo / max(vec3(1.0) - rho * (1.0 - meanAlbedo), MX_EPS);
}

vec3 mx_eon(float NdotV, float NdotL, float LdotV, float sigma, vec3 rho)
{
    float projected = LdotV - NdotL * NdotV;
    float ratio = (projected > 0.0) ? projected / max(max(NdotL, NdotV), MX_EPS) : projected;
    vec3 single = rho * (1.0 + sigma * ratio) / (1.0 + MX_EON_C1 * sigma);
    float meanAlbedo = mx_eon_mean_albedo(sigma);
    float lostV = max(1.0 - mx_eon_single_albedo(NdotV, sigma), 0.0);
    float lostL = max(1.0 - mx_eon_single_albedo(NdotL, sigma), 0.0);
    return single + mx_eon_multiple_colour(rho, meanAlbedo) * lostV * lostL / max(1.0 - meanAlbedo, MX_EPS);
}

vec3 mx_eon_albedo(float mu, float sigma, vec3 rho)
{
    return mix(mx_eon_multiple_colour(rho, mx_eon_mean_albedo(sigma)), rho, mx_eon_single_albedo(mu, sigma));
}

void mx_oren_nayar_diffuse_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N,
                                bool energy_compensation, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float sigma = mx_clamp_finite(roughness, 0.0, 1.0);
    vec3 rho = max(color, 0.0);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        vec3 albedo = energy_compensation ? mx_eon_albedo(NdotV, sigma, rho)
                                          : rho * mx_oren_nayar_albedo_renormalised(NdotV, sigma);
        bsdf.response = mx_environment_irradiance(N) * albedo * weight;
    }
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            return;
        float LdotV = dot(L, V);
        vec3 f = energy_compensation ? mx_eon(NdotV, NdotL, LdotV, sigma, rho)
                                     : rho * mx_oren_nayar(NdotV, NdotL, LdotV, sigma);
        bsdf.response = f * (closureData.occlusion * weight * NdotL * MX_INV_PI);
    }
}

// A BSDF's response is scaled by the weight clamped to [0, 1]; what it lets through is unchanged.
void mx_multiply_bsdf_color3(ClosureData closureData, BSDF in1, vec3 in2, out BSDF result)
{
    result.response = in1.response * clamp(in2, 0.0, 1.0);
    result.throughput = in1.throughput;
}

void mx_uniform_edf(ClosureData closureData, vec3 color, inout EDF result)
{
    if (closureData.closureType == CLOSURE_TYPE_EMISSION)
        result = color;
}

// Largest weight the curve takes: any real use is far below (the coat's transmittance is <= 1).
const float MX_MAX_EDF_WEIGHT = 1.0e6;

void mx_generalized_schlick_edf(ClosureData closureData, vec3 color0, vec3 color90, float exponent, EDF base,
                                inout EDF result)
{
    if (closureData.closureType != CLOSURE_TYPE_EMISSION)
        return;
    vec3 V = closureData.V;
    float NdotV = clamp(dot(mx_facing_normal(closureData.N, V), V), MX_EPS, 1.0);
    // the colours may be computed by the graph (a shading model's coat transmittance): finite, >= 0
    vec3 weight = mx_fresnel_schlick_exp(NdotV, mx_clamp_finite(color0, 0.0, MX_MAX_EDF_WEIGHT),
                                         mx_clamp_finite(color90, 0.0, MX_MAX_EDF_WEIGHT),
                                         mx_clamp_finite(exponent, 0.0, MX_MAX_EDF_WEIGHT));
    result = base * weight;
}

// <point_light>: light from `light.position`, falling off as (distance + 1)^-decay_rate.
void mx_point_light(LightData light, vec3 position, out lightshader result)
{
    vec3 toLight = light.position - position;
    float dist = length(toLight) + 1.0e-8;
    result.direction = toLight / dist;
    result.intensity = light.color * light.intensity / pow(dist + 1.0, light.decay_rate + 1.0e-8);
}

// <directional_light>: parallel light travelling along `light.direction`.
void mx_directional_light(LightData light, vec3 position, out lightshader result)
{
    result.direction = -light.direction;
    result.intensity = light.color * light.intensity;
}

// <spot_light>: a point light restricted to a cone about `light.direction`. As in MaterialX's
// hardware lights, inner_angle and outer_angle are compared with the cosine between the cone axis
// and the direction to the shaded point: full intensity where that cosine is at least inner_angle,
// none below min(inner_angle, outer_angle), smooth in between.
void mx_spot_light(LightData light, vec3 position, out lightshader result)
{
    vec3 toLight = light.position - position;
    float dist = length(toLight) + 1.0e-8;
    result.direction = toLight / dist;
    result.intensity = light.color * light.intensity / pow(dist + 1.0, light.decay_rate + 1.0e-8);

    float cosAxis = dot(result.direction, -light.direction);
    float low = min(light.inner_angle, light.outer_angle);
    float high = light.inner_angle;
    result.intensity *= (low < high) ? smoothstep(low, high, cosAxis) : step(high, cosAxis);
}

int numActiveLightSources()
{
    return min(u_numActiveLightSources, MAX_LIGHT_SOURCES);
}

void sampleLightSource(LightData light, vec3 position, out lightshader result)
{
    result.intensity = vec3(0.0);
    result.direction = vec3(0.0);
    if (light.type == 1)
        mx_point_light(light, position, result);
    else if (light.type == 2)
        mx_directional_light(light, position, result);
    else if (light.type == 3)
        mx_spot_light(light, position, result);
}

void main()
{
    vec2 n0_out;
    mx_roughness_anisotropy(u_n70_coat_roughness, u_n70_coat_anisotropy, n0_out);
    vec3 n1_out = normalize(vd.normalWorld);
    vec3 n2_out = normalize(vd.tangentWorld);
    float n3_out = u_n70_coat_rotation * 180.0;
    vec3 n4_out;
    mx_rotate3d_vector3(n2_out, n3_out, n1_out, n4_out);
    float n7_out = u_n70_coat * u_n70_coat_affect_color;
    float n8_out = n7_out + 1.0;
    vec3 n9_out = pow(u_n70_base_color, vec3(n8_out));
    vec3 n10_out = n9_out * u_n70_base;
    vec3 n11_ior;
    vec3 n11_extinction;
    mx_artistic_ior(n10_out, u_n70_specular_color, n11_ior, n11_extinction);
    float n12_out = u_n70_coat * u_n70_coat_affect_roughness;
    float n13_out = n12_out * u_n70_coat_roughness;
    float n14_out = mix(u_n70_specular_roughness, 1.0, n13_out);
    vec2 n15_out;
    mx_roughness_anisotropy(n14_out, u_n70_specular_anisotropy, n15_out);
    float n16_out = u_n70_specular_rotation * 180.0;
    vec3 n17_out;
    mx_rotate3d_vector3(n2_out, n16_out, n1_out, n17_out);
    float n20_out = (u_n70_transmission_depth > 0.0) ? 1.0 : 0.0;
    vec3 n21_out = mix(u_n70_transmission_color, vec3(1.0, 1.0, 1.0), n20_out);
    float n22_out = n14_out + u_n70_transmission_extra_roughness;
    float n23_out = clamp(n22_out, 0.0, 1.0);
    vec2 n24_out;
    mx_roughness_anisotropy(n23_out, u_n70_specular_anisotropy, n24_out);
    vec3 n26_out = u_n70_transmission_color;
    vec3 n27_out = max(n26_out, 1.0e-6);
    vec3 n28_out = log(n27_out);
    float n29_out = max(u_n70_transmission_depth, 1.0e-6);
    vec3 n30_out = n28_out / n29_out;
    vec3 n31_out = u_n70_transmission_scatter;
    vec3 n32_out = n31_out / n29_out;
    vec3 n33_out = n30_out + n32_out;
    vec3 n34_out = min(n33_out, 0.0);
    vec3 n35_out = n34_out * (-1.0);
    vec3 n39_out = pow(u_n70_subsurface_color, vec3(n8_out));
    vec3 n41_out = u_n70_subsurface_radius * u_n70_subsurface_scale;
    float n43_out = float(u_n70_thin_walled);
    vec3 n51_out = mix(vec3(1.0, 1.0, 1.0), u_n70_coat_color, u_n70_coat);
    float n54_out = u_n70_coat_IOR - 1.0;
    float n55_out = u_n70_coat_IOR + 1.0;
    float n56_out = n54_out / n55_out;
    float n57_out = n56_out * n56_out;
    float n58_out = 1.0 - n57_out;
    vec3 n59_out = u_n70_coat_color * n58_out;
    vec3 n60_out = mix(vec3(1.0, 1.0, 1.0), n59_out, u_n70_coat);
    float n61_out = 1.0 - u_n70_coat;
    vec3 n62_out = vec3(n61_out);
    vec3 n63_out = u_n70_emission_color * u_n70_emission;
    vec3 n66_out = u_n70_opacity;
    float n67_out = dot(n66_out, vec3(0.333333, 0.333333, 0.333334));
    surfaceshader n68_out = surfaceshader(vec3(0.0), vec3(0.0));
    {
        vec3 N = normalize(vd.normalWorld);
        vec3 V = normalize(u_viewPosition - vd.positionWorld);
        vec3 P = vd.positionWorld;
        vec3 L = vec3(0.0);
        float occlusion = 1.0;
        float surfaceOpacity = n67_out;
        // lobes under a mix: weight 0 where the mix leaves them out
        bool n48_reached = u_n70_metalness != 1.0;
        bool n46_reached = n48_reached && u_n70_transmission != 1.0;
        float n45_active_weight = (n46_reached && u_n70_subsurface != 1.0) ? u_n70_base : 0.0;
        bool n44_reached = n46_reached && u_n70_subsurface != 0.0;
        float n42_active_weight = (n44_reached && n43_out != 1.0) ? 1.0 : 0.0;
        float n40_active_weight = (n44_reached && n43_out != 0.0) ? 1.0 : 0.0;
        bool n38_reached = n48_reached && u_n70_transmission != 0.0;
        bool n37_reached = n38_reached && n20_out != 0.0;
        float n25_active_weight = ((n38_reached && n20_out != 1.0) || n37_reached) ? 1.0 : 0.0;
        float n19_active_weight = n48_reached ? u_n70_specular : 0.0;
        float n18_active_weight = (u_n70_metalness != 0.0) ? 1.0 : 0.0;
        // lobes prepared once per shading point, before any light
        ClosureData pointData = ClosureData(CLOSURE_TYPE_DEFAULT, L, V, N, P, occlusion);
        SpecularLobe n5_lobe;
        mx_dielectric_bsdf_prepare(pointData, u_n70_coat, vec3(1.0, 1.0, 1.0), u_n70_coat_IOR, n0_out, false, 0.0, 1.5, n1_out, n4_out, 0, 0, n5_lobe);
        SpecularLobe n18_lobe;
        mx_conductor_bsdf_prepare(pointData, n18_active_weight, n11_ior, n11_extinction, n15_out, false, u_n70_thin_film_thickness, u_n70_thin_film_IOR, n1_out, n17_out, 0, n18_lobe);
        SpecularLobe n19_lobe;
        mx_dielectric_bsdf_prepare(pointData, n19_active_weight, u_n70_specular_color, u_n70_specular_IOR, n15_out, false, u_n70_thin_film_thickness, u_n70_thin_film_IOR, n1_out, n17_out, 0, 0, n19_lobe);
        SpecularLobe n25_lobe;
        mx_dielectric_bsdf_prepare(pointData, n25_active_weight, n21_out, u_n70_specular_IOR, n24_out, false, 0.0, 1.5, n1_out, n17_out, 0, 1, n25_lobe);
        for (int activeLightIndex = 0; activeLightIndex < numActiveLightSources(); ++activeLightIndex)
        {
            lightshader lightShader;
            sampleLightSource(u_lightData[activeLightIndex], vd.positionWorld, lightShader);
            L = lightShader.direction;
            ClosureData closureData = ClosureData(CLOSURE_TYPE_REFLECTION, L, V, N, P, occlusion);
            BSDF n5_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n5_lobe, n5_out);
            BSDF n6_out = BSDF(vec3(0.0), vec3(1.0));
            mx_sheen_bsdf(closureData, u_n70_sheen, u_n70_sheen_color, u_n70_sheen_roughness, n1_out, 0, n6_out);
            BSDF n18_out = BSDF(vec3(0.0), vec3(1.0));
            mx_conductor_bsdf(closureData, n18_lobe, n18_out);
            BSDF n19_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n19_lobe, n19_out);
            BSDF n25_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n25_lobe, n25_out);
            VDF n36_out = VDF(vec3(0.0), vec3(1.0));
            mx_anisotropic_vdf(closureData, n35_out, n32_out, u_n70_transmission_scatter_anisotropy, n36_out);
            BSDF n37_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_vdf(closureData, n25_out, n36_out, n37_out);
            BSDF n38_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n37_out, n25_out, n20_out, n38_out);
            BSDF n40_out = BSDF(vec3(0.0), vec3(1.0));
            mx_translucent_bsdf(closureData, n40_active_weight, n39_out, n1_out, n40_out);
            BSDF n42_out = BSDF(vec3(0.0), vec3(1.0));
            mx_subsurface_bsdf(closureData, n42_active_weight, n39_out, n41_out, u_n70_subsurface_anisotropy, n1_out, n42_out);
            BSDF n44_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n40_out, n42_out, n43_out, n44_out);
            BSDF n45_out = BSDF(vec3(0.0), vec3(1.0));
            mx_oren_nayar_diffuse_bsdf(closureData, n45_active_weight, n9_out, u_n70_diffuse_roughness, n1_out, false, n45_out);
            BSDF n46_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n44_out, n45_out, u_n70_subsurface, n46_out);
            BSDF n47_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n38_out, n46_out, u_n70_transmission, n47_out);
            BSDF n48_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n19_out, n47_out, n48_out);
            BSDF n49_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n18_out, n48_out, u_n70_metalness, n49_out);
            BSDF n50_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n6_out, n49_out, n50_out);
            BSDF n52_out = BSDF(vec3(0.0), vec3(1.0));
            mx_multiply_bsdf_color3(closureData, n50_out, n51_out, n52_out);
            BSDF n53_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n5_out, n52_out, n53_out);
            n68_out.color += lightShader.intensity * n53_out.response;
        }
        // environment
        {
            ClosureData closureData = ClosureData(CLOSURE_TYPE_INDIRECT, L, V, N, P, occlusion);
            BSDF n5_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n5_lobe, n5_out);
            BSDF n6_out = BSDF(vec3(0.0), vec3(1.0));
            mx_sheen_bsdf(closureData, u_n70_sheen, u_n70_sheen_color, u_n70_sheen_roughness, n1_out, 0, n6_out);
            BSDF n18_out = BSDF(vec3(0.0), vec3(1.0));
            mx_conductor_bsdf(closureData, n18_lobe, n18_out);
            BSDF n19_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n19_lobe, n19_out);
            BSDF n25_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n25_lobe, n25_out);
            VDF n36_out = VDF(vec3(0.0), vec3(1.0));
            mx_anisotropic_vdf(closureData, n35_out, n32_out, u_n70_transmission_scatter_anisotropy, n36_out);
            BSDF n37_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_vdf(closureData, n25_out, n36_out, n37_out);
            BSDF n38_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n37_out, n25_out, n20_out, n38_out);
            BSDF n40_out = BSDF(vec3(0.0), vec3(1.0));
            mx_translucent_bsdf(closureData, n40_active_weight, n39_out, n1_out, n40_out);
            BSDF n42_out = BSDF(vec3(0.0), vec3(1.0));
            mx_subsurface_bsdf(closureData, n42_active_weight, n39_out, n41_out, u_n70_subsurface_anisotropy, n1_out, n42_out);
            BSDF n44_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n40_out, n42_out, n43_out, n44_out);
            BSDF n45_out = BSDF(vec3(0.0), vec3(1.0));
            mx_oren_nayar_diffuse_bsdf(closureData, n45_active_weight, n9_out, u_n70_diffuse_roughness, n1_out, false, n45_out);
            BSDF n46_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n44_out, n45_out, u_n70_subsurface, n46_out);
            BSDF n47_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n38_out, n46_out, u_n70_transmission, n47_out);
            BSDF n48_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n19_out, n47_out, n48_out);
            BSDF n49_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n18_out, n48_out, u_n70_metalness, n49_out);
            BSDF n50_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n6_out, n49_out, n50_out);
            BSDF n52_out = BSDF(vec3(0.0), vec3(1.0));
            mx_multiply_bsdf_color3(closureData, n50_out, n51_out, n52_out);
            BSDF n53_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n5_out, n52_out, n53_out);
            n68_out.color += occlusion * n53_out.response;
        }
        // emission
        {
            ClosureData closureData = ClosureData(CLOSURE_TYPE_EMISSION, L, V, N, P, occlusion);
            EDF n64_out = EDF(0.0);
            mx_uniform_edf(closureData, n63_out, n64_out);
            EDF n65_out = EDF(0.0);
            mx_generalized_schlick_edf(closureData, n60_out, n62_out, 5.0, n64_out, n65_out);
            n68_out.color += n65_out;
        }
        // transmission, seen along the view direction
        {
            ClosureData closureData = ClosureData(CLOSURE_TYPE_TRANSMISSION, L, V, N, P, occlusion);
            BSDF n5_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n5_lobe, n5_out);
            BSDF n6_out = BSDF(vec3(0.0), vec3(1.0));
            mx_sheen_bsdf(closureData, u_n70_sheen, u_n70_sheen_color, u_n70_sheen_roughness, n1_out, 0, n6_out);
            BSDF n18_out = BSDF(vec3(0.0), vec3(1.0));
            mx_conductor_bsdf(closureData, n18_lobe, n18_out);
            BSDF n19_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n19_lobe, n19_out);
            BSDF n25_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, n25_lobe, n25_out);
            VDF n36_out = VDF(vec3(0.0), vec3(1.0));
            mx_anisotropic_vdf(closureData, n35_out, n32_out, u_n70_transmission_scatter_anisotropy, n36_out);
            BSDF n37_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_vdf(closureData, n25_out, n36_out, n37_out);
            BSDF n38_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n37_out, n25_out, n20_out, n38_out);
            BSDF n40_out = BSDF(vec3(0.0), vec3(1.0));
            mx_translucent_bsdf(closureData, n40_active_weight, n39_out, n1_out, n40_out);
            BSDF n42_out = BSDF(vec3(0.0), vec3(1.0));
            mx_subsurface_bsdf(closureData, n42_active_weight, n39_out, n41_out, u_n70_subsurface_anisotropy, n1_out, n42_out);
            BSDF n44_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n40_out, n42_out, n43_out, n44_out);
            BSDF n45_out = BSDF(vec3(0.0), vec3(1.0));
            mx_oren_nayar_diffuse_bsdf(closureData, n45_active_weight, n9_out, u_n70_diffuse_roughness, n1_out, false, n45_out);
            BSDF n46_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n44_out, n45_out, u_n70_subsurface, n46_out);
            BSDF n47_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n38_out, n46_out, u_n70_transmission, n47_out);
            BSDF n48_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n19_out, n47_out, n48_out);
            BSDF n49_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, n18_out, n48_out, u_n70_metalness, n49_out);
            BSDF n50_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n6_out, n49_out, n50_out);
            BSDF n52_out = BSDF(vec3(0.0), vec3(1.0));
            mx_multiply_bsdf_color3(closureData, n50_out, n51_out, n52_out);
            BSDF n53_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, n5_out, n52_out, n53_out);
            n68_out.color += n53_out.response;
        }
        n68_out.color *= surfaceOpacity;
        n68_out.transparency = mix(vec3(1.0), n68_out.transparency, surfaceOpacity);
    }
    material n69_out = n68_out;
    out1 = vec4(n69_out.color, 1.0 - dot(n69_out.transparency, vec3(1.0 / 3.0)));
}
