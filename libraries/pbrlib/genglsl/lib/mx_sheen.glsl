// Sheen, the back-scattering of fibres (cloth, dust, peach fuzz), two ways:
//   microfiber: Estevez & Kulla 2017's distribution of fibre normals, D = (2 + 1/r) sin^(1/r) / 2pi,
//       over the smooth denominator 4 (NdotL + NdotV - NdotL NdotV) of Ashikhmin & Premoze 2007 in
//       place of masking-shadowing, renormalised by max(1, E(mu_l), E(mu_v)) with its directional
//       albedo E from our table (tools/fit_albedo.py): the plain model reflects up to 3.7 times the
//       light at grazing angles for small r, the renormalised one never more than arrives;
//   Zeltner et al. 2022: a linearly transformed cosine fitted to a volumetric fibre layer.
#include "mx_pbr_common.glsl"
#include "mx_albedo_sheen.glsl"

// --- Microfiber (Estevez & Kulla 2017 distribution) -------------------------------------------------

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

// --- Zeltner et al. 2022 (LTC) -------------------------------------------------------------------
// The albedo and inverse-matrix fits are the paper's own (published with its supplemental code,
// github.com/tizian/ltc-sheen); x = NdotV, y = roughness.

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

// A direction L (in the LTC's frame, mx_sheen_ltc_frame) drawn from the LTC lobe: a cosine-
// distributed direction through the matrix, the inverse of mx_sheen_ltc_inverse's; the lobe's
// density there is mx_sheen_ltc.
vec3 mx_sheen_ltc_sample(vec2 u, float NdotV, float roughness)
{
    vec2 inv = mx_sheen_ltc_inverse(NdotV, roughness);
    vec3 wo = mx_cosine_sample(u);
    return normalize(vec3((wo.x - inv.y * wo.z) / inv.x, wo.y / inv.x, wo.z));
}
