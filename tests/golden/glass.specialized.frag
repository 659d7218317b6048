#version 400

struct surfaceshader { vec3 color; vec3 transparency; };
struct lightshader { vec3 intensity; vec3 direction; };
struct BSDF { vec3 response; vec3 throughput; };
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

in VertexData
{
    vec3 normalWorld;
    vec3 tangentWorld;
    vec3 positionWorld;
} vd;

out vec4 out1;

#define CLOSURE_TYPE_REFLECTION 1

#define CLOSURE_TYPE_TRANSMISSION 2

#define CLOSURE_TYPE_INDIRECT 3


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


ClosureData makeClosureData(int closureType, vec3 L, vec3 V, vec3 N, vec3 P, float occlusion)
{
    return ClosureData(closureType, L, V, N, P, occlusion);
}


// Constants and small helpers shared by the PBR library.

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


float mx_pow_6(float x)
{
    float x2 = x * x;
    return x2 * x2 * x2;
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


// Fresnel reflectance: Schlick and its generalisations, exact dielectric and conductor
// reflectance, and Belcour & Barla's thin-film (Airy) interference over any of them.

#ifndef AIRY_FRESNEL_ITERATIONS

#define AIRY_FRESNEL_ITERATIONS 2

#endif


#define FRESNEL_MODEL_DIELECTRIC 0

#define FRESNEL_MODEL_CONDUCTOR 1

#define FRESNEL_MODEL_SCHLICK 2


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
    return FresnelData(model, ior, extinction, F0, F82, F90, exponent, tf_thickness, tf_ior, false);
}


bool mx_fresnel_has_thinfilm(FresnelData fd)
{
    return fd.tf_thickness > 0.0;
}


// Generalised Schlick with Hoffman's F82 tint: the Schlick curve minus a x (1 - x)^6 lobe, whose
// weight puts the curve through F82 at cos = 1/7 (about 82 degrees).
vec3 mx_fresnel_f82(float cosTheta, FresnelData fd)
{
    const float COS_82 = 1.0 / 7.0;
    const float LOBE_AT_82 = 0.0566527795;  // (1/7) (6/7)^6
    float c = clamp(cosTheta, 0.0, 1.0);
    vec3 schlick82 = mix(fd.F0, fd.F90, mx_power(1.0 - COS_82, fd.exponent));
    vec3 a = schlick82 * (vec3(1.0) - fd.F82) / LOBE_AT_82;
    return max(mix(fd.F0, fd.F90, mx_power(1.0 - c, fd.exponent)) - a * (c * mx_pow_6(1.0 - c)), 0.0);
}


// --- Dielectric ------------------------------------------------------------------------------

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


// --- Conductor -------------------------------------------------------------------------------

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


// --- Thin film (Belcour & Barla 2017) --------------------------------------------------------
// A film of index n2 and thickness d over the base: light reflected at the top interface (R12) and
// light that crossed the film once or more (an Airy series) interfere with an optical path
// difference opd = 2 n2 d cos(theta2) per round trip. Belcour & Barla integrate each harmonic m of
// the series against the CIE colour matching functions in closed form, approximating their
// Fourier transforms by Gaussians; the amplitudes, centres and variances below are the paper's
// published fits (x has a second, small Gaussian), normalised by the integral of y.

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
    if (schlick)
    {
        R23p = R23s = mx_fresnel_f82(c2, fd);  // unpolarised: the same for both
        phi23p = phi23s = mix(vec3(0.0), vec3(MX_PI), lessThan(n3, vec3(n2)));
    }
    else
    {
        mx_fresnel_conductor_pol(c2, n3 / n2, k3 / n2, R23p, R23s);
        mx_fresnel_conductor_phase(c2, n2, n3, k3, phi23p, phi23s);
    }

    float opd = 2.0 * n2 * c2 * fd.tf_thickness * 1.0e-9;
    vec3 xyz = mx_thinfilm_polarisation(R12.x, R23p, phi23p + phi21.x, opd) +
               mx_thinfilm_polarisation(R12.y, R23s, phi23s + phi21.y, opd);
    return clamp(XYZ_TO_RGB * (0.5 * xyz), 0.0, 1.0);
}


// --- Dispatch --------------------------------------------------------------------------------

vec3 mx_fresnel_eval(float cosTheta, FresnelData fd)
{
    if (mx_fresnel_has_thinfilm(fd))
        return mx_fresnel_airy(cosTheta, fd);
    if (fd.model == FRESNEL_MODEL_DIELECTRIC)
        return vec3(mx_fresnel_dielectric(cosTheta, fd.ior.x));
    if (fd.model == FRESNEL_MODEL_CONDUCTOR)
        return mx_fresnel_conductor(cosTheta, fd.ior, fd.extinction);
    return mx_fresnel_f82(cosTheta, fd);
}


// Reading the albedo tables that tools/fit_albedo.py writes: regular grids over [0, 1]^2 with a
// node at both ends, interpolated bilinearly.

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


// Generated by tools/fit_albedo.py from numerical integration of the models' formulas; do not
// edit: change the script and run it again. GGX directional albedo with Schlick's Fresnel.

