// Diffuse reflectance models: Oren-Nayar (qualitative, and the energy-conserving variant of
// OpenPBR built on Fujii's improved model), Burley (Disney 2012), and a screen-space approximation
// of Burley's normalised diffusion for subsurface scattering.
#include "mx_pbr_common.glsl"

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

// --- Burley ----------------------------------------------------------------------------------

// Reflectance relative to Lambert: the retro-reflective Fresnel factors of both directions.
float mx_burley(float NdotV, float NdotL, float LdotH, float roughness)
{
    float F90 = 0.5 + 2.0 * roughness * LdotH * LdotH;
    float towardsL = mix(1.0, F90, mx_pow_5(clamp(1.0 - NdotL, 0.0, 1.0)));
    float towardsV = mix(1.0, F90, mx_pow_5(clamp(1.0 - NdotV, 0.0, 1.0)));
    return towardsL * towardsV;
}

// Directional albedo, Stephen Hill's fit.
float mx_burley_albedo(float NdotV, float roughness)
{
    float x = NdotV;
    float smooth_ = 0.97619 - 0.488095 * mx_pow_5(1.0 - x);
    float rough = 1.55754 + (-2.02221 + (2.56283 - 1.06244 * x) * x) * x;
    return mix(smooth_, rough, roughness);
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
