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
uniform float SR_coated_diffuse_roughness = 0.0;
uniform float SR_coated_metalness = 0.0;
uniform float SR_coated_specular = 1.0;
uniform vec3 SR_coated_specular_color = vec3(1.0, 1.0, 1.0);
uniform float SR_coated_specular_roughness = 0.35;
uniform float SR_coated_specular_IOR = 1.5;
uniform float SR_coated_specular_anisotropy = 0.0;
uniform float SR_coated_specular_rotation = 0.0;
uniform float SR_coated_transmission = 0.0;
uniform vec3 SR_coated_transmission_color = vec3(1.0, 1.0, 1.0);
uniform float SR_coated_transmission_depth = 0.0;
uniform vec3 SR_coated_transmission_scatter = vec3(0.0, 0.0, 0.0);
uniform float SR_coated_transmission_scatter_anisotropy = 0.0;
uniform float SR_coated_transmission_dispersion = 0.0;
uniform float SR_coated_transmission_extra_roughness = 0.0;
uniform float SR_coated_subsurface = 0.0;
uniform vec3 SR_coated_subsurface_color = vec3(1.0, 1.0, 1.0);
uniform vec3 SR_coated_subsurface_radius = vec3(1.0, 1.0, 1.0);
uniform float SR_coated_subsurface_scale = 1.0;
uniform float SR_coated_subsurface_anisotropy = 0.0;
uniform float SR_coated_sheen = 0.0;
uniform vec3 SR_coated_sheen_color = vec3(1.0, 1.0, 1.0);
uniform float SR_coated_sheen_roughness = 0.3;
uniform float SR_coated_coat = 0.8;
uniform vec3 SR_coated_coat_color = vec3(1.0, 1.0, 1.0);
uniform float SR_coated_coat_roughness = 0.05;
uniform float SR_coated_coat_anisotropy = 0.0;
uniform float SR_coated_coat_rotation = 0.0;
uniform float SR_coated_coat_IOR = 1.5;
uniform float SR_coated_coat_affect_color = 0.0;
uniform float SR_coated_coat_affect_roughness = 0.0;
uniform float SR_coated_thin_film_thickness = 0.0;
uniform float SR_coated_thin_film_IOR = 1.5;
uniform float SR_coated_emission = 0.0;
uniform vec3 SR_coated_emission_color = vec3(1.0, 1.0, 1.0);
uniform vec3 SR_coated_opacity = vec3(1.0, 1.0, 1.0);
uniform bool SR_coated_thin_walled = false;
uniform float SR_coated_base = 1.0;
uniform vec3 SR_coated_base_color = vec3(0.1, 0.25, 0.7);
uniform surfaceshader Coated_backsurfaceshader;
uniform displacementshader Coated_displacementshader;

in VertexData
{
    vec3 normalWorld;
    vec3 tangentWorld;
    vec3 positionWorld;
} vd;

out vec4 out1;

// Constants and small helpers shared by the PBR library.

const float MX_PI = 3.1415926535897932;

const float MX_INV_PI = 1.0 / MX_PI;

const float MX_EPS = 1.0e-8;  // floor for cosines and weights, as in MaterialX's hardware shading

float mx_sqr(float x) { return x * x; }

vec2 mx_sqr(vec2 x) { return x * x; }

vec3 mx_sqr(vec3 x) { return x * x; }


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


