// Fresnel reflectance: Schlick and its generalisations, exact dielectric and conductor
// reflectance, and Belcour & Barla's thin-film (Airy) interference over any of them.
#include "mx_pbr_common.glsl"

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
    return mix(F0, F90, mx_power(m, exponent));
}

float mx_fresnel_schlick_5(float cosTheta, float F0, float F90)
{
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    return mix(F0, F90, mx_pow_5(m));
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
