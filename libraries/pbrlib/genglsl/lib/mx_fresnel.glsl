// Fresnel reflectance: Schlick and its generalisations, exact dielectric and conductor
// reflectance, and Belcour & Barla's thin-film (Airy) interference over any of them.
#include "mx_pbr_common.glsl"

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

// The angle of (x, y), atan(y, x), with a zero y on the positive x axis read as 0 whatever its
// sign: IEEE gives -0 for atan(-0, x > 0), but SwiftShader (headless Chromium's WebGL) gives pi,
// which turns a dielectric base's phase (y is 0 or -0 there) by half a wave.
vec3 mx_phase_angle(vec3 y, vec3 x)
{
    vec3 angle = atan(y, x);
    vec3 onAxis = mix(angle, vec3(0.0), greaterThan(x, vec3(0.0)));
    return mix(angle, onAxis, equal(y, vec3(0.0)));
}

// Phase shifts on reflection at a conductor (Belcour & Barla 2017), per polarisation.
void mx_fresnel_conductor_phase(float cosTheta, float eta1, vec3 eta2, vec3 kappa2, out vec3 phiP, out vec3 phiS)
{
    vec3 k = kappa2 / eta2;
    vec3 s2 = vec3(1.0) - cosTheta * cosTheta;
    vec3 oneMinusK2 = vec3(1.0) - k * k;
    vec3 A = eta2 * eta2 * oneMinusK2 - eta1 * eta1 * s2;
    vec3 B = sqrt(A * A + mx_sqr(2.0 * eta2 * eta2 * k));
    // B >= |A| exactly, but rounding can leave A + B or B - A a tiny negative: clamped before the
    // square root, whose NaN a max() after it does not remove everywhere (SwiftShader keeps it)
    vec3 U = sqrt(max((A + B) / 2.0, vec3(0.0)));
    vec3 V = sqrt(max((B - A) / 2.0, vec3(0.0)));
    phiS = mx_phase_angle(2.0 * eta1 * V * cosTheta, U * U + V * V - mx_sqr(eta1 * cosTheta));
    phiP = mx_phase_angle(2.0 * eta1 * eta2 * eta2 * cosTheta * (2.0 * k * U - oneMinusK2 * V),
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
#ifdef MX_FEATURE_FRESNEL_SCHLICK
    if (schlick)
    {
        R23p = R23s = mx_fresnel_f82(c2, fd);  // unpolarised: the same for both
        phi23p = phi23s = mix(vec3(0.0), vec3(MX_PI), lessThan(n3, vec3(n2)));
    }
    else
#endif
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

// Generation-time features (shadergen/features.py): a shader keeps the models its closures use,
// and the thin film only when some closure's film can be thicker than 0. `withFilm` false leaves
// fd's film out: a caller that knows it has none passes a constant and gets no film code, which
// matters where F is taken per sample, since a CPU rasterizer (Mesa's llvmpipe) runs both sides
// of a branch (mx_environment_reflected).
vec3 mx_fresnel_eval_film(float cosTheta, FresnelData fd, bool withFilm)
{
#ifdef MX_FEATURE_THIN_FILM
    if (withFilm && mx_fresnel_has_thinfilm(fd))
        return mx_fresnel_airy(cosTheta, fd);
#endif
#ifdef MX_FEATURE_FRESNEL_DIELECTRIC
    if (fd.model == FRESNEL_MODEL_DIELECTRIC)
        return vec3(mx_fresnel_dielectric(cosTheta, fd.ior.x));
#endif
#ifdef MX_FEATURE_FRESNEL_CONDUCTOR
    if (fd.model == FRESNEL_MODEL_CONDUCTOR)
        return mx_fresnel_conductor(cosTheta, fd.ior, fd.extinction);
#endif
#ifdef MX_FEATURE_FRESNEL_SCHLICK
    return mx_fresnel_f82(cosTheta, fd);
#else
    return vec3(0.0);  // no closure of this shader uses another model
#endif
}

vec3 mx_fresnel_eval(float cosTheta, FresnelData fd)
{
    return mx_fresnel_eval_film(cosTheta, fd, true);
}