// Columns (X, Y, N): `X` made orthogonal to the unit normal `N`, then Y = N x X.
mat3 mx_tangent_frame(vec3 N, vec3 X)
{
    vec3 T = normalize(X - N * dot(X, N));
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


// Parameter conversions of the PBR library.

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


ClosureData makeClosureData(int closureType, vec3 L, vec3 V, vec3 N, vec3 P, float occlusion)
{
    return ClosureData(closureType, L, V, N, P, occlusion);
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


// --- Schlick ---------------------------------------------------------------------------------

// mix(F0, F90, (1 - cos)^exponent), the generalised form (exponent 5 is Schlick's).
vec3 mx_fresnel_schlick_exp(float cosTheta, vec3 F0, vec3 F90, float exponent)
{
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    return mix(F0, F90, pow(m, exponent));
}


// Generalised Schlick with Hoffman's F82 tint: the Schlick curve minus a x (1 - x)^6 lobe, whose
// weight puts the curve through F82 at cos = 1/7 (about 82 degrees).
vec3 mx_fresnel_f82(float cosTheta, FresnelData fd)
{
    const float COS_82 = 1.0 / 7.0;
    const float LOBE_AT_82 = 0.0566527795;  // (1/7) (6/7)^6
    float c = clamp(cosTheta, 0.0, 1.0);
    vec3 schlick82 = mix(fd.F0, fd.F90, pow(1.0 - COS_82, fd.exponent));
    vec3 a = schlick82 * (vec3(1.0) - fd.F82) / LOBE_AT_82;
    return mix(fd.F0, fd.F90, pow(1.0 - c, fd.exponent)) - a * (c * mx_pow_6(1.0 - c));
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


// --- Index / reflectance conversions -----------------------------------------------------------

float mx_ior_to_f0(float ior)
{
    return mx_sqr((ior - 1.0) / (ior + 1.0));
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


// --- Thin film (Airy) ------------------------------------------------------------------------

// Spectral sensitivity of the XYZ matching functions to an optical path difference `opd` (metres)
// with phase `shift`: the Fourier-domain Gaussian fits of Belcour & Barla 2017.
vec3 mx_airy_sensitivity(float opd, vec3 shift)
{
    float phase = 2.0 * MX_PI * opd;
    const vec3 VAL = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 POS = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 VAR = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = VAL * sqrt(2.0 * MX_PI * VAR) * cos(POS * phase + shift) * exp(-VAR * phase * phase);
    xyz.x += 9.7470e-14 * sqrt(2.0 * MX_PI * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) *
             exp(-4.5282e+09 * phase * phase);
    return xyz / 1.0685e-7;
}


// One polarisation of the Airy sum: DC term plus AIRY_FRESNEL_ITERATIONS spectral harmonics.
vec3 mx_airy_polarisation(float R12, vec3 R23, vec3 phi, float opd)
{
    float T121 = 1.0 - R12;
    vec3 r123 = max(sqrt(R12 * R23), 0.0);
    vec3 Rdc = (T121 * T121 * R23) / (vec3(1.0) - R12 * R23);
    vec3 total = R12 + Rdc;
    vec3 Cm = Rdc - T121;
    for (int m = 1; m <= AIRY_FRESNEL_ITERATIONS; m++)
    {
        Cm *= r123;
        total += Cm * 2.0 * mx_airy_sensitivity(float(m) * opd, float(m) * phi);
    }
    return total;
}


// Reflectance of a thin film (thickness fd.tf_thickness nm, index fd.tf_ior) in vacuum over the
// base described by `fd` (dielectric, conductor, or generalised Schlick read as a dielectric).
vec3 mx_fresnel_airy(float cosTheta, FresnelData fd)
{
    // CIE XYZ to CIE RGB (illuminant E), columns.
    const mat3 XYZ_TO_RGB = mat3(2.3706743, -0.5138850, 0.0052982,
                                 -0.9000405, 1.4253036, -0.0146949,
                                 -0.4706338, 0.0885814, 1.0093968);
    bool schlick = fd.model == FRESNEL_MODEL_SCHLICK;
    float eta1 = 1.0;
    float eta2 = max(fd.tf_ior, eta1);
    vec3 eta3 = schlick ? mx_f0_to_ior(fd.F0) : fd.ior;
    vec3 kappa3 = schlick ? vec3(0.0) : fd.extinction;
    float cosThetaT = sqrt(1.0 - (1.0 - cosTheta * cosTheta) * mx_sqr(eta1 / eta2));

    // Outer interface (vacuum / film).
    vec2 R12 = (cosThetaT <= 0.0) ? vec2(1.0) : mx_fresnel_dielectric_pol(cosTheta, eta2 / eta1);

    // Inner interface (film / base) and its phase shifts.
    vec3 R23p, R23s, phi23p, phi23s;
    if (schlick)
    {
        vec3 f = mx_fresnel_f82(cosThetaT, fd);
        R23p = 0.5 * f;
        R23s = R23p;
        phi23p = vec3(eta3.x < eta2 ? MX_PI : 0.0, eta3.y < eta2 ? MX_PI : 0.0, eta3.z < eta2 ? MX_PI : 0.0);
        phi23s = phi23p;
    }
    else
    {
        mx_fresnel_conductor_pol(cosThetaT, eta3 / eta2, kappa3 / eta2, R23p, R23s);
        mx_fresnel_conductor_phase(cosThetaT, eta2, eta3, kappa3, phi23p, phi23s);
    }
    float cosBrewster = cos(atan(eta2 / eta1));
    vec2 phi21 = vec2(cosTheta < cosBrewster ? 0.0 : MX_PI, MX_PI);

    float opd = 2.0 * eta2 * cosThetaT * (fd.tf_thickness * 1.0e-9);
    vec3 I = mx_airy_polarisation(R12.x, R23p, phi23p + vec3(phi21.x), opd) +
             mx_airy_polarisation(R12.y, R23s, phi23s + vec3(phi21.y), opd);
    return clamp(XYZ_TO_RGB * (0.5 * I), 0.0, 1.0);
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


// The GGX (Trowbridge-Reitz) microfacet model: distribution, visible-normal sampling, Smith
// masking-shadowing, and the directional albedo used for energy compensation and layering.

// Distribution of normals; `H` in the tangent frame (x along the tangent, z along the normal),
// `alpha` the roughness along x and y.
float mx_ggx_D(vec3 H, vec2 alpha)
{
    vec2 stretched = H.xy / alpha;
    float d = dot(stretched, stretched) + H.z * H.z;
    return 1.0 / (MX_PI * alpha.x * alpha.y * d * d);
}


// A visible normal for the tangent-space view direction V, from the uniform point `u`, by the
// spherical-cap construction of Dupuy & Benyoub 2023.
vec3 mx_ggx_sample_visible_normal(vec2 u, vec3 V, vec2 alpha)
{
    vec3 Vh = normalize(vec3(V.xy * alpha, V.z));   // to the hemisphere configuration
    float phi = 2.0 * MX_PI * u.x;
    float z = (1.0 - u.y) * (1.0 + Vh.z) - Vh.z;     // uniform on the cap (-Vh.z, 1]
    float r = sqrt(clamp(1.0 - z * z, 0.0, 1.0));
    vec3 Hh = vec3(r * cos(phi), r * sin(phi), z) + Vh;
    return normalize(vec3(Hh.xy * alpha, max(Hh.z, 0.0)));  // back to the ellipsoid
}


// Smith masking for one direction (Walter et al. 2007, eq. 34), isotropic roughness `alpha`.
float mx_ggx_G1(float cosTheta, float alpha)
{
    float c2 = cosTheta * cosTheta;
    float tan2 = (1.0 - c2) / c2;
    return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * tan2));
}


// Height-correlated masking-shadowing (Heitz 2014).
float mx_ggx_G2(float NdotL, float NdotV, float alpha)
{
    float a2 = alpha * alpha;
    float lambdaL = sqrt(a2 + (1.0 - a2) * NdotL * NdotL);
    float lambdaV = sqrt(a2 + (1.0 - a2) * NdotV * NdotV);
    return 2.0 * NdotL * NdotV / (lambdaL * NdotV + lambdaV * NdotL);
}


// Density of the reflected direction sampled through a visible normal H.
float mx_ggx_reflection_pdf(vec3 H, vec2 alpha, float G1V, float NdotV)
{
    return mx_ggx_D(H, alpha) * G1V / (4.0 * NdotV);
}


// One isotropic roughness for an anisotropic pair.
float mx_average_alpha(vec2 alpha)
{
    return sqrt(alpha.x * alpha.y);
}


// Directional albedo of the GGX lobe with Schlick Fresnel between F0 and F90: the scale and bias
// (A, B) of MaterialX's rational quadratic fit to Monte Carlo data, albedo = F0 A + F90 B.
vec2 mx_ggx_albedo_scale_bias(float NdotV, float alpha)
{
    float x = NdotV;
    float y = alpha;
    float xx = x * x;
    float yy = y * y;
    vec4 n = vec4(0.1003, 0.9345, 1.0, 1.0) +
             vec4(-0.6303, -2.323, -1.765, 0.2281) * x +
             vec4(9.748, 2.229, 8.263, 15.94) * y +
             vec4(-2.038, -3.748, 11.53, -55.83) * x * y +
             vec4(29.34, 1.424, 28.96, 13.08) * xx +
             vec4(-8.245, -0.7684, -7.507, 41.26) * yy +
             vec4(-26.44, 1.436, -36.11, 54.9) * xx * y +
             vec4(19.99, 0.2913, 15.86, 300.2) * x * yy +
             vec4(-5.448, 0.6286, 33.37, -285.1) * xx * yy;
    return clamp(n.xy / n.zw, 0.0, 1.0);
}


vec3 mx_ggx_albedo(float NdotV, float alpha, vec3 F0, vec3 F90)
{
    vec2 ab = mx_ggx_albedo_scale_bias(NdotV, alpha);
    return F0 * ab.x + F90 * ab.y;
}


float mx_ggx_albedo(float NdotV, float alpha, float F0, float F90)
{
    vec2 ab = mx_ggx_albedo_scale_bias(NdotV, alpha);
    return F0 * ab.x + F90 * ab.y;
}


// Multiple-scattering compensation (Turquin 2019): scales the single-scattering lobe with Fresnel
// `Fss` so that the energy lost between microfacets is returned.
vec3 mx_ggx_energy_compensation(float NdotV, float alpha, vec3 Fss)
{
    float Ess = mx_ggx_albedo(NdotV, alpha, 1.0, 1.0);
    return 1.0 + Fss * (1.0 - Ess) / Ess;
}


// Image-based lighting from a lat-long environment map, by filtered importance sampling (Krivanek
// & Colbert 2008): GGX visible normals drawn from a spherical Fibonacci set, each environment
// sample fetched from the mip level whose texel covers the sample's solid angle.
//
// Uniforms (declared by the generator with the surface node): u_envRadiance (mipmapped radiance),
// u_envIrradiance (irradiance / pi), u_envMatrix (world -> map direction), u_envRadianceMips (levels
// in the radiance map's mip chain), u_envRadianceSamples, u_envLightIntensity.
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


// Mip level for a sample of density `pdf` along world direction `dir` (GPU Gems 3, 20.4, eq. 13),
// with the lat-long map's stretching towards the poles, biased 1.5 levels sharper.
float mx_envmap_lod(vec3 dir, float pdf, int sampleCount)
{
    float coarsest = float(u_envRadianceMips - 1) - 1.5;
    float stretch = sqrt(1.0 - dir.y * dir.y);
    return max(coarsest - 0.5 * log2(float(sampleCount) * pdf * stretch), 0.0);
}


// Direction leaving a solid sphere of index `ior` that ray direction R enters where the normal is N.
vec3 mx_refraction_solid_sphere(vec3 R, vec3 N, float ior)
{
    vec3 inside = refract(R, N, 1.0 / ior);
    vec3 exitNormal = normalize(inside * dot(inside, N) - N * 0.5);
    return refract(inside, exitNormal, ior);
}


// Light leaving a point with normal N towards V (tangent X) after one GGX bounce, or, with
// fd.refraction, after passing through a solid sphere of index fd.ior.x.
vec3 mx_environment_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd)
{
    int sampleCount = u_envRadianceSamples;
    if (sampleCount <= 0)
        return vec3(0.0);

    mat3 frame = mx_tangent_frame(N, X);
    vec3 Vt = V * frame;  // (V.X, V.Y, V.N)
    float NdotV = clamp(Vt.z, MX_EPS, 1.0);
    float avgAlpha = mx_average_alpha(alpha);
    float G1V = mx_ggx_G1(NdotV, avgAlpha);

    vec3 sum = vec3(0.0);
    for (int i = 0; i < sampleCount; i++)
    {
        vec3 H = mx_ggx_sample_visible_normal(mx_fibonacci_point(i, sampleCount), Vt, alpha);
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
        float NdotL = clamp(Lt.z, MX_EPS, 1.0);
        float VdotH = clamp(dot(Vt, H), MX_EPS, 1.0);

        vec3 Lw = frame * Lt;
        float lod = mx_envmap_lod(Lw, mx_ggx_reflection_pdf(H, alpha, G1V, NdotV), sampleCount);
        vec3 Li = mx_envmap_fetch(u_envRadiance, Lw, lod);

        // Radiance times BRDF times cosine over the sample density leaves F G2 / G1(V); G1(V) is
        // divided out once below. Refraction keeps what the interface does not reflect.
        vec3 F = mx_fresnel_eval(VdotH, fd);
        sum += Li * (fd.refraction ? vec3(1.0) - F : F * mx_ggx_G2(NdotL, NdotV, avgAlpha));
    }
    return sum / (G1V * float(sampleCount)) * u_envLightIntensity;
}


// Irradiance / pi arriving at a point with normal N: what a white Lambert surface reflects.
vec3 mx_environment_irradiance(vec3 N)
{
    return mx_envmap_fetch(u_envIrradiance, N, 0.0) * u_envLightIntensity;
}


// Transmission rendered by refraction: what is seen through the surface is the environment,
// refracted through a solid sphere of the surface's index; scene geometry behind is ignored.

vec3 mx_surface_transmission(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, vec3 tint)
{
    fd.refraction = true;
    // A two-sided interface filters the light twice.
    vec3 through = u_refractionTwoSided ? tint * tint : tint;
    return mx_environment_radiance(N, V, X, alpha, distribution, fd) * through;
}


// The GGX reflection lobe shared by the specular closures (dielectric, conductor, generalized
// Schlick, and the environment term of hair).


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


// <dielectric_bsdf>: GGX reflection off, and refraction through, a dielectric interface, with an
// optional thin film. scatter_mode: 0 R, 1 T, 2 RT.

void mx_dielectric_bsdf(ClosureData closureData, float weight, vec3 tint, float ior, vec2 roughness, bool retroreflective,
                        float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X, int distribution, int scatter_mode,
                        inout BSDF bsdf)
{
    int context = closureData.closureType;
    bool transmission = context == CLOSURE_TYPE_TRANSMISSION;
    if (weight < MX_EPS || (scatter_mode == 1 && !transmission) || !mx_is_scattering_context(context))
        return;

    // Retro-reflection mirrors the view about the normal (reflection and environment only).
    vec3 V = (retroreflective && !transmission) ? reflect(-closureData.V, N) : closureData.V;
    N = mx_facing_normal(N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    vec2 alpha = clamp(roughness, MX_EPS, 1.0);
    vec3 tintRGB = max(tint, 0.0);
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(ior), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);

    vec3 comp;
    vec3 lobe = mx_specular_lobe(closureData, N, V, X, alpha, fd, comp);

    // What the interface does not reflect passes on to the layers below.
    vec3 albedo = mx_ggx_albedo(NdotV, mx_average_alpha(alpha), mx_ior_to_f0(ior), 1.0) * comp;
    bsdf.throughput = 1.0 - albedo * weight;

    if (!transmission)
        bsdf.response = lobe * tintRGB * weight;
    else if (scatter_mode != 0)
        bsdf.response = mx_surface_transmission(N, V, X, alpha, distribution, fd, tintRGB) * weight;
}


// Sheen: the Imageworks microfiber lobe (Conty & Kulla 2017) and Zeltner et al.'s multiple-
// scattering LTC sheen (2022), each with its directional albedo for layering.

// --- Imageworks ("conty_kulla") --------------------------------------------------------------

float mx_sheen_iw_D(float NdotH, float roughness)
{
    float k = 1.0 / max(roughness, 0.005);
    float sin2 = 1.0 - NdotH * NdotH;
    return (2.0 + k) * pow(sin2, k * 0.5) / (2.0 * MX_PI);
}


// BRDF with the smoothed 4 (NdotL + NdotV - NdotL NdotV) denominator in place of masking.
float mx_sheen_iw(float NdotL, float NdotV, float NdotH, float roughness)
{
    return mx_sheen_iw_D(NdotH, roughness) / (4.0 * (NdotL + NdotV - NdotL * NdotV));
}


// Directional albedo: MaterialX's rational fit to Monte Carlo data.
float mx_sheen_iw_albedo(float NdotV, float roughness)
{
    float c = NdotV;
    float r = roughness;
    float num = 13.67300 - 68.78018 * c + 799.08825 * r - 905.00061 * c * r + 60.28956 * (c * c) + 1086.96473 * (r * r);
    float den = 1.0 + 61.57746 * c + 442.78211 * r + 2597.49308 * c * r + 121.81241 * (c * c) + 3045.55075 * (r * r);
    return clamp(num / den, 0.0, 1.0);
}


// --- Zeltner (LTC) ---------------------------------------------------------------------------
// Fits from the paper's reference code (github.com/tizian/ltc-sheen); x = NdotV, y = roughness.

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


// <sheen_bsdf>: back-scattering of fibres (cloth, dust) layered over a base. mode: 0 conty_kulla
// (Imageworks), 1 zeltner (LTC, multiple scattering).



void mx_sheen_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N, int mode, inout BSDF bsdf)
{
    int context = closureData.closureType;
    if (weight < MX_EPS || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    vec3 V = closureData.V;
    N = mx_facing_normal(N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);
    bool ltc = mode != 0;
    float r = ltc ? clamp(roughness, 0.01, 1.0) : roughness;  // the LTC fits hold on [0.01, 1]
    float albedo = ltc ? mx_sheen_ltc_albedo(NdotV, r) : mx_sheen_iw_albedo(NdotV, r);

    if (context == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float f;
        if (ltc)
        {
            f = albedo * mx_sheen_ltc(L, V, N, NdotV, r);  // the LTC lobe carries the cosine
        }
        else
        {
            float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
            float NdotH = clamp(dot(N, normalize(L + V)), MX_EPS, 1.0);
            f = mx_sheen_iw(NdotL, NdotV, NdotH, r) * NdotL;
        }
        bsdf.response = color * (f * closureData.occlusion * weight);
    }
    else
    {
        bsdf.response = mx_environment_irradiance(N) * color * albedo * weight;
    }
    bsdf.throughput = vec3(1.0 - albedo * weight);
}


// <conductor_bsdf>: GGX reflection off a metal of complex index ior + i extinction, with an
// optional thin film. Opaque.

void mx_conductor_bsdf(ClosureData closureData, float weight, vec3 ior_n, vec3 ior_k, vec2 roughness, bool retroreflective,
                       float thinfilm_thickness, float thinfilm_ior, vec3 N, vec3 X, int distribution, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    int context = closureData.closureType;
    if (weight < MX_EPS || (context != CLOSURE_TYPE_REFLECTION && context != CLOSURE_TYPE_INDIRECT))
        return;

    vec3 V = retroreflective ? reflect(-closureData.V, N) : closureData.V;
    N = mx_facing_normal(N, V);
    vec2 alpha = clamp(roughness, MX_EPS, 1.0);
    FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_CONDUCTOR, ior_n, ior_k, vec3(0.0), vec3(0.0), vec3(0.0), 0.0,
                                     thinfilm_thickness, thinfilm_ior);
    vec3 comp;
    bsdf.response = mx_specular_lobe(closureData, N, V, X, alpha, fd, comp) * weight;
}


// Media. The hardware targets model a medium by its transmittance over a unit distance,
// exp(-absorption), answered in the TRANSMISSION context (the only one that looks through a surface).

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


// <layer>: vertical layering. The base is lit by what the top layer lets through.

void mx_layer_bsdf(ClosureData closureData, BSDF top, BSDF base, out BSDF result)
{
    result.response = top.response + base.response * top.throughput;
    result.throughput = top.throughput * base.throughput;
}


// A BSDF over a medium: the medium filters what the top layer scatters and lets through.
void mx_layer_vdf(ClosureData closureData, BSDF top, VDF base, out BSDF result)
{
    result.response = top.response * base.throughput;
    result.throughput = top.throughput * base.throughput;
}


// <mix> of closures: linear interpolation, bg at 0 and fg at 1.

void mx_mix_bsdf(ClosureData closureData, BSDF fg, BSDF bg, float mixValue, out BSDF result)
{
    result.response = mix(bg.response, fg.response, mixValue);
    result.throughput = mix(bg.throughput, fg.throughput, mixValue);
}


// <translucent_bsdf>: diffuse transmission, light arriving from behind the surface leaving in
// front of it (Lambert about the reversed normal).


void mx_translucent_bsdf(ClosureData closureData, float weight, vec3 color, vec3 N, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (weight < MX_EPS)
        return;

    vec3 back = -N;
    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        float cosine = clamp(dot(back, closureData.L), 0.0, 1.0);
        bsdf.response = color * (weight * cosine * MX_INV_PI);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(back) * color * weight;
    }
}


