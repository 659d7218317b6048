// Parameter conversions of the PBR library.
#include "lib/mx_pbr_common.glsl"

// <roughness_anisotropy>: GGX alpha along the tangent and bitangent from a perceptual roughness
// (squared) and an anisotropy that stretches the lobe along the tangent.
void mx_roughness_anisotropy(float roughness, float anisotropy, out vec2 result)
{
    float alpha = clamp(roughness * roughness, MX_EPS, 1.0);
    if (anisotropy > 0.0)
    {
        float aspect = sqrt(1.0 - clamp(anisotropy, 0.0, 0.98));
        result = vec2(min(alpha / aspect, 1.0), alpha * aspect);
    }
    else
    {
        result = vec2(alpha);
    }
}

// <roughness_dual>: GGX alpha from two perceptual roughnesses; a negative y repeats x.
void mx_roughness_dual(vec2 roughness, out vec2 result)
{
    vec2 r = vec2(roughness.x, (roughness.y < 0.0) ? roughness.x : roughness.y);
    result = clamp(r * r, MX_EPS, 1.0);
}

// <artistic_ior>: complex index of refraction (n, k) of a metal from its reflectivity at normal
// incidence and its edge tint (Gulbrandsen 2014).
void mx_artistic_ior(vec3 reflectivity, vec3 edge_color, out vec3 ior, out vec3 extinction)
{
    vec3 r = clamp(reflectivity, 0.0, 0.99);
    vec3 sr = sqrt(r);
    vec3 nFromEdge = (1.0 - r) / (1.0 + r);      // the n that gives r with k = 0
    vec3 nFromFacing = (1.0 + sr) / (1.0 - sr);  // the largest n that gives r
    ior = mix(nFromFacing, nFromEdge, edge_color);
    vec3 k2 = ((ior + 1.0) * (ior + 1.0) * r - (ior - 1.0) * (ior - 1.0)) / (1.0 - r);
    extinction = sqrt(max(k2, 0.0));
}

// <blackbody>: linear Rec.709 colour of a black body at `temperature` kelvin, normalised to
// luminance 1: the Planckian locus in CIE xy (the cubic splines of Kang et al. 2002, from 800 K to 25000 K)
// taken to XYZ with Y = 1, then to Rec.709, negative channels dropped.
void mx_blackbody(float temperature, out vec3 result)
{
    float T = clamp(temperature, 800.0, 25000.0);
    float t = 1000.0 / T;
    float t2 = t * t;
    float t3 = t2 * t;
    float x = (T < 4000.0) ? -0.2661239 * t3 - 0.2343580 * t2 + 0.8776956 * t + 0.179910
                           : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t + 0.240390;
    float x2 = x * x;
    float x3 = x2 * x;
    float y;
    if (T < 2222.0)
        y = -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683;
    else if (T < 4000.0)
        y = -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867;
    else
        y = 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    if (y <= 0.0)
    {
        result = vec3(1.0);
        return;
    }
    vec3 XYZ = vec3(x / y, 1.0, (1.0 - x - y) / y);
    const mat3 XYZ_TO_REC709 = mat3(3.2406, -0.9689, 0.0557,   // columns
                                    -1.5372, 1.8758, -0.2040,
                                    -0.4986, 0.0415, 1.0570);
    result = max(XYZ_TO_REC709 * XYZ, vec3(0.0));
}
