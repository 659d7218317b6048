// Diffuse reflectance models, each as a factor relative to Lambert (rho / pi):
//   Oren & Nayar 1994, the qualitative model (their eq. 30), renormalised to conserve energy;
//   EON, the energy-preserving Oren-Nayar of the OpenPBR specification (Fujii's improved model,
//       whose directional albedo has a closed form, plus a multiple-scattering lobe);
//   Burley 2012 ("Physically-Based Shading at Disney", sect. 5.3), renormalised to conserve energy.
// Renormalised: f / max(1, E(mu_l), E(mu_v)) with the model's directional albedo E from our table
// (tools/fit_albedo.py). Dividing by a symmetric factor keeps the model reciprocal, and the
// directional albedo of the result cannot exceed 1; it changes nothing where E <= 1 (Burley's
// retro-reflection reaches E = 1.55 at grazing angles for roughness 1, Oren-Nayar's 1.01).
#include "mx_pbr_common.glsl"
#include "mx_albedo_oren_nayar.glsl"
#include "mx_albedo_burley.glsl"

float mx_renormalisation(float albedoL, float albedoV)
{
    return 1.0 / max(1.0, max(albedoL, albedoV));
}

// --- Oren-Nayar, qualitative model ---------------------------------------------------------------

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

// --- EON (OpenPBR) -------------------------------------------------------------------------------

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

// --- Burley --------------------------------------------------------------------------------------

// The product of two Schlick-shaped factors with F90 = 0.5 + 2 roughness cos^2(theta_d).
float mx_burley(float NdotV, float NdotL, float LdotH, float roughness)
{
    float F90 = 0.5 + 2.0 * roughness * LdotH * LdotH;
    float lightSide = 1.0 + (F90 - 1.0) * mx_pow_5(1.0 - NdotL);
    float viewSide = 1.0 + (F90 - 1.0) * mx_pow_5(1.0 - NdotV);
    float renorm = mx_renormalisation(mx_burley_albedo(NdotL, roughness), mx_burley_albedo(NdotV, roughness));
    return lightSide * viewSide * renorm;
}
