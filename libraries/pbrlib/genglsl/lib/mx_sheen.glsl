// Sheen: the Imageworks microfiber lobe (Conty & Kulla 2017) and Zeltner et al.'s multiple-
// scattering LTC sheen (2022), each with its directional albedo for layering.
#include "mx_pbr_common.glsl"

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