// (A, B) at alpha = row / 15, mu = column / 15 (mu 0 evaluated at 0.001); 256^2 visible normals each
const float MX_ALBEDO_GGX_SCHLICK[512] = float[512](
    0.005156, 0.988974, 0.291756, 0.708243, 0.511055, 0.488945, 0.672320, 0.327680,
    0.787916, 0.212084, 0.868313, 0.131687, 0.922240, 0.077760, 0.956849, 0.043151,
    0.977867, 0.022133, 0.989760, 0.010240, 0.995885, 0.004115, 0.998652, 0.001348,
    0.999680, 0.000320, 0.999958, 0.000042, 0.999999, 0.000001, 1.000000, 0.000000,
    0.503389, 0.493339, 0.473406, 0.414102, 0.567321, 0.341221, 0.681307, 0.258590,
    0.778379, 0.181799, 0.852089, 0.120130, 0.904671, 0.074861, 0.940370, 0.043819,
    0.963447, 0.023854, 0.977590, 0.011883, 0.985782, 0.005290, 0.990228, 0.002029,
    0.992539, 0.000637, 0.993892, 0.000158, 0.994541, 0.000028, 0.995782, 0.000004,
    0.672243, 0.325751, 0.634868, 0.271328, 0.655251, 0.221747, 0.706550, 0.175051,
    0.766191, 0.131471, 0.821438, 0.093400, 0.867031, 0.062628, 0.901980, 0.039514,
    0.927371, 0.023319, 0.945102, 0.012746, 0.957183, 0.006357, 0.965178, 0.002832,
    0.970441, 0.001094, 0.973954, 0.000351, 0.976290, 0.000087, 0.977831, 0.000010,
    0.762398, 0.235753, 0.722527, 0.193522, 0.717871, 0.156385, 0.734810, 0.123566,
    0.763713, 0.094576, 0.796765, 0.069558, 0.828727, 0.048847, 0.856889, 0.032565,
    0.880219, 0.020476, 0.898809, 0.012038, 0.913172, 0.006538, 0.924040, 0.003224,
    0.932226, 0.001406, 0.938598, 0.000519, 0.943550, 0.000147, 0.947691, 0.000021,
    0.817295, 0.180716, 0.771287, 0.145705, 0.754493, 0.116435, 0.753500, 0.091511,
    0.762887, 0.070286, 0.778328, 0.052407, 0.796527, 0.037694, 0.815046, 0.025985,
    0.832427, 0.017046, 0.848019, 0.010550, 0.861472, 0.006090, 0.872883, 0.003225,
    0.882531, 0.001528, 0.890678, 0.000619, 0.897628, 0.000193, 0.903673, 0.000030,
    0.853318, 0.144428, 0.798804, 0.114187, 0.773373, 0.090174, 0.761284, 0.070365,
    0.758144, 0.053942, 0.761144, 0.040404, 0.768085, 0.029402, 0.777264, 0.020662,
    0.787456, 0.013923, 0.797877, 0.008921, 0.807959, 0.005375, 0.817472, 0.002996,
    0.826289, 0.001508, 0.834397, 0.000655, 0.841852, 0.000221, 0.848691, 0.000037,
    0.878183, 0.119230, 0.813860, 0.092332, 0.780849, 0.072008, 0.760611, 0.055726,
    0.748652, 0.042536, 0.742590, 0.031864, 0.740780, 0.023308, 0.741985, 0.016555,
    0.745267, 0.011344, 0.749919, 0.007438, 0.755421, 0.004616, 0.761414, 0.002671,
    0.767650, 0.001406, 0.773974, 0.000644, 0.780287, 0.000231, 0.786516, 0.000043,
    0.895998, 0.101039, 0.821181, 0.076555, 0.780957, 0.058934, 0.753913, 0.045199,
    0.735060, 0.034303, 0.722010, 0.025638, 0.713316, 0.018780, 0.707944, 0.013414,
    0.705108, 0.009286, 0.704244, 0.006182, 0.704876, 0.003918, 0.706663, 0.002328,
    0.709342, 0.001268, 0.712701, 0.000605, 0.716585, 0.000229, 0.720871, 0.000046,
    0.909136, 0.087498, 0.823490, 0.064794, 0.776231, 0.049218, 0.743071, 0.037387,
    0.718401, 0.028187, 0.699654, 0.020987, 0.685360, 0.015360, 0.674526, 0.010998,
    0.666464, 0.007659, 0.660646, 0.005150, 0.656664, 0.003312, 0.654198, 0.002007,
    0.652990, 0.001121, 0.652833, 0.000554, 0.653565, 0.000219, 0.655037, 0.000047,
    0.919051, 0.077161, 0.822444, 0.055791, 0.768321, 0.041802, 0.729462, 0.031438,
    0.699627, 0.023531, 0.676006, 0.017436, 0.657000, 0.012732, 0.641595, 0.009119,
    0.629094, 0.006371, 0.618983, 0.004312, 0.610873, 0.002801, 0.604461, 0.001723,
    0.599496, 0.000981, 0.595784, 0.000497, 0.593156, 0.000204, 0.591477, 0.000047,
    0.926674, 0.069103, 0.819102, 0.048740, 0.758281, 0.036010, 0.714037, 0.026805,
    0.679506, 0.019910, 0.651581, 0.014673, 0.628518, 0.010679, 0.609231, 0.007641,
    0.592971, 0.005345, 0.579208, 0.003633, 0.567543, 0.002377, 0.557666, 0.001477,
    0.549333, 0.000854, 0.542346, 0.000442, 0.536539, 0.000188, 0.531776, 0.000046,
    0.932625, 0.062707, 0.814165, 0.043110, 0.746813, 0.031399, 0.697461, 0.023129,
    0.658606, 0.017042, 0.626831, 0.012485, 0.600231, 0.009051, 0.577618, 0.006463,
    0.558180, 0.004522, 0.541349, 0.003080, 0.526698, 0.002025, 0.513900, 0.001269,
    0.502702, 0.000743, 0.492897, 0.000391, 0.484316, 0.000170, 0.476813, 0.000044,
    0.937329, 0.057550, 0.808136, 0.038537, 0.734418, 0.027664, 0.680236, 0.020162,
    0.637379, 0.014735, 0.602132, 0.010728, 0.572423, 0.007743, 0.546946, 0.005514,
    0.524830, 0.003854, 0.505451, 0.002628, 0.488345, 0.001734, 0.473165, 0.001093,
    0.459637, 0.000646, 0.447540, 0.000345, 0.436697, 0.000153, 0.426963, 0.000042,
    0.941086, 0.053335, 0.801325, 0.034766, 0.721465, 0.024594, 0.662706, 0.017732,
    0.616142, 0.012852, 0.577761, 0.009297, 0.545311, 0.006678, 0.517384, 0.004741,
    0.493023, 0.003309, 0.471555, 0.002257, 0.452479, 0.001492, 0.435416, 0.000945,
    0.420069, 0.000562, 0.406204, 0.000304, 0.393628, 0.000138, 0.382186, 0.000039,
    0.944111, 0.049847, 0.793962, 0.031616, 0.708198, 0.022037, 0.645103, 0.015718,
    0.595122, 0.011297, 0.553921, 0.008119, 0.519072, 0.005803, 0.489050, 0.004105,
    0.462829, 0.002859, 0.439678, 0.001949, 0.419058, 0.001290, 0.400558, 0.000820,
    0.383860, 0.000491, 0.368708, 0.000268, 0.354896, 0.000123, 0.342259, 0.000036,
    0.946562, 0.046929, 0.786219, 0.028952, 0.694780, 0.019882, 0.627619, 0.014027,
    0.574500, 0.009998, 0.530767, 0.007138, 0.493821, 0.005076, 0.462023, 0.003577,
    0.434288, 0.002486, 0.409811, 0.001694, 0.388015, 0.001122, 0.368471, 0.000714,
    0.350827, 0.000430, 0.334811, 0.000236, 0.320197, 0.000110, 0.306821, 0.000034);


// Albedo = F0 A + F90 B of the GGX lobe at view cosine mu and isotropic alpha.
vec2 mx_ggx_albedo_schlick_scale_bias(float mu, float roughness)
{
    vec4 c = mx_albedo_cell(vec2(mu, roughness), vec2(16.0, 16.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix(vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 0), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 0), 16) + 1]), vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 0), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 0), 16) + 1]), c.z),
               mix(vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 1), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(0, 1), 16) + 1]), vec2(MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 1), 16)], MX_ALBEDO_GGX_SCHLICK[2 * mx_albedo_index(i + ivec2(1, 1), 16) + 1]), c.z), c.w);
}