// Diffuse reflectance models: Oren-Nayar (qualitative, and the energy-conserving variant of
// OpenPBR built on Fujii's improved model), Burley (Disney 2012), and a screen-space approximation
// of Burley's normalised diffusion for subsurface scattering.

// --- Oren-Nayar, qualitative model ---------------------------------------------------------------

// Reflectance relative to Lambert for roughness (sigma) `roughness`.
float mx_oren_nayar(float NdotV, float NdotL, float LdotV, float roughness)
{
    float s = LdotV - NdotL * NdotV;
    float t = (s > 0.0) ? s / max(NdotL, NdotV) : 0.0;
    float sigma2 = roughness * roughness;
    float A = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float B = 0.45 * sigma2 / (sigma2 + 0.09);
    return A + B * t;
}


// Its directional albedo: MaterialX's rational fit to Monte Carlo data.
float mx_oren_nayar_albedo(float NdotV, float roughness)
{
    float r = roughness;
    float num = 1.0 - 0.4297 * r - 0.7632 * NdotV * r + 1.4385 * (r * r);
    float den = 1.0 - 0.6076 * r - 0.4993 * NdotV * r + 2.0315 * (r * r);
    return clamp(num / den, 0.0, 1.0);
}


// --- Energy-conserving Oren-Nayar (Fujii's model + a multiple-scattering lobe) --------------------

