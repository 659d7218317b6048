// The GGX (Trowbridge-Reitz) microfacet model: distribution, visible-normal sampling, Smith
// masking-shadowing, and the directional albedo used for energy compensation and layering.
#include "mx_fresnel.glsl"

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