// GGX (Trowbridge-Reitz) microfacets after Walter et al. 2007, with Smith masking-shadowing in
// Heitz 2014's height-correlated form, visible-normal sampling, and multiple-scattering energy
// compensation from our own albedo table (tools/fit_albedo.py; Kulla & Conty 2017, Turquin 2019).
// Directions are in the tangent frame: x along the tangent, z along the normal; alpha = (alpha_x,
// alpha_y) is the roughness along x and y.


// Smallest alpha the lobe uses: a mirror to 1e-4, without the overflow of D at alpha -> 0.
const float MX_GGX_MIN_ALPHA = 1.0e-4;


vec2 mx_ggx_clamp_alpha(vec2 alpha)
{
    return clamp(alpha, MX_GGX_MIN_ALPHA, 1.0);
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


// What a light direction sampled through a visible normal carries, f cos / pdf with F = 1:
// G2 / G1 (Heitz 2014, sect. 5.3), 0 below the horizon.
float mx_ggx_sample_weight(vec3 V, vec3 L, vec2 alpha)
{
    if (L.z <= 0.0)
        return 0.0;
    float lambdaV = mx_ggx_lambda(V, alpha);
    return (1.0 + lambdaV) / (1.0 + lambdaV + mx_ggx_lambda(L, alpha));
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


// The lat-long environment map: lookups along world directions, shared by the two ways of lighting
// with it (mx_environment_fis.glsl, mx_environment_prefilter.glsl).
//
// Map convention: texel (u, v) with v = 0 the top row holds map direction
// (cos(lat) sin(lon), sin(lat), -cos(lat) cos(lon)), lat = (0.5 - v) pi, lon = (u - 0.5) 2 pi.

vec2 mx_envmap_uv(vec3 dir)
{
    return vec2(atan(dir.x, -dir.z) * MX_INV_PI * 0.5 + 0.5, 0.5 - asin(dir.y) * MX_INV_PI);
}


// The map `envMap` seen along world direction `dir`, at mip level `lod`.
vec3 mx_envmap_fetch(sampler2D envMap, vec3 dir, float lod)
{
    vec3 mapDir = normalize((u_envMatrix * vec4(dir, 0.0)).xyz);
    return textureLod(envMap, mx_envmap_uv(mapDir), lod).rgb;
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


// Split-sum DFG table of GGX: the BRDF's directional albedo for any Fresnel F is
// w1 F(c1) + w2 F(c2), a two-point Gauss quadrature in VdotH. Written by tools/fit_dfg.py
// (numerical integration over GGX visible normals, Heitz 2018, with Smith height-correlated
// masking-shadowing, Heitz 2014); do not edit by hand.
// Rows: sqrt(NdotV) = i / 15; columns: roughness = sqrt(alpha) = j / 15.

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


// Image-based lighting from a prefiltered environment, by the split sum (Karis 2013, "Real Shading
// in Unreal Engine 4"): the radiance map convolved with the GGX lobe per roughness (computed by the
// renderer, shadergen/render/prefilter.py, with N = V = R), times the BRDF's directional albedo
// from our DFG table (mx_environment_dfg.glsl, tools/fit_dfg.py). One lookup instead of
// u_envRadianceSamples; used when the shader is compiled with MX_ENV_PREFILTER defined, and then
// u_envRadiance must hold the prefiltered chain.



// Mip level of the prefiltered chain holding the GGX lobe of `alpha`: level 0 is the unfiltered
// map, level l >= 1 the lobe of alpha = 2^(l + 4 - u_envRadianceMips) up to alpha 1 (texels about
// as wide as the lobe), in between the chain's trilinear filtering blends neighbouring lobes.
float mx_prefiltered_lod(float alpha)
{
    float roughest = max(float(u_envRadianceMips - 4), 1.0);
    float firstAlpha = exp2(1.0 - roughest);
    return alpha < firstAlpha ? alpha / firstAlpha : min(log2(alpha) + roughest, roughest);
}


// Light leaving a point with normal N towards V after one GGX bounce of roughness alpha, or, with
// fd.refraction, after passing through a solid sphere of index fd.ior.x; `albedo` as
// mx_environment_radiance() gives it. The lobe's directional albedo comes from the DFG table's
// quadrature rule, with F (reflection, times Turquin's multiple-scattering factor 1 + F (1 - E) / E
// as the sampled path applies it) or with 1 - F averaged over the lobe (refraction).
vec3 mx_environment_prefiltered_radiance(vec3 N, vec3 V, vec2 alpha, FresnelData fd, out vec3 albedo)
{
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float avgAlpha = clamp(sqrt(alpha.x * alpha.y), 0.0, 1.0);
    vec4 rule = mx_environment_dfg_rule(NdotV, avgAlpha);
    vec3 reflected = rule.z * mx_fresnel_eval(rule.x, fd) + rule.w * mx_fresnel_eval(rule.y, fd);
    float E = max(rule.z + rule.w, MX_EPS);  // the albedo with F = 1
    vec3 L;
    if (fd.refraction)
    {
        albedo = vec3(1.0) - reflected / E;
        L = mx_refraction_solid_sphere(-V, N, fd.ior.x);
    }
    else
    {
        albedo = reflected * (vec3(1.0) + mx_fresnel_eval(NdotV, fd) * ((1.0 - E) / E));
        L = reflect(-V, N);
    }
    return mx_envmap_fetch(u_envRadiance, L, mx_prefiltered_lod(avgAlpha)) * albedo * u_envLightIntensity;
}


// Image-based lighting from a lat-long environment map, by filtered importance sampling (Krivanek
// & Colbert 2008): GGX visible normals drawn from a spherical Fibonacci set, each environment
// sample fetched from the mip level whose texel covers the sample's solid angle. A shader compiled
// with MX_ENV_PREFILTER defined reads a prefiltered map instead (mx_environment_prefilter.glsl).
//
// Uniforms (declared by the generator with the surface node): u_envRadiance (mipmapped radiance),
// u_envIrradiance (irradiance / pi), u_envMatrix (world -> map direction), u_envRadianceMips (levels
// in the radiance map's mip chain), u_envRadianceSamples, u_envLightIntensity.



// Mip level for a sample of density `pdf` along world direction `dir` (GPU Gems 3, 20.4, eq. 13),
// with the lat-long map's stretching towards the poles, biased 1.5 levels sharper.
float mx_envmap_lod(vec3 dir, float pdf, int sampleCount)
{
    float coarsest = float(u_envRadianceMips - 1) - 1.5;
    float stretch = sqrt(1.0 - dir.y * dir.y);
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
// what a layer below must not receive again.
vec3 mx_environment_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, out vec3 albedo)
{
#ifdef MX_ENV_PREFILTER
    return mx_environment_prefiltered_radiance(N, V, alpha, fd, albedo);
#else
    albedo = vec3(0.0);
    int sampleCount = u_envRadianceSamples;
    if (sampleCount <= 0)
        return vec3(0.0);

    mat3 frame = mx_tangent_frame(N, X);
    vec3 Vt = V * frame;  // (V.X, V.Y, V.N)
    Vt.z = max(Vt.z, MX_EPS);

    vec3 carried = vec3(0.0);
    float whiteAlbedo = 0.0;
    for (int i = 0; i < sampleCount; i++)
    {
        vec3 H = mx_ggx_sample_visible_normal(mx_fibonacci_point(i, sampleCount), Vt, alpha);
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
        vec3 Lw = frame * Lt;
        float lod = mx_envmap_lod(Lw, mx_ggx_reflection_pdf(H, Vt, alpha), sampleCount);
        vec3 Li = mx_envmap_fetch(u_envRadiance, Lw, lod);
        vec3 F = mx_fresnel_eval(clamp(dot(Vt, H), MX_EPS, 1.0), fd);
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
        vec3 compensation = vec3(1.0) + mx_fresnel_eval(Vt.z, fd) * ((1.0 - E) / max(E, MX_EPS));
        carried *= compensation;
        albedo *= compensation;
    }
    albedo *= scale;
    return carried * (scale * u_envLightIntensity);
#endif
}


// Transmission rendered by refraction: what is seen through the surface is the environment,
// refracted through a solid sphere of the surface's index; scene geometry behind is ignored.

vec3 mx_surface_transmission(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, vec3 tint)
{
    fd.refraction = true;
    // A two-sided interface filters the light twice.
    vec3 through = u_refractionTwoSided ? tint * tint : tint;
    vec3 transmitted;
    return mx_environment_radiance(N, V, X, alpha, distribution, fd, transmitted) * through;
}


// The GGX reflection lobe shared by the specular closures (dielectric, conductor, generalized
// Schlick, and the environment term of hair).


// The fraction of light arriving with `cosine` that the lobe reflects, multiple scattering
// included, from its single-scattering albedo there (the caller's table value).
vec3 mx_specular_albedo(float cosine, vec2 alpha, FresnelData fd, vec3 singleScatteringAlbedo)
{
    float c = clamp(cosine, MX_EPS, 1.0);
    return singleScatteringAlbedo * mx_ggx_energy_compensation(c, mx_ggx_isotropic_alpha(alpha), mx_fresnel_eval(c, fd));
}


// The lobe with Fresnel `fd` in the current closure context, multiple scattering included.
// `albedo` returns the fraction of light the lobe reflects at this view, which a layer below does
// not receive: in INDIRECT the sampled value that matches the radiance, elsewhere
// `singleScatteringAlbedo` (the caller's table value) with the compensation at the view angle.
//   REFLECTION    D F G2 / (4 NdotV) towards closureData.L (the light's cosine cancels against the
//                 BRDF's), F and the compensation taken at the half vector.
//   INDIRECT      the environment by filtered importance sampling, compensated there.
//   other         no light.
// N must face V; alpha is the clamped roughness pair.
vec3 mx_specular_lobe(ClosureData closureData, vec3 N, vec3 V, vec3 X, vec2 alpha, FresnelData fd,
                      vec3 singleScatteringAlbedo, out vec3 albedo)
{
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
        return mx_environment_radiance(N, V, X, alpha, 0, fd, albedo);

    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    albedo = mx_specular_albedo(NdotV, alpha, fd, singleScatteringAlbedo);
    if (closureData.closureType != CLOSURE_TYPE_REFLECTION)
        return vec3(0.0);

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


// Generated by tools/fit_albedo.py from numerical integration of the models' formulas; do not
// edit: change the script and run it again. GGX dielectric reflection albedo.

// [eta = 1 + 2 t, t = slab / 7][alpha = row / 7][mu = column / 15]
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
    0.987370, 0.648936, 0.425039, 0.280733, 0.187072, 0.126011, 0.086111, 0.060035,
    0.043041, 0.032041, 0.025012, 0.020620, 0.017983, 0.016512, 0.015814, 0.015625,
    0.283970, 0.232344, 0.188672, 0.151165, 0.118709, 0.091530, 0.069776, 0.053066,
    0.040666, 0.031732, 0.025474, 0.021221, 0.018441, 0.016723, 0.015769, 0.015349,
    0.161097, 0.129790, 0.105347, 0.085711, 0.069779, 0.056821, 0.046319, 0.037884,
    0.031205, 0.026011, 0.022058, 0.019129, 0.017032, 0.015597, 0.014685, 0.014177,
    0.111990, 0.087912, 0.070864, 0.057779, 0.047511, 0.039371, 0.032891, 0.027729,
    0.023632, 0.020401, 0.017881, 0.015946, 0.014492, 0.013435, 0.012703, 0.012236,
    0.087234, 0.066352, 0.052879, 0.042978, 0.035431, 0.029571, 0.024975, 0.021347,
    0.018477, 0.016207, 0.014418, 0.013017, 0.011933, 0.011107, 0.010494, 0.010056,
    0.073002, 0.053596, 0.042110, 0.033998, 0.027975, 0.023385, 0.019828, 0.017041,
    0.014841, 0.013095, 0.011705, 0.010599, 0.009719, 0.009022, 0.008475, 0.008048,
    0.064071, 0.045296, 0.035020, 0.028019, 0.022942, 0.019135, 0.016216, 0.013943,
    0.012150, 0.010722, 0.009577, 0.008652, 0.007901, 0.007288, 0.006787, 0.006377,
    0.058098, 0.039506, 0.030019, 0.023763, 0.019320, 0.016036, 0.013541, 0.011607,
    0.010085, 0.008871, 0.007891, 0.007092, 0.006436, 0.005891, 0.005436, 0.005053,
    0.988236, 0.691001, 0.487515, 0.350168, 0.255885, 0.190459, 0.144794, 0.112882,
    0.090657, 0.075311, 0.064880, 0.057972, 0.053590, 0.051020, 0.049743, 0.049383,
    0.338173, 0.285274, 0.242078, 0.205236, 0.172501, 0.143813, 0.119584, 0.099893,
    0.084425, 0.072639, 0.063920, 0.057681, 0.053399, 0.050637, 0.049055, 0.048355,
    0.213729, 0.179214, 0.152463, 0.130843, 0.113084, 0.098360, 0.086119, 0.075977,
    0.067667, 0.060964, 0.055674, 0.051615, 0.048614, 0.046509, 0.045156, 0.044418,
    0.161550, 0.132972, 0.112825, 0.097160, 0.084657, 0.074550, 0.066332, 0.059639,
    0.054201, 0.049810, 0.046305, 0.043554, 0.041449, 0.039899, 0.038824, 0.038154,
    0.134363, 0.107921, 0.090831, 0.078050, 0.068092, 0.060173, 0.053805, 0.048649,
    0.044464, 0.041068, 0.038324, 0.036122, 0.034377, 0.033020, 0.031992, 0.031248,
    0.118348, 0.092420, 0.076877, 0.065636, 0.057061, 0.050333, 0.044959, 0.040616,
    0.037076, 0.034176, 0.031791, 0.029829, 0.028216, 0.026894, 0.025817, 0.024947,
    0.108106, 0.081906, 0.067172, 0.056816, 0.049056, 0.043033, 0.038251, 0.034389,
    0.031232, 0.028623, 0.026450, 0.024627, 0.023090, 0.021787, 0.020678, 0.019732,
    0.101151, 0.074278, 0.059962, 0.050147, 0.042904, 0.037337, 0.032940, 0.029397,
    0.026498, 0.024094, 0.022076, 0.020369, 0.018910, 0.017655, 0.016566, 0.015617,
    0.988277, 0.698443, 0.505367, 0.376962, 0.289192, 0.228042, 0.184914, 0.154311,
    0.132589, 0.117267, 0.106608, 0.099377, 0.094677, 0.091852, 0.090414, 0.090000,
    0.365610, 0.311420, 0.269358, 0.234961, 0.205015, 0.178848, 0.156584, 0.138258,
    0.123635, 0.112295, 0.103751, 0.097520, 0.093166, 0.090314, 0.088681, 0.087981,
    0.248024, 0.211730, 0.184399, 0.162789, 0.145394, 0.131217, 0.119582, 0.110015,
    0.102207, 0.095913, 0.090942, 0.087130, 0.084321, 0.082376, 0.081172, 0.080587,
    0.198501, 0.167195, 0.145651, 0.129088, 0.115988, 0.105488, 0.097019, 0.090176,
    0.084661, 0.080244, 0.076751, 0.074042, 0.072004, 0.070545, 0.069583, 0.069051,
    0.172544, 0.142357, 0.123183, 0.108900, 0.097780, 0.088930, 0.081801, 0.076019,
    0.071315, 0.067492, 0.064398, 0.061913, 0.059945, 0.058418, 0.057270, 0.056449,
    0.157163, 0.126488, 0.108232, 0.094991, 0.084826, 0.076784, 0.070299, 0.065003,
    0.060637, 0.057017, 0.054002, 0.051487, 0.049390, 0.047645, 0.046199, 0.045008,
    0.147271, 0.115355, 0.097335, 0.084545, 0.074843, 0.067209, 0.061057, 0.056011,
    0.051815, 0.048288, 0.045298, 0.042743, 0.040548, 0.038650, 0.037004, 0.035569,
    0.140516, 0.107003, 0.088878, 0.076251, 0.066775, 0.059362, 0.053402, 0.048510,
    0.044433, 0.040987, 0.038043, 0.035504, 0.033295, 0.031359, 0.029650, 0.028134,
    0.988059, 0.695043, 0.508811, 0.389202, 0.309451, 0.254798, 0.216621, 0.189638,
    0.170473, 0.156894, 0.147379, 0.140861, 0.136576, 0.133969, 0.132624, 0.132231,
    0.383471, 0.327996, 0.287132, 0.255496, 0.229046, 0.206468, 0.187476, 0.171919,
    0.159514, 0.149876, 0.142588, 0.137250, 0.133507, 0.131053, 0.129681, 0.129139,
    0.275047, 0.237448, 0.210060, 0.189046, 0.172667, 0.159747, 0.149471, 0.141251,
    0.134711, 0.129554, 0.125571, 0.122593, 0.120471, 0.119083, 0.118323, 0.118090,
    0.229933, 0.196543, 0.174184, 0.157287, 0.144143, 0.133789, 0.125593, 0.119105,
    0.113991, 0.109996, 0.106926, 0.104628, 0.102981, 0.101886, 0.101261, 0.101037,
    0.206397, 0.173174, 0.152484, 0.137208, 0.125388, 0.116030, 0.108529, 0.102476,
    0.097578, 0.093621, 0.090441, 0.087909, 0.085924, 0.084405, 0.083285, 0.082510,
    0.192469, 0.157783, 0.137353, 0.122562, 0.111195, 0.102177, 0.094878, 0.088888,
    0.083925, 0.079784, 0.076314, 0.073399, 0.070949, 0.068892, 0.067172, 0.065739,
    0.183505, 0.146624, 0.125825, 0.110999, 0.099681, 0.090708, 0.083414, 0.077376,
    0.072306, 0.068001, 0.064311, 0.061124, 0.058353, 0.055931, 0.053803, 0.051926,
    0.177373, 0.137980, 0.116517, 0.101431, 0.089997, 0.080959, 0.073614, 0.067518,
    0.062381, 0.057991, 0.054199, 0.050892, 0.047985, 0.045410, 0.043115, 0.041057,
    0.987721, 0.687123, 0.506440, 0.395458, 0.324042, 0.276443, 0.243887, 0.221220,
    0.205281, 0.194050, 0.186194, 0.180806, 0.177251, 0.175074, 0.173944, 0.173611,
    0.396885, 0.340220, 0.300583, 0.271755, 0.248941, 0.230208, 0.214838, 0.202460,
    0.192706, 0.185193, 0.179550, 0.175443, 0.172584, 0.170734, 0.169761, 0.169448,
    0.298232, 0.259577, 0.232346, 0.212134, 0.196978, 0.185531, 0.176844, 0.170212,
    0.165183, 0.161407, 0.158643, 0.156712, 0.155464, 0.154786, 0.154589, 0.154787,
    0.258049, 0.222908, 0.199992, 0.182992, 0.170016, 0.160007, 0.152273, 0.146319,
    0.141777, 0.138366, 0.135869, 0.134121, 0.132986, 0.132362, 0.132161, 0.132314,
    0.237307, 0.201441, 0.179513, 0.163476, 0.151160, 0.141476, 0.133766, 0.127589,
    0.122631, 0.118663, 0.115508, 0.113027, 0.111114, 0.109680, 0.108654, 0.107979,
    0.225098, 0.186839, 0.164527, 0.148418, 0.136042, 0.126215, 0.118246, 0.111691,
    0.106243, 0.101681, 0.097845, 0.094607, 0.091873, 0.089565, 0.087622, 0.085991,
    0.217256, 0.175889, 0.152609, 0.135977, 0.123230, 0.113074, 0.104770, 0.097854,
    0.092007, 0.087008, 0.082693, 0.078937, 0.075648, 0.072749, 0.070183, 0.067901,
    0.211890, 0.167131, 0.142639, 0.125322, 0.112110, 0.101593, 0.092983, 0.085786,
    0.079676, 0.074416, 0.069839, 0.065820, 0.062263, 0.059091, 0.056244, 0.053677,
    0.987315, 0.677156, 0.501647, 0.399157, 0.335982, 0.295385, 0.268449, 0.250153,
    0.237532, 0.228764, 0.222689, 0.218545, 0.215817, 0.214146, 0.213275, 0.213018,
    0.407923, 0.350199, 0.311814, 0.285754, 0.266516, 0.251576, 0.239807, 0.230617,
    0.223554, 0.218228, 0.214306, 0.211507, 0.209605, 0.208420, 0.207887, 0.207825,
    0.318987, 0.279439, 0.252462, 0.233114, 0.219218, 0.209266, 0.202184, 0.197158,
    0.193666, 0.191301, 0.189791, 0.188946, 0.188608, 0.188674, 0.189066, 0.189712,
    0.283765, 0.247084, 0.223741, 0.206733, 0.194000, 0.184396, 0.177173, 0.171796,
    0.167864, 0.165071, 0.163180, 0.162010, 0.161415, 0.161285, 0.161528, 0.162071,
    0.265855, 0.227608, 0.204603, 0.187926, 0.175210, 0.165279, 0.157428, 0.151187,
    0.146221, 0.142287, 0.139196, 0.136803, 0.134991, 0.133669, 0.132760, 0.132204,
    0.255398, 0.213883, 0.189877, 0.172591, 0.159321, 0.148779, 0.140221, 0.133169,
    0.127297, 0.122369, 0.118213, 0.114696, 0.111715, 0.109189, 0.107053, 0.105251,
    0.248708, 0.203220, 0.177676, 0.159398, 0.145349, 0.134115, 0.124891, 0.117173,
    0.110617, 0.104984, 0.100096, 0.095820, 0.092054, 0.088717, 0.085747, 0.083091,
    0.244132, 0.194423, 0.167141, 0.147769, 0.132918, 0.121036, 0.111258, 0.103041,
    0.096028, 0.089961, 0.084655, 0.079974, 0.075810, 0.072081, 0.068720, 0.065677,
    0.986869, 0.666308, 0.495994, 0.401858, 0.346646, 0.312739, 0.291146, 0.277000,
    0.267540, 0.261133, 0.256781, 0.253856, 0.251948, 0.250785, 0.250179, 0.250000,
    0.417558, 0.358919, 0.321806, 0.298433, 0.282623, 0.271298, 0.262949, 0.256788,
    0.252286, 0.249050, 0.246781, 0.245248, 0.244279, 0.243749, 0.243652, 0.243838,
    0.337997, 0.297677, 0.270999, 0.252509, 0.239832, 0.231314, 0.225763, 0.222268,
    0.220240, 0.219222, 0.218913, 0.219110, 0.219651, 0.220436, 0.221399, 0.222479,
    0.307547, 0.269479, 0.245779, 0.228800, 0.216322, 0.207121, 0.200396, 0.195578,
    0.192235, 0.190037, 0.188730, 0.188118, 0.188046, 0.188394, 0.189065, 0.189985,
    0.292359, 0.251932, 0.227954, 0.210706, 0.197639, 0.187494, 0.179527, 0.173239,
    0.168278, 0.164387, 0.161368, 0.159067, 0.157362, 0.156155, 0.155364, 0.154927,
    0.283588, 0.239071, 0.213510, 0.195145, 0.181055, 0.169858, 0.160761, 0.153255,
    0.146995, 0.141732, 0.137285, 0.133513, 0.130308, 0.127584, 0.125273, 0.123315,
    0.278006, 0.228706, 0.201068, 0.181269, 0.166017, 0.153784, 0.143709, 0.135248,
    0.128035, 0.121814, 0.116395, 0.111636, 0.107428, 0.103686, 0.100342, 0.097338,
    0.274191, 0.219891, 0.190023, 0.168744, 0.152370, 0.139220, 0.128355, 0.119190,
    0.111338, 0.104519, 0.098534, 0.093236, 0.088508, 0.084259, 0.080418, 0.076930);


// the same with eta = 1 / (1 + 2 t): from the dense side
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
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 0.166899, 0.054413, 0.027818, 0.019104, 0.016230, 0.015625,
    0.874289, 0.819030, 0.803148, 0.810167, 0.823503, 0.832941, 0.831611, 0.810235,
    0.746734, 0.593111, 0.347604, 0.160519, 0.072921, 0.035993, 0.020556, 0.015801,
    0.759724, 0.709458, 0.676208, 0.651990, 0.631782, 0.610552, 0.582279, 0.539817,
    0.475457, 0.385102, 0.277522, 0.175515, 0.098685, 0.050297, 0.024197, 0.015296,
    0.660963, 0.598752, 0.554330, 0.516522, 0.481352, 0.445896, 0.407658, 0.364224,
    0.314314, 0.257824, 0.197725, 0.139195, 0.088148, 0.048897, 0.023469, 0.013756,
    0.580267, 0.505814, 0.453548, 0.409345, 0.369286, 0.331306, 0.293885, 0.256219,
    0.217739, 0.178748, 0.139970, 0.102788, 0.069037, 0.040775, 0.020301, 0.011656,
    0.516303, 0.432073, 0.375134, 0.328944, 0.288632, 0.252278, 0.218618, 0.186960,
    0.156843, 0.128129, 0.100878, 0.075395, 0.052198, 0.032124, 0.016613, 0.009531,
    0.466538, 0.374347, 0.315367, 0.269041, 0.230299, 0.196829, 0.167244, 0.140683,
    0.116560, 0.094535, 0.074354, 0.055957, 0.039375, 0.024886, 0.013284, 0.007667,
    0.427257, 0.329330, 0.269379, 0.223964, 0.187420, 0.156967, 0.131013, 0.108538,
    0.088874, 0.071491, 0.056027, 0.042254, 0.029994, 0.019293, 0.010554, 0.006139,
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 0.190571, 0.071603, 0.052419, 0.049383,
    0.932520, 0.862773, 0.840074, 0.845203, 0.860496, 0.876302, 0.888430, 0.894934,
    0.893603, 0.878745, 0.832677, 0.698471, 0.413183, 0.181952, 0.089947, 0.057470,
    0.869084, 0.808227, 0.770900, 0.747521, 0.733409, 0.724565, 0.717054, 0.706974,
    0.689336, 0.657269, 0.600028, 0.504783, 0.371685, 0.233583, 0.130105, 0.067226,
    0.809603, 0.737645, 0.690647, 0.654488, 0.624849, 0.598921, 0.574276, 0.548217,
    0.517995, 0.480240, 0.431463, 0.369054, 0.293725, 0.211992, 0.134651, 0.069694,
    0.755831, 0.668811, 0.611690, 0.566173, 0.527346, 0.492439, 0.459421, 0.426760,
    0.392996, 0.356799, 0.317088, 0.272771, 0.224092, 0.172025, 0.118549, 0.065134,
    0.708411, 0.606607, 0.540804, 0.488691, 0.444548, 0.405311, 0.369551, 0.335691,
    0.302847, 0.270610, 0.237995, 0.204665, 0.170285, 0.134616, 0.097352, 0.057114,
    0.667333, 0.552244, 0.479658, 0.423220, 0.376398, 0.335869, 0.300148, 0.267559,
    0.237480, 0.209180, 0.182190, 0.156049, 0.130327, 0.104528, 0.077773, 0.048092,
    0.632172, 0.505310, 0.427861, 0.368829, 0.321037, 0.281012, 0.246445, 0.216041,
    0.188976, 0.164411, 0.141860, 0.120847, 0.100886, 0.081466, 0.061675, 0.039756,
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.198589, 0.098369, 0.090000,
    0.956704, 0.880042, 0.853903, 0.857476, 0.872459, 0.888942, 0.902918, 0.912996,
    0.918637, 0.918459, 0.908469, 0.874486, 0.759831, 0.449335, 0.194725, 0.113855,
    0.916038, 0.848835, 0.808328, 0.783714, 0.770110, 0.763552, 0.760737, 0.758494,
    0.753808, 0.742684, 0.718810, 0.670467, 0.578554, 0.430927, 0.267242, 0.152268,
    0.876665, 0.798400, 0.748932, 0.712282, 0.684006, 0.661088, 0.641489, 0.623059,
    0.603420, 0.579695, 0.548364, 0.504434, 0.442378, 0.359889, 0.262925, 0.169409,
    0.839611, 0.745215, 0.685268, 0.638944, 0.600778, 0.567847, 0.538152, 0.510017,
    0.482051, 0.452632, 0.420122, 0.382593, 0.338419, 0.286171, 0.226569, 0.163600,
    0.805422, 0.694179, 0.624134, 0.569814, 0.524715, 0.485453, 0.450327, 0.417845,
    0.386852, 0.356492, 0.325804, 0.294005, 0.260400, 0.224072, 0.185051, 0.144468,
    0.774337, 0.647051, 0.568153, 0.507460, 0.457798, 0.415250, 0.377661, 0.343864,
    0.312928, 0.283852, 0.256087, 0.229008, 0.202270, 0.175336, 0.148177, 0.122258,
    0.746420, 0.604381, 0.518011, 0.452969, 0.400336, 0.356221, 0.318196, 0.285142,
    0.255322, 0.228347, 0.203632, 0.180641, 0.158863, 0.137956, 0.118118, 0.100688,
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.150928, 0.132231,
    0.969638, 0.889056, 0.861013, 0.863618, 0.878244, 0.894848, 0.909328, 0.920528,
    0.928174, 0.931922, 0.930395, 0.918330, 0.875188, 0.701675, 0.330748, 0.172955,
    0.941474, 0.870357, 0.827823, 0.802189, 0.788455, 0.782623, 0.781457, 0.782189,
    0.782330, 0.779286, 0.769067, 0.744405, 0.689917, 0.577802, 0.399994, 0.236220,
    0.913619, 0.831283, 0.780099, 0.742875, 0.714862, 0.693341, 0.676025, 0.661142,
    0.646756, 0.630688, 0.609796, 0.579953, 0.534661, 0.466919, 0.372628, 0.263794,
    0.886873, 0.787738, 0.725978, 0.679099, 0.641230, 0.609447, 0.581678, 0.556434,
    0.532335, 0.507754, 0.481323, 0.451027, 0.414519, 0.369892, 0.315589, 0.251460,
    0.861586, 0.744391, 0.671878, 0.616400, 0.570938, 0.532136, 0.497960, 0.466933,
    0.437972, 0.409801, 0.382079, 0.353431, 0.323418, 0.291270, 0.256992, 0.219933,
    0.837945, 0.703051, 0.620624, 0.557897, 0.506978, 0.463508, 0.425689, 0.392027,
    0.361254, 0.332686, 0.305524, 0.279779, 0.254275, 0.229795, 0.206277, 0.183491,
    0.816097, 0.664465, 0.573459, 0.505049, 0.450018, 0.404213, 0.364642, 0.330105,
    0.299358, 0.272008, 0.246707, 0.223390, 0.201875, 0.182391, 0.165154, 0.149604,
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.215071, 0.173611,
    0.977426, 0.894413, 0.865168, 0.867205, 0.881558, 0.898168, 0.912886, 0.924563,
    0.933078, 0.938463, 0.940072, 0.935581, 0.915559, 0.829510, 0.484908, 0.229538,
    0.956882, 0.883221, 0.839367, 0.813055, 0.799154, 0.793610, 0.793207, 0.795327,
    0.797910, 0.798714, 0.795122, 0.782361, 0.749735, 0.671740, 0.511017, 0.313998,
    0.936289, 0.851141, 0.798839, 0.761166, 0.733260, 0.712365, 0.696350, 0.683451,
    0.672042, 0.660339, 0.645750, 0.624975, 0.592910, 0.540363, 0.457308, 0.343979,
    0.916227, 0.813780, 0.750847, 0.703593, 0.665948, 0.634861, 0.608376, 0.584950,
    0.563367, 0.542135, 0.520098, 0.495476, 0.466176, 0.429655, 0.382666, 0.322759,
    0.896905, 0.775714, 0.701633, 0.645510, 0.600012, 0.561611, 0.528212, 0.498456,
    0.470875, 0.444904, 0.419525, 0.394131, 0.367998, 0.340650, 0.310801, 0.277359,
    0.878576, 0.738649, 0.654080, 0.590182, 0.538562, 0.494957, 0.457346, 0.423909,
    0.393662, 0.365935, 0.340034, 0.315510, 0.292606, 0.270652, 0.249637, 0.228737,
    0.861301, 0.703483, 0.609485, 0.539333, 0.482964, 0.436099, 0.395869, 0.360952,
    0.330064, 0.302492, 0.277279, 0.254494, 0.234241, 0.216317, 0.200226, 0.186083,
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.372451, 0.213018,
    0.982515, 0.897862, 0.867871, 0.869494, 0.883672, 0.900263, 0.915084, 0.926990,
    0.935982, 0.942200, 0.945347, 0.944445, 0.933946, 0.886963, 0.627825, 0.284158,
    0.966974, 0.891489, 0.846805, 0.820031, 0.805955, 0.800538, 0.800625, 0.803497,
    0.807390, 0.810400, 0.810565, 0.804496, 0.784539, 0.730673, 0.596906, 0.384277,
    0.951159, 0.864038, 0.810931, 0.772982, 0.745161, 0.724623, 0.709354, 0.697748,
    0.688201, 0.679082, 0.668717, 0.654147, 0.631034, 0.590971, 0.520682, 0.410841,
    0.935594, 0.830812, 0.767050, 0.719599, 0.682162, 0.651577, 0.625929, 0.603767,
    0.583921, 0.565056, 0.546194, 0.525964, 0.502485, 0.472487, 0.432351, 0.377692,
    0.920462, 0.796400, 0.721301, 0.664807, 0.619340, 0.581318, 0.548609, 0.519755,
    0.493441, 0.469009, 0.445840, 0.423169, 0.400451, 0.376551, 0.350485, 0.320918,
    0.905930, 0.762468, 0.676502, 0.611957, 0.560049, 0.516405, 0.479057, 0.446026,
    0.416498, 0.389522, 0.364718, 0.341911, 0.320680, 0.300843, 0.281511, 0.262542,
    0.892039, 0.729885, 0.634014, 0.562683, 0.505528, 0.458132, 0.417845, 0.382736,
    0.351933, 0.324359, 0.299896, 0.277941, 0.258645, 0.241418, 0.225915, 0.211597,
    0.994130, 0.999999, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000,
    1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 1.000000, 0.250000,
    0.986002, 0.900268, 0.869701, 0.871099, 0.885111, 0.901710, 0.916567, 0.928640,
    0.937891, 0.944570, 0.948684, 0.949508, 0.943908, 0.915590, 0.735906, 0.335235,
    0.973912, 0.897161, 0.851862, 0.824776, 0.810592, 0.805242, 0.805584, 0.808979,
    0.813701, 0.818102, 0.820658, 0.818625, 0.806475, 0.768701, 0.661053, 0.444971,
    0.961429, 0.872847, 0.819201, 0.781047, 0.753265, 0.732973, 0.718225, 0.707457,
    0.699117, 0.691880, 0.684341, 0.674057, 0.657068, 0.626434, 0.568115, 0.465495,
    0.949035, 0.842537, 0.778221, 0.730640, 0.693287, 0.663094, 0.638060, 0.616833,
    0.598240, 0.581096, 0.564734, 0.547825, 0.528323, 0.503451, 0.469459, 0.420634,
    0.936932, 0.810727, 0.734939, 0.678231, 0.632841, 0.595127, 0.562909, 0.534795,
    0.509469, 0.486438, 0.464923, 0.444547, 0.424285, 0.403084, 0.380065, 0.354009,
    0.925158, 0.779117, 0.692196, 0.627182, 0.575143, 0.531694, 0.494456, 0.461848,
    0.432888, 0.406855, 0.383280, 0.361715, 0.341858, 0.323269, 0.305222, 0.287743,
    0.913818, 0.748519, 0.651304, 0.579264, 0.521642, 0.474071, 0.433630, 0.398642,
    0.367923, 0.340753, 0.316784, 0.295685, 0.277104, 0.260115, 0.244969, 0.231651);


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
// index eta (transmitted side over incident side), eta clamped to [1/3, 3].
float mx_dielectric_albedo(float mu, float alpha, float eta)
{
    bool leaving = eta < 1.0;
    float t = clamp(((leaving ? 1.0 / max(eta, 1.0e-6) : eta) - 1.0) * 0.5, 0.0, 1.0) * 7.0;
    int slab = min(int(t), 6);
    vec4 c = mx_albedo_cell(vec2(mu, alpha), vec2(16.0, 8.0));
    ivec2 i = ivec2(c.xy);
    float low = leaving ? mx_albedo_dielectric_leaving(c, i, slab) : mx_albedo_dielectric_entering(c, i, slab);
    float high = leaving ? mx_albedo_dielectric_leaving(c, i, slab + 1) : mx_albedo_dielectric_entering(c, i, slab + 1);
    return mix(low, high, t - float(slab));
}


// <dielectric_bsdf>: GGX reflection off, and refraction through, a dielectric interface (exact
// dielectric Fresnel), with an optional thin film. scatter_mode: 0 R, 1 T, 2 RT.


void mx_dielectric_bsdf(ClosureData closureData, float weight, vec3 tint, float ior, vec2 roughness, bool retroreflective,
                        float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X, int distribution, int scatter_mode,
                        inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (mx_weight_is_zero(weight) || (scatter_mode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;

    // Retro-reflection mirrors the view about the normal (reflection and environment only).
    N = mx_usable_normal(N, closureData.N);
    vec3 V = (retroreflective && !transmission) ? reflect(-closureData.V, N) : closureData.V;
    N = mx_facing_normal(N, V);
    vec2 alpha = mx_ggx_clamp_alpha(roughness);
    float eta = max(ior, 0.0);
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(eta), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);
    // What the interface reflects, multiple scattering included, does not reach the layers below.
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    float isoAlpha = mx_ggx_isotropic_alpha(alpha);
    float tableAlbedo = mx_dielectric_albedo(NdotV, isoAlpha, eta);
    vec3 reflected;
    vec3 lobe = mx_specular_lobe(closureData, N, V, X, alpha, fd, vec3(tableAlbedo), reflected);
    bsdf.throughput = max(vec3(1.0) - reflected * weight, 0.0);
    if (context == CLOSURE_TYPE_REFLECTION)  // the light crosses the interface on its way in too
    {
        float NdotL = dot(N, closureData.L);
        vec3 reflectedL = mx_specular_albedo(NdotL, alpha, fd, vec3(mx_dielectric_albedo(NdotL, isoAlpha, eta)));
        bsdf.throughput *= max(vec3(1.0) - reflectedL * weight, 0.0);
    }

    vec3 tintRGB = max(tint, 0.0);
    if (!transmission)
        bsdf.response = lobe * tintRGB * weight;
    else if (scatter_mode != 0)
        bsdf.response = mx_surface_transmission(N, V, X, alpha, distribution, fd, tintRGB) * weight;
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
    vec3 geomprop_Nworld_out = normalize(vd.normalWorld);
    vec3 geomprop_Tworld_out = normalize(vd.tangentWorld);
    surfaceshader glass_surface_out = surfaceshader(vec3(0.0), vec3(0.0));
    {
        vec3 N = normalize(vd.normalWorld);
        vec3 V = normalize(u_viewPosition - vd.positionWorld);
        vec3 P = vd.positionWorld;
        vec3 L = vec3(0.0);
        float occlusion = 1.0;
        float surfaceOpacity = 1.0;
        for (int activeLightIndex = 0; activeLightIndex < numActiveLightSources(); ++activeLightIndex)
        {
            lightshader lightShader;
            sampleLightSource(u_lightData[activeLightIndex], vd.positionWorld, lightShader);
            L = lightShader.direction;
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_REFLECTION, L, V, N, P, occlusion);
            BSDF glass_lobe_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, 1.0, vec3(1.0, 1.0, 1.0), 1.45, vec2(0.05, 0.05), false, 0.0, 1.5, geomprop_Nworld_out, geomprop_Tworld_out, 0, 2, glass_lobe_out);
            glass_surface_out.color += lightShader.intensity * glass_lobe_out.response;
        }
        // environment
        {
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_INDIRECT, L, V, N, P, occlusion);
            BSDF glass_lobe_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, 1.0, vec3(1.0, 1.0, 1.0), 1.45, vec2(0.05, 0.05), false, 0.0, 1.5, geomprop_Nworld_out, geomprop_Tworld_out, 0, 2, glass_lobe_out);
            glass_surface_out.color += occlusion * glass_lobe_out.response;
        }
        // transmission, seen along the view direction
        {
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_TRANSMISSION, L, V, N, P, occlusion);
            BSDF glass_lobe_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, 1.0, vec3(1.0, 1.0, 1.0), 1.45, vec2(0.05, 0.05), false, 0.0, 1.5, geomprop_Nworld_out, geomprop_Tworld_out, 0, 2, glass_lobe_out);
            glass_surface_out.color += glass_lobe_out.response;
        }
        glass_surface_out.color *= surfaceOpacity;
        glass_surface_out.transparency = mix(vec3(1.0), glass_surface_out.transparency, surfaceOpacity);
    }
    material Glass_out = glass_surface_out;
    out1 = vec4(Glass_out.color, 1.0);
}