const float MX_FUJII_C1 = 0.5 - 2.0 / (3.0 * MX_PI);

const float MX_FUJII_C2 = 2.0 / 3.0 - 28.0 / (15.0 * MX_PI);


float mx_fujii_albedo(float cosTheta, float roughness)
{
    float A = 1.0 / (1.0 + MX_FUJII_C1 * roughness);
    float B = roughness * A;
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float G = sinTheta * (acos(clamp(cosTheta, -1.0, 1.0)) - sinTheta * cosTheta) +
              2.0 * ((sinTheta / cosTheta) * (1.0 - sinTheta * sinTheta * sinTheta) - sinTheta) / 3.0;
    return A + B * G * MX_INV_PI;
}


float mx_fujii_average_albedo(float roughness)
{
    return (1.0 + MX_FUJII_C2 * roughness) / (1.0 + MX_FUJII_C1 * roughness);
}


// Colour of the multiple-scattering lobe for albedo `color`.
vec3 mx_eon_multiscatter_color(vec3 color, float avgAlbedo)
{
    return color * color * avgAlbedo / (vec3(1.0) - color * max(0.0, 1.0 - avgAlbedo));
}


// Reflectance relative to Lambert, colour included.
vec3 mx_eon(float NdotV, float NdotL, float LdotV, float roughness, vec3 color)
{
    float s = LdotV - NdotL * NdotV;
    float t = (s > 0.0) ? s / max(NdotL, NdotV) : s;
    float A = 1.0 / (1.0 + MX_FUJII_C1 * roughness);
    vec3 single = color * A * (1.0 + roughness * t);

    float avgAlbedo = mx_fujii_average_albedo(roughness);
    float missV = max(MX_EPS, 1.0 - mx_fujii_albedo(NdotV, roughness));
    float missL = max(MX_EPS, 1.0 - mx_fujii_albedo(NdotL, roughness));
    vec3 multi = mx_eon_multiscatter_color(color, avgAlbedo) * missV * missL / max(MX_EPS, 1.0 - avgAlbedo);
    return single + multi;
}


