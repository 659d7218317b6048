// Hair scattering after Chiang et al. 2016 ("A Practical and Controllable Hair and Fur Model for
// Production Path Tracing"), the fibre a dielectric cylinder: each lobe p (0 R, 1 TT, 2 TRT, 3 the
// remainder TRRT+) is the product of a longitudinal term Mp (d'Eon et al. 2011), an attenuation Ap
// (Fresnel at the cuticle, absorption inside) and an azimuthal term Np (a trimmed logistic about
// the lobe's exit azimuth). Angles: theta from the normal plane of the fibre, phi about the fibre.
#include "mx_fresnel.glsl"

float mx_hair_cos_from_sin(float s)
{
    return sqrt(max(1.0 - s * s, 0.0));
}

// ln I0(x) of the modified Bessel function of the first kind: its power series
// sum (x^2 / 4)^k / (k!)^2 for moderate x, the asymptotic e^x / sqrt(2 pi x) (1 + 1 / 8x) beyond.
float mx_hair_log_bessel_i0(float x)
{
    if (x > 12.0)
        return x - 0.5 * log(2.0 * MX_PI * x) + log(1.0 + 0.125 / x);
    float quarter = 0.25 * x * x;
    float term = 1.0;
    float sum = 1.0;
    for (int k = 1; k < 14; k++)
    {
        term *= quarter / float(k * k);
        sum += term;
    }
    return log(sum);
}

// d'Eon et al. 2011: Mp = exp(-sin(i) sin(o) / v) I0(cos(i) cos(o) / v) / (2 v sinh(1 / v)), in log
// space throughout, with ln(2 v sinh(1/v)) = 1/v + ln v + ln(1 - exp(-2/v)), so that it stays finite
// for the small variances of glossy hair.
float mx_hair_longitudinal(float sinI, float cosI, float sinO, float cosO, float v)
{
    float inv = 1.0 / max(v, 1.0e-4);
    float logNormalisation = inv + log(1.0 / inv) + log(1.0 - exp(-2.0 * inv));
    return exp(mx_hair_log_bessel_i0(cosI * cosO * inv) - sinI * sinO * inv - logNormalisation);
}

float mx_hair_logistic_cdf(float x, float s)
{
    return 1.0 / (1.0 + exp(-x / s));
}

// Np: a logistic of scale s in the azimuth difference from the lobe's exit azimuth
// 2 p gammaT - 2 gammaO + p pi, wrapped to [-pi, pi] and normalised there (Chiang et al. 2016,
// eqs. 10-12; s carries their factor sqrt(pi / 8)).
float mx_hair_azimuthal(float phi, int p, float s, float gammaO, float gammaT)
{
    float fp = float(p);
    float offset = phi - (2.0 * fp * gammaT - 2.0 * gammaO + fp * MX_PI);
    offset -= 2.0 * MX_PI * floor((offset + MX_PI) / (2.0 * MX_PI));
    float scale = max(s * sqrt(MX_PI / 8.0), 1.0e-4);
    float e = exp(-abs(offset) / scale);
    float logistic = e / (scale * (1.0 + e) * (1.0 + e));
    return logistic / (mx_hair_logistic_cdf(MX_PI, scale) - mx_hair_logistic_cdf(-MX_PI, scale));
}

// Radiance scattered from L towards V by a fibre along X, normal N (where on the fibre's cross-
// section the view falls). roughness[p] = (longitudinal variance v, azimuthal scale s); the cuticle
// tilts the scales by alpha, shifting the R, TT and TRT lobes by 2 alpha, -alpha and -4 alpha.
vec3 mx_hair_scattering(vec3 L, vec3 V, vec3 N, vec3 X, vec3 tint[3], vec2 roughness[3], float ior, float cuticleAlpha,
                        vec3 absorption)
{
    mat3 frame = mx_tangent_frame(N, X);  // x along the fibre, z the normal
    vec3 Vt = V * frame;
    vec3 Lt = L * frame;
    float sinO = clamp(Vt.x, -1.0, 1.0);
    float sinI = clamp(Lt.x, -1.0, 1.0);
    float cosO = mx_hair_cos_from_sin(sinO);
    float cosI = mx_hair_cos_from_sin(sinI);
    float phi = atan(Lt.z * Vt.y - Lt.y * Vt.z, Lt.y * Vt.y + Lt.z * Vt.z);  // azimuth of L from V

    // Offset h = sin(gammaO) of the view across the fibre, and the refracted ray's gammaT, through
    // Bravais' modified index in the normal plane.
    vec2 across = normalize(vec2(Vt.y, Vt.z) + vec2(0.0, MX_EPS));
    float gammaO = asin(clamp(-across.x, -1.0, 1.0));
    float eta = mx_clamp_finite(ior, 1.0, MX_MAX_IOR);
    float etaPerp = sqrt(max(eta * eta - sinO * sinO, 0.0)) / max(cosO, MX_EPS);
    float gammaT = asin(clamp(sin(gammaO) / etaPerp, -1.0, 1.0));
    float cosThetaT = mx_hair_cos_from_sin(sinO / eta);

    // Ap: Fresnel f at the cuticle, transmittance T of one crossing of the fibre.
    float f = mx_fresnel_dielectric(cosO * cos(gammaO), eta);
    vec3 T = exp(-max(absorption, 0.0) * (2.0 * cos(gammaT) / max(cosThetaT, MX_EPS)));
    vec3 A = vec3(f);
    vec3 sum = vec3(0.0);
    for (int p = 0; p < 3; p++)
    {
        if (p == 1)
            A = (1.0 - f) * (1.0 - f) * T;
        else if (p == 2)
            A *= T * f;
        float tilt = (2.0 - 3.0 * float(p)) * cuticleAlpha;
        float sinTilted = sinI * cos(tilt) + cosI * sin(tilt);
        float cosTilted = abs(cosI * cos(tilt) - sinI * sin(tilt));
        float Mp = mx_hair_longitudinal(sinTilted, cosTilted, sinO, cosO, roughness[p].x);
        sum += Mp * mx_hair_azimuthal(phi, p, roughness[p].y, gammaO, gammaT) * A * max(tint[p], vec3(0.0));
    }
    // TRRT+: the geometric series of further internal bounces, spread evenly in azimuth.
    vec3 remainder = A * T * f / max(vec3(1.0) - T * f, MX_EPS);
    float Mp = mx_hair_longitudinal(sinI, cosI, sinO, cosO, roughness[2].x);
    return sum + Mp * remainder * max(tint[2], vec3(0.0)) / (2.0 * MX_PI);
}
