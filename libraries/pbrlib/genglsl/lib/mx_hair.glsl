// Building blocks of Chiang et al.'s hair BCSDF (2016, after d'Eon et al. 2011): longitudinal
// scattering Mp, azimuthal scattering Np, and the attenuations Ap of the R, TT, TRT and TRRT+ lobes.
#include "mx_fresnel.glsl"

float mx_hair_cos_from_sin(float s)
{
    return sqrt(max(1.0 - s * s, 0.0));
}

// Modified Bessel function of the first kind, order 0: ten terms of its power series.
float mx_hair_bessel_i0(float x)
{
    float sum = 1.0;
    float term = 1.0;     // (x^2 / 4)^k
    float factSq = 1.0;   // (k!)^2
    float x2 = x * x;
    for (int k = 1; k <= 9; k++)
    {
        float fk = float(k);
        factSq *= 4.0 * fk * fk;
        term *= x2;
        sum += term / factSq;
    }
    return sum;
}

float mx_hair_log_bessel_i0(float x)
{
    if (x > 12.0)  // asymptotic expansion
        return x + 0.5 * (-log(2.0 * MX_PI) + log(1.0 / x) + 1.0 / (8.0 * x));
    return log(mx_hair_bessel_i0(x));
}

// Longitudinal scattering for variance v (d'Eon et al. 2011), in log space for small v.
float mx_hair_Mp(float sinThetaI, float cosThetaI, float sinThetaO, float cosThetaO, float v)
{
    float invV = 1.0 / v;
    float a = cosThetaO * cosThetaI * invV;
    float b = sinThetaO * sinThetaI * invV;
    if (v < 0.1)
        return exp(mx_hair_log_bessel_i0(a) - b - invV + 0.6931 + log(0.5 * invV));
    return exp(-b) * mx_hair_bessel_i0(a) / (2.0 * v * sinh(invV));
}

// Logistic distribution of scale s (and its CDF), trimmed to [a, b] and normalised there.
float mx_hair_logistic(float x, float s)
{
    float e = exp(-abs(x) / s);
    return e / (s * (1.0 + e) * (1.0 + e));
}

float mx_hair_logistic_cdf(float x, float s)
{
    return 1.0 / (1.0 + exp(-x / s));
}

float mx_hair_trimmed_logistic(float x, float s, float a, float b)
{
    s *= 0.626657;  // sqrt(pi / 8): Chiang et al. 2016, appendix A, eq. 12
    return mx_hair_logistic(x, s) / (mx_hair_logistic_cdf(b, s) - mx_hair_logistic_cdf(a, s));
}

// Azimuthal scattering of lobe p (0 R, 1 TT, 2 TRT) for azimuth phi and scale s.
float mx_hair_Np(float phi, int p, float s, float gammaO, float gammaT)
{
    float fp = float(p);
    float dphi = phi - (2.0 * fp * gammaT - 2.0 * gammaO + fp * MX_PI);
    if (isinf(dphi))
        return 0.5 / MX_PI;
    dphi -= 2.0 * MX_PI * floor((dphi + MX_PI) / (2.0 * MX_PI));  // wrap into [-pi, pi)
    return mx_hair_trimmed_logistic(dphi, s, -MX_PI, MX_PI);
}