vec3 mx_eon_albedo(float cosTheta, float roughness, vec3 color)
{
    float avgAlbedo = mx_fujii_average_albedo(roughness);
    return mix(mx_eon_multiscatter_color(color, avgAlbedo), color, mx_fujii_albedo(cosTheta, roughness));
}


// --- Subsurface approximation -----------------------------------------------------------------

// Burley's normalised diffusion profile at distance r for shape 1/d (up to constant factors).
vec3 mx_burley_profile(float r, vec3 shape)
{
    return (exp(-shape * r) + exp(-shape * r / 3.0)) / max(r, MX_EPS);
}


// The profile wrapped around a sphere of `radius` (Penner 2011): the fraction of light from L that
// diffuses to the point with normal N, for mean free path `mfp`.
vec3 mx_burley_sphere_scatter(vec3 N, vec3 L, float radius, vec3 mfp)
{
    const int STEPS = 32;
    const float STEP = 2.0 * MX_PI / float(STEPS);
    float theta = acos(clamp(dot(N, L), -1.0, 1.0));
    vec3 shape = vec3(1.0) / max(mfp, 0.1);
    vec3 lit = vec3(0.0);
    vec3 total = vec3(0.0);
    for (int i = 0; i < STEPS; i++)
    {
        float x = -MX_PI + (float(i) + 0.5) * STEP;  // angle around the sphere
        vec3 w = mx_burley_profile(radius * abs(2.0 * sin(x * 0.5)), shape);
        lit += w * max(cos(theta + x), 0.0);
        total += w;
    }
    return lit / total;
}


// Subsurface reflectance towards L (cosine included), the surface's curvature estimated from
// screen-space derivatives of the normal and position.
vec3 mx_subsurface_scatter(vec3 N, vec3 L, vec3 P, vec3 albedo, vec3 mfp)
{
    float curvature = length(fwidth(N)) / length(fwidth(P));
    float radius = 1.0 / max(curvature, 0.01);
    return albedo * mx_burley_sphere_scatter(N, L, radius, mfp) / vec3(MX_PI);
}


// <subsurface_bsdf>: subsurface scattering approximated at the shading point, with Burley's
// diffusion profile wrapped around the local curvature; the environment lights it as diffuse.



void mx_subsurface_bsdf(ClosureData closureData, float weight, vec3 color, vec3 radius, float anisotropy, vec3 N,
                        inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (weight < MX_EPS)
        return;

    N = mx_facing_normal(N, closureData.V);
    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        vec3 scattered = mx_subsurface_scatter(N, L, closureData.P, color, radius);
        // Occlusion darkens only the part of the light that arrives directly.
        float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
        float visible = 1.0 - NdotL * (1.0 - closureData.occlusion);
        bsdf.response = scattered * (visible * weight);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * color * weight;
    }
}


// <oren_nayar_diffuse_bsdf>: opaque diffuse reflection, Lambert at roughness 0.



void mx_oren_nayar_diffuse_bsdf(ClosureData closureData, float weight, vec3 color, float roughness, vec3 N,
                                bool energy_compensation, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);  // opaque: nothing reaches the layers below
    if (weight < MX_EPS)
        return;

    vec3 V = closureData.V;
    N = mx_facing_normal(N, V);
    float NdotV = clamp(dot(N, V), MX_EPS, 1.0);

    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
        float LdotV = clamp(dot(L, V), MX_EPS, 1.0);
        vec3 f = energy_compensation ? mx_eon(NdotV, NdotL, LdotV, roughness, color)
                                     : color * mx_oren_nayar(NdotV, NdotL, LdotV, roughness);
        bsdf.response = f * (closureData.occlusion * weight * NdotL * MX_INV_PI);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        vec3 albedo = energy_compensation ? mx_eon_albedo(NdotV, roughness, color)
                                          : color * mx_oren_nayar_albedo(NdotV, roughness);
        bsdf.response = mx_environment_irradiance(N) * albedo * weight;
    }
}


// <multiply> of a closure by a weight (float or colour).

// A BSDF's response is scaled by the weight clamped to [0, 1]; what it lets through is unchanged.
void mx_multiply_bsdf_color3(ClosureData closureData, BSDF in1, vec3 in2, out BSDF result)
{
    result.response = in1.response * clamp(in2, 0.0, 1.0);
    result.throughput = in1.throughput;
}


// <uniform_edf>: the same radiance in every direction.

void mx_uniform_edf(ClosureData closureData, vec3 color, inout EDF result)
{
    if (closureData.closureType == CLOSURE_TYPE_EMISSION)
        result = color;
}


// <generalized_schlick_edf>: the base EDF weighted by a Schlick curve over the view angle, color0
// along the normal and color90 at grazing angles.


