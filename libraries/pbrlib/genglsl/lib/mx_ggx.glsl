// GGX (Trowbridge-Reitz) microfacets after Walter et al. 2007, with Smith masking-shadowing in
// Heitz 2014's height-correlated form, visible-normal sampling, and multiple-scattering energy
// compensation from our own albedo table (tools/fit_albedo.py; Kulla & Conty 2017, Turquin 2019).
// Directions are in the tangent frame: x along the tangent, z along the normal; alpha = (alpha_x,
// alpha_y) is the roughness along x and y.
#include "mx_fresnel.glsl"
#include "mx_albedo_ggx.glsl"

// Smallest alpha the lobe uses: a mirror to 1e-4, without the overflow of D at alpha -> 0.
const float MX_GGX_MIN_ALPHA = 1.0e-4;

vec2 mx_ggx_clamp_alpha(vec2 alpha)
{
    return mx_clamp_finite(alpha, MX_GGX_MIN_ALPHA, 1.0);
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

// mx_ggx_sample_weight with the view's Lambda(V) given: the samples of one view share it.
float mx_ggx_sample_weight_given(float lambdaV, vec3 L, vec2 alpha)
{
    if (L.z <= 0.0)
        return 0.0;
    return (1.0 + lambdaV) / (1.0 + lambdaV + mx_ggx_lambda(L, alpha));
}

// What a light direction sampled through a visible normal carries, f cos / pdf with F = 1:
// G2 / G1 (Heitz 2014, sect. 5.3), 0 below the horizon.
float mx_ggx_sample_weight(vec3 V, vec3 L, vec2 alpha)
{
    return mx_ggx_sample_weight_given(mx_ggx_lambda(V, alpha), L, alpha);
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

// Single-scattering directional albedo with Schlick's Fresnel between F0 and F90.
vec3 mx_ggx_albedo(float NdotV, float alpha, vec3 F0, vec3 F90)
{
    vec2 scaleBias = mx_ggx_albedo_schlick_scale_bias(NdotV, alpha);
    return F0 * scaleBias.x + F90 * scaleBias.y;
}

// Turquin 2019: the lobe scaled by 1 + F (1 - E) / E returns the energy that single scattering
// loses between microfacets (1 - E with a white Fresnel), tinted by the Fresnel colour F.
vec3 mx_ggx_energy_compensation(float NdotV, float alpha, vec3 F)
{
    vec2 scaleBias = mx_ggx_albedo_schlick_scale_bias(NdotV, alpha);
    float E = max(scaleBias.x + scaleBias.y, MX_EPS);
    return vec3(1.0) + F * ((1.0 - E) / E);
}