void mx_generalized_schlick_edf(ClosureData closureData, vec3 color0, vec3 color90, float exponent, EDF base,
                                inout EDF result)
{
    if (closureData.closureType != CLOSURE_TYPE_EMISSION)
        return;
    vec3 V = closureData.V;
    float NdotV = clamp(dot(mx_facing_normal(closureData.N, V), V), MX_EPS, 1.0);
    result = base * mx_fresnel_schlick_exp(NdotV, color0, color90, exponent);
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
    vec2 SR_coated_coat_alpha_out;
    mx_roughness_anisotropy(SR_coated_coat_roughness, SR_coated_coat_anisotropy, SR_coated_coat_alpha_out);
    vec3 geomprop_Nworld_out = normalize(vd.normalWorld);
    vec3 geomprop_Tworld_out = normalize(vd.tangentWorld);
    float SR_coated_coat_angle_out = SR_coated_coat_rotation * 180.0;
    vec3 SR_coated_coat_tangent_out;
    mx_rotate3d_vector3(geomprop_Tworld_out, SR_coated_coat_angle_out, geomprop_Nworld_out, SR_coated_coat_tangent_out);
    float SR_coated_coat_saturation_out = SR_coated_coat * SR_coated_coat_affect_color;
    float SR_coated_saturation_exponent_out = SR_coated_coat_saturation_out + 1.0;
    vec3 SR_coated_saturated_base_color_out = pow(SR_coated_base_color, vec3(SR_coated_saturation_exponent_out));
    vec3 SR_coated_metal_reflectivity_out = SR_coated_saturated_base_color_out * SR_coated_base;
    vec3 SR_coated_metal_ior_ior;
    vec3 SR_coated_metal_ior_extinction;
    mx_artistic_ior(SR_coated_metal_reflectivity_out, SR_coated_specular_color, SR_coated_metal_ior_ior, SR_coated_metal_ior_extinction);
    float SR_coated_coat_gloss_loss_out = SR_coated_coat * SR_coated_coat_affect_roughness;
    float SR_coated_coat_roughening_out = SR_coated_coat_gloss_loss_out * SR_coated_coat_roughness;
    float SR_coated_base_roughness_out = mix(SR_coated_specular_roughness, 1.0, SR_coated_coat_roughening_out);
    vec2 SR_coated_specular_alpha_out;
    mx_roughness_anisotropy(SR_coated_base_roughness_out, SR_coated_specular_anisotropy, SR_coated_specular_alpha_out);
    float SR_coated_specular_angle_out = SR_coated_specular_rotation * 180.0;
    vec3 SR_coated_specular_tangent_out;
    mx_rotate3d_vector3(geomprop_Tworld_out, SR_coated_specular_angle_out, geomprop_Nworld_out, SR_coated_specular_tangent_out);
    float SR_coated_transmission_bsdf_has_medium_out = (SR_coated_transmission_depth > 0.0) ? 1.0 : 0.0;
    vec3 SR_coated_transmission_bsdf_interface_tint_out = mix(SR_coated_transmission_color, vec3(1.0, 1.0, 1.0), SR_coated_transmission_bsdf_has_medium_out);
    float SR_coated_transmission_roughness_sum_out = SR_coated_base_roughness_out + SR_coated_transmission_extra_roughness;
    float SR_coated_transmission_roughness_out = clamp(SR_coated_transmission_roughness_sum_out, 0.0, 1.0);
    vec2 SR_coated_transmission_alpha_out;
    mx_roughness_anisotropy(SR_coated_transmission_roughness_out, SR_coated_specular_anisotropy, SR_coated_transmission_alpha_out);
    vec3 SR_coated_transmission_bsdf_medium_color_v_out = SR_coated_transmission_color;
    vec3 SR_coated_transmission_bsdf_medium_positive_color_out = max(SR_coated_transmission_bsdf_medium_color_v_out, 1.0e-6);
    vec3 SR_coated_transmission_bsdf_medium_log_transmittance_out = log(SR_coated_transmission_bsdf_medium_positive_color_out);
    float SR_coated_transmission_bsdf_medium_safe_depth_out = max(SR_coated_transmission_depth, 1.0e-6);
    vec3 SR_coated_transmission_bsdf_medium_log_per_depth_out = SR_coated_transmission_bsdf_medium_log_transmittance_out / SR_coated_transmission_bsdf_medium_safe_depth_out;
    vec3 SR_coated_transmission_bsdf_medium_scatter_v_out = SR_coated_transmission_scatter;
    vec3 SR_coated_transmission_bsdf_medium_scattering_out = SR_coated_transmission_bsdf_medium_scatter_v_out / SR_coated_transmission_bsdf_medium_safe_depth_out;
    vec3 SR_coated_transmission_bsdf_medium_log_per_depth_and_scattering_out = SR_coated_transmission_bsdf_medium_log_per_depth_out + SR_coated_transmission_bsdf_medium_scattering_out;
    vec3 SR_coated_transmission_bsdf_medium_negative_absorption_out = min(SR_coated_transmission_bsdf_medium_log_per_depth_and_scattering_out, 0.0);
    vec3 SR_coated_transmission_bsdf_medium_absorption_out = SR_coated_transmission_bsdf_medium_negative_absorption_out * (-1.0);
    vec3 SR_coated_saturated_subsurface_color_out = pow(SR_coated_subsurface_color, vec3(SR_coated_saturation_exponent_out));
    vec3 SR_coated_mean_free_path_out = SR_coated_subsurface_radius * SR_coated_subsurface_scale;
    float SR_coated_thin_walled_weight_out = float(SR_coated_thin_walled);
    vec3 SR_coated_coat_absorption_out = mix(vec3(1.0, 1.0, 1.0), SR_coated_coat_color, SR_coated_coat);
    float SR_coated_emission_edf_ior_minus_one_out = SR_coated_coat_IOR - 1.0;
    float SR_coated_emission_edf_ior_plus_one_out = SR_coated_coat_IOR + 1.0;
    float SR_coated_emission_edf_amplitude_ratio_out = SR_coated_emission_edf_ior_minus_one_out / SR_coated_emission_edf_ior_plus_one_out;
    float SR_coated_emission_edf_f0_out = SR_coated_emission_edf_amplitude_ratio_out * SR_coated_emission_edf_amplitude_ratio_out;
    float SR_coated_emission_edf_t0_out = 1.0 - SR_coated_emission_edf_f0_out;
    vec3 SR_coated_emission_edf_tinted_t0_out = SR_coated_coat_color * SR_coated_emission_edf_t0_out;
    vec3 SR_coated_emission_edf_facing_out = mix(vec3(1.0, 1.0, 1.0), SR_coated_emission_edf_tinted_t0_out, SR_coated_coat);
    float SR_coated_emission_edf_uncoated_out = 1.0 - SR_coated_coat;
    vec3 SR_coated_emission_edf_grazing_out = vec3(SR_coated_emission_edf_uncoated_out);
    vec3 SR_coated_emission_radiance_out = SR_coated_emission_color * SR_coated_emission;
    vec3 SR_coated_opacity_v_out = SR_coated_opacity;
    float SR_coated_opacity_mean_out = dot(SR_coated_opacity_v_out, vec3(0.333333, 0.333333, 0.333334));
    surfaceshader SR_coated_shader_out = surfaceshader(vec3(0.0), vec3(0.0));
    {
        vec3 N = normalize(vd.normalWorld);
        vec3 V = normalize(u_viewPosition - vd.positionWorld);
        vec3 P = vd.positionWorld;
        vec3 L = vec3(0.0);
        float occlusion = 1.0;
        float surfaceOpacity = SR_coated_opacity_mean_out;
        for (int activeLightIndex = 0; activeLightIndex < numActiveLightSources(); ++activeLightIndex)
        {
            lightshader lightShader;
            sampleLightSource(u_lightData[activeLightIndex], vd.positionWorld, lightShader);
            L = lightShader.direction;
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_REFLECTION, L, V, N, P, occlusion);
            BSDF SR_coated_coat_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, SR_coated_coat, vec3(1.0, 1.0, 1.0), SR_coated_coat_IOR, SR_coated_coat_alpha_out, false, 0.0, 1.5, geomprop_Nworld_out, SR_coated_coat_tangent_out, 0, 0, SR_coated_coat_brdf_out);
            BSDF SR_coated_sheen_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_sheen_bsdf(closureData, SR_coated_sheen, SR_coated_sheen_color, SR_coated_sheen_roughness, geomprop_Nworld_out, 0, SR_coated_sheen_brdf_out);
            BSDF SR_coated_metal_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_conductor_bsdf(closureData, 1.0, SR_coated_metal_ior_ior, SR_coated_metal_ior_extinction, SR_coated_specular_alpha_out, false, SR_coated_thin_film_thickness, SR_coated_thin_film_IOR, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, SR_coated_metal_brdf_out);
            BSDF SR_coated_specular_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, SR_coated_specular, SR_coated_specular_color, SR_coated_specular_IOR, SR_coated_specular_alpha_out, false, SR_coated_thin_film_thickness, SR_coated_thin_film_IOR, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, 0, SR_coated_specular_brdf_out);
            BSDF SR_coated_transmission_bsdf_interface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, 1.0, SR_coated_transmission_bsdf_interface_tint_out, SR_coated_specular_IOR, SR_coated_transmission_alpha_out, false, 0.0, 1.5, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, 1, SR_coated_transmission_bsdf_interface_out);
            VDF SR_coated_transmission_bsdf_medium_medium_out = VDF(vec3(0.0), vec3(1.0));
            mx_anisotropic_vdf(closureData, SR_coated_transmission_bsdf_medium_absorption_out, SR_coated_transmission_bsdf_medium_scattering_out, SR_coated_transmission_scatter_anisotropy, SR_coated_transmission_bsdf_medium_medium_out);
            BSDF SR_coated_transmission_bsdf_interface_over_medium_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_vdf(closureData, SR_coated_transmission_bsdf_interface_out, SR_coated_transmission_bsdf_medium_medium_out, SR_coated_transmission_bsdf_interface_over_medium_out);
            BSDF SR_coated_transmission_bsdf_transmission_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_transmission_bsdf_interface_over_medium_out, SR_coated_transmission_bsdf_interface_out, SR_coated_transmission_bsdf_has_medium_out, SR_coated_transmission_bsdf_transmission_out);
            BSDF SR_coated_thin_subsurface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_translucent_bsdf(closureData, 1.0, SR_coated_saturated_subsurface_color_out, geomprop_Nworld_out, SR_coated_thin_subsurface_out);
            BSDF SR_coated_volume_subsurface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_subsurface_bsdf(closureData, 1.0, SR_coated_saturated_subsurface_color_out, SR_coated_mean_free_path_out, SR_coated_subsurface_anisotropy, geomprop_Nworld_out, SR_coated_volume_subsurface_out);
            BSDF SR_coated_subsurface_bsdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_thin_subsurface_out, SR_coated_volume_subsurface_out, SR_coated_thin_walled_weight_out, SR_coated_subsurface_bsdf_out);
            BSDF SR_coated_diffuse_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_oren_nayar_diffuse_bsdf(closureData, SR_coated_base, SR_coated_saturated_base_color_out, SR_coated_diffuse_roughness, geomprop_Nworld_out, false, SR_coated_diffuse_brdf_out);
            BSDF SR_coated_opaque_base_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_subsurface_bsdf_out, SR_coated_diffuse_brdf_out, SR_coated_subsurface, SR_coated_opaque_base_out);
            BSDF SR_coated_dielectric_substrate_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_transmission_bsdf_transmission_out, SR_coated_opaque_base_out, SR_coated_transmission, SR_coated_dielectric_substrate_out);
            BSDF SR_coated_dielectric_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_specular_brdf_out, SR_coated_dielectric_substrate_out, SR_coated_dielectric_out);
            BSDF SR_coated_base_substrate_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_metal_brdf_out, SR_coated_dielectric_out, SR_coated_metalness, SR_coated_base_substrate_out);
            BSDF SR_coated_sheen_layer_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_sheen_brdf_out, SR_coated_base_substrate_out, SR_coated_sheen_layer_out);
            BSDF SR_coated_under_coat_out = BSDF(vec3(0.0), vec3(1.0));
            mx_multiply_bsdf_color3(closureData, SR_coated_sheen_layer_out, SR_coated_coat_absorption_out, SR_coated_under_coat_out);
            BSDF SR_coated_coat_layer_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_coat_brdf_out, SR_coated_under_coat_out, SR_coated_coat_layer_out);
            SR_coated_shader_out.color += lightShader.intensity * SR_coated_coat_layer_out.response;
        }
        // environment
        {
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_INDIRECT, L, V, N, P, occlusion);
            BSDF SR_coated_coat_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, SR_coated_coat, vec3(1.0, 1.0, 1.0), SR_coated_coat_IOR, SR_coated_coat_alpha_out, false, 0.0, 1.5, geomprop_Nworld_out, SR_coated_coat_tangent_out, 0, 0, SR_coated_coat_brdf_out);
            BSDF SR_coated_sheen_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_sheen_bsdf(closureData, SR_coated_sheen, SR_coated_sheen_color, SR_coated_sheen_roughness, geomprop_Nworld_out, 0, SR_coated_sheen_brdf_out);
            BSDF SR_coated_metal_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_conductor_bsdf(closureData, 1.0, SR_coated_metal_ior_ior, SR_coated_metal_ior_extinction, SR_coated_specular_alpha_out, false, SR_coated_thin_film_thickness, SR_coated_thin_film_IOR, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, SR_coated_metal_brdf_out);
            BSDF SR_coated_specular_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, SR_coated_specular, SR_coated_specular_color, SR_coated_specular_IOR, SR_coated_specular_alpha_out, false, SR_coated_thin_film_thickness, SR_coated_thin_film_IOR, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, 0, SR_coated_specular_brdf_out);
            BSDF SR_coated_transmission_bsdf_interface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, 1.0, SR_coated_transmission_bsdf_interface_tint_out, SR_coated_specular_IOR, SR_coated_transmission_alpha_out, false, 0.0, 1.5, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, 1, SR_coated_transmission_bsdf_interface_out);
            VDF SR_coated_transmission_bsdf_medium_medium_out = VDF(vec3(0.0), vec3(1.0));
            mx_anisotropic_vdf(closureData, SR_coated_transmission_bsdf_medium_absorption_out, SR_coated_transmission_bsdf_medium_scattering_out, SR_coated_transmission_scatter_anisotropy, SR_coated_transmission_bsdf_medium_medium_out);
            BSDF SR_coated_transmission_bsdf_interface_over_medium_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_vdf(closureData, SR_coated_transmission_bsdf_interface_out, SR_coated_transmission_bsdf_medium_medium_out, SR_coated_transmission_bsdf_interface_over_medium_out);
            BSDF SR_coated_transmission_bsdf_transmission_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_transmission_bsdf_interface_over_medium_out, SR_coated_transmission_bsdf_interface_out, SR_coated_transmission_bsdf_has_medium_out, SR_coated_transmission_bsdf_transmission_out);
            BSDF SR_coated_thin_subsurface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_translucent_bsdf(closureData, 1.0, SR_coated_saturated_subsurface_color_out, geomprop_Nworld_out, SR_coated_thin_subsurface_out);
            BSDF SR_coated_volume_subsurface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_subsurface_bsdf(closureData, 1.0, SR_coated_saturated_subsurface_color_out, SR_coated_mean_free_path_out, SR_coated_subsurface_anisotropy, geomprop_Nworld_out, SR_coated_volume_subsurface_out);
            BSDF SR_coated_subsurface_bsdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_thin_subsurface_out, SR_coated_volume_subsurface_out, SR_coated_thin_walled_weight_out, SR_coated_subsurface_bsdf_out);
            BSDF SR_coated_diffuse_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_oren_nayar_diffuse_bsdf(closureData, SR_coated_base, SR_coated_saturated_base_color_out, SR_coated_diffuse_roughness, geomprop_Nworld_out, false, SR_coated_diffuse_brdf_out);
            BSDF SR_coated_opaque_base_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_subsurface_bsdf_out, SR_coated_diffuse_brdf_out, SR_coated_subsurface, SR_coated_opaque_base_out);
            BSDF SR_coated_dielectric_substrate_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_transmission_bsdf_transmission_out, SR_coated_opaque_base_out, SR_coated_transmission, SR_coated_dielectric_substrate_out);
            BSDF SR_coated_dielectric_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_specular_brdf_out, SR_coated_dielectric_substrate_out, SR_coated_dielectric_out);
            BSDF SR_coated_base_substrate_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_metal_brdf_out, SR_coated_dielectric_out, SR_coated_metalness, SR_coated_base_substrate_out);
            BSDF SR_coated_sheen_layer_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_sheen_brdf_out, SR_coated_base_substrate_out, SR_coated_sheen_layer_out);
            BSDF SR_coated_under_coat_out = BSDF(vec3(0.0), vec3(1.0));
            mx_multiply_bsdf_color3(closureData, SR_coated_sheen_layer_out, SR_coated_coat_absorption_out, SR_coated_under_coat_out);
            BSDF SR_coated_coat_layer_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_coat_brdf_out, SR_coated_under_coat_out, SR_coated_coat_layer_out);
            SR_coated_shader_out.color += occlusion * SR_coated_coat_layer_out.response;
        }
        // emission
        {
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_EMISSION, L, V, N, P, occlusion);
            EDF SR_coated_emission_edf_emission_out = EDF(0.0);
            mx_uniform_edf(closureData, SR_coated_emission_radiance_out, SR_coated_emission_edf_emission_out);
            EDF SR_coated_emission_edf_through_coat_out = EDF(0.0);
            mx_generalized_schlick_edf(closureData, SR_coated_emission_edf_facing_out, SR_coated_emission_edf_grazing_out, 5.0, SR_coated_emission_edf_emission_out, SR_coated_emission_edf_through_coat_out);
            SR_coated_shader_out.color += SR_coated_emission_edf_through_coat_out;
        }
        // transmission, seen along the view direction
        {
            ClosureData closureData = makeClosureData(CLOSURE_TYPE_TRANSMISSION, L, V, N, P, occlusion);
            BSDF SR_coated_coat_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, SR_coated_coat, vec3(1.0, 1.0, 1.0), SR_coated_coat_IOR, SR_coated_coat_alpha_out, false, 0.0, 1.5, geomprop_Nworld_out, SR_coated_coat_tangent_out, 0, 0, SR_coated_coat_brdf_out);
            BSDF SR_coated_sheen_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_sheen_bsdf(closureData, SR_coated_sheen, SR_coated_sheen_color, SR_coated_sheen_roughness, geomprop_Nworld_out, 0, SR_coated_sheen_brdf_out);
            BSDF SR_coated_metal_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_conductor_bsdf(closureData, 1.0, SR_coated_metal_ior_ior, SR_coated_metal_ior_extinction, SR_coated_specular_alpha_out, false, SR_coated_thin_film_thickness, SR_coated_thin_film_IOR, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, SR_coated_metal_brdf_out);
            BSDF SR_coated_specular_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, SR_coated_specular, SR_coated_specular_color, SR_coated_specular_IOR, SR_coated_specular_alpha_out, false, SR_coated_thin_film_thickness, SR_coated_thin_film_IOR, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, 0, SR_coated_specular_brdf_out);
            BSDF SR_coated_transmission_bsdf_interface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_dielectric_bsdf(closureData, 1.0, SR_coated_transmission_bsdf_interface_tint_out, SR_coated_specular_IOR, SR_coated_transmission_alpha_out, false, 0.0, 1.5, geomprop_Nworld_out, SR_coated_specular_tangent_out, 0, 1, SR_coated_transmission_bsdf_interface_out);
            VDF SR_coated_transmission_bsdf_medium_medium_out = VDF(vec3(0.0), vec3(1.0));
            mx_anisotropic_vdf(closureData, SR_coated_transmission_bsdf_medium_absorption_out, SR_coated_transmission_bsdf_medium_scattering_out, SR_coated_transmission_scatter_anisotropy, SR_coated_transmission_bsdf_medium_medium_out);
            BSDF SR_coated_transmission_bsdf_interface_over_medium_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_vdf(closureData, SR_coated_transmission_bsdf_interface_out, SR_coated_transmission_bsdf_medium_medium_out, SR_coated_transmission_bsdf_interface_over_medium_out);
            BSDF SR_coated_transmission_bsdf_transmission_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_transmission_bsdf_interface_over_medium_out, SR_coated_transmission_bsdf_interface_out, SR_coated_transmission_bsdf_has_medium_out, SR_coated_transmission_bsdf_transmission_out);
            BSDF SR_coated_thin_subsurface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_translucent_bsdf(closureData, 1.0, SR_coated_saturated_subsurface_color_out, geomprop_Nworld_out, SR_coated_thin_subsurface_out);
            BSDF SR_coated_volume_subsurface_out = BSDF(vec3(0.0), vec3(1.0));
            mx_subsurface_bsdf(closureData, 1.0, SR_coated_saturated_subsurface_color_out, SR_coated_mean_free_path_out, SR_coated_subsurface_anisotropy, geomprop_Nworld_out, SR_coated_volume_subsurface_out);
            BSDF SR_coated_subsurface_bsdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_thin_subsurface_out, SR_coated_volume_subsurface_out, SR_coated_thin_walled_weight_out, SR_coated_subsurface_bsdf_out);
            BSDF SR_coated_diffuse_brdf_out = BSDF(vec3(0.0), vec3(1.0));
            mx_oren_nayar_diffuse_bsdf(closureData, SR_coated_base, SR_coated_saturated_base_color_out, SR_coated_diffuse_roughness, geomprop_Nworld_out, false, SR_coated_diffuse_brdf_out);
            BSDF SR_coated_opaque_base_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_subsurface_bsdf_out, SR_coated_diffuse_brdf_out, SR_coated_subsurface, SR_coated_opaque_base_out);
            BSDF SR_coated_dielectric_substrate_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_transmission_bsdf_transmission_out, SR_coated_opaque_base_out, SR_coated_transmission, SR_coated_dielectric_substrate_out);
            BSDF SR_coated_dielectric_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_specular_brdf_out, SR_coated_dielectric_substrate_out, SR_coated_dielectric_out);
            BSDF SR_coated_base_substrate_out = BSDF(vec3(0.0), vec3(1.0));
            mx_mix_bsdf(closureData, SR_coated_metal_brdf_out, SR_coated_dielectric_out, SR_coated_metalness, SR_coated_base_substrate_out);
            BSDF SR_coated_sheen_layer_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_sheen_brdf_out, SR_coated_base_substrate_out, SR_coated_sheen_layer_out);
            BSDF SR_coated_under_coat_out = BSDF(vec3(0.0), vec3(1.0));
            mx_multiply_bsdf_color3(closureData, SR_coated_sheen_layer_out, SR_coated_coat_absorption_out, SR_coated_under_coat_out);
            BSDF SR_coated_coat_layer_out = BSDF(vec3(0.0), vec3(1.0));
            mx_layer_bsdf(closureData, SR_coated_coat_brdf_out, SR_coated_under_coat_out, SR_coated_coat_layer_out);
            SR_coated_shader_out.color += SR_coated_coat_layer_out.response;
        }
        SR_coated_shader_out.color *= surfaceOpacity;
        SR_coated_shader_out.transparency = mix(vec3(1.0), SR_coated_shader_out.transparency, surfaceOpacity);
    }
    material Coated_out = SR_coated_shader_out;
    out1 = vec4(Coated_out.color, 1.0);
}
