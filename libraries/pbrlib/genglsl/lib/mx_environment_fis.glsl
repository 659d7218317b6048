// Image-based lighting from a lat-long environment map, by filtered importance sampling (Krivanek
// & Colbert 2008): GGX visible normals drawn from a spherical Fibonacci set, each environment
// sample fetched from the mip level whose texel covers the sample's solid angle.
//
// Uniforms (declared by the generator with the surface node): u_envRadiance (mipmapped radiance),
// u_envIrradiance (irradiance / pi), u_envMatrix (world -> map direction), u_envRadianceMips (levels
// in the radiance map's mip chain), u_envRadianceSamples, u_envLightIntensity.
//
// Map convention: texel (u, v) with v = 0 the top row holds map direction
// (cos(lat) sin(lon), sin(lat), -cos(lat) cos(lon)), lat = (0.5 - v) pi, lon = (u - 0.5) 2 pi.
#include "mx_ggx.glsl"

vec2 mx_envmap_uv(vec3 dir)
{
    return vec2(atan(dir.x, -dir.z) * MX_INV_PI * 0.5 + 0.5, 0.5 - asin(dir.y) * MX_INV_PI);
}

// The map `envMap` seen along world direction `dir`, at mip level `lod`.
vec3 mx_envmap_fetch(sampler2D envMap, vec3 dir, float lod)
{
    vec3 mapDir = normalize((u_envMatrix * vec4(dir, 0.0)).xyz);
    return textureLod(envMap, mx_envmap_uv(mapDir), lod).rgb;
}

// Mip level for a sample of density `pdf` along world direction `dir` (GPU Gems 3, 20.4, eq. 13),
// with the lat-long map's stretching towards the poles, biased 1.5 levels sharper.
float mx_envmap_lod(vec3 dir, float pdf, int sampleCount)
{
    float coarsest = float(u_envRadianceMips - 1) - 1.5;
    float stretch = sqrt(1.0 - dir.y * dir.y);
    return max(coarsest - 0.5 * log2(float(sampleCount) * pdf * stretch), 0.0);
}

// Direction leaving a solid sphere of index `ior` that ray direction R enters where the normal is N.
vec3 mx_refraction_solid_sphere(vec3 R, vec3 N, float ior)
{
    vec3 inside = refract(R, N, 1.0 / ior);
    vec3 exitNormal = normalize(inside * dot(inside, N) - N * 0.5);
    return refract(inside, exitNormal, ior);
}

// Light leaving a point with normal N towards V (tangent X) after one GGX bounce, or, with
// fd.refraction, after passing through a solid sphere of index fd.ior.x.
vec3 mx_environment_radiance(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd)
{
    int sampleCount = u_envRadianceSamples;
    if (sampleCount <= 0)
        return vec3(0.0);

    mat3 frame = mx_tangent_frame(N, X);
    vec3 Vt = V * frame;  // (V.X, V.Y, V.N)
    float NdotV = clamp(Vt.z, MX_EPS, 1.0);
    float avgAlpha = mx_average_alpha(alpha);
    float G1V = mx_ggx_G1(NdotV, avgAlpha);

    vec3 sum = vec3(0.0);
    for (int i = 0; i < sampleCount; i++)
    {
        vec3 H = mx_ggx_sample_visible_normal(mx_fibonacci_point(i, sampleCount), Vt, alpha);
        vec3 Lt = fd.refraction ? mx_refraction_solid_sphere(-Vt, H, fd.ior.x) : reflect(-Vt, H);
        float NdotL = clamp(Lt.z, MX_EPS, 1.0);
        float VdotH = clamp(dot(Vt, H), MX_EPS, 1.0);

        vec3 Lw = frame * Lt;
        float lod = mx_envmap_lod(Lw, mx_ggx_reflection_pdf(H, alpha, G1V, NdotV), sampleCount);
        vec3 Li = mx_envmap_fetch(u_envRadiance, Lw, lod);

        // Radiance times BRDF times cosine over the sample density leaves F G2 / G1(V); G1(V) is
        // divided out once below. Refraction keeps what the interface does not reflect.
        vec3 F = mx_fresnel_eval(VdotH, fd);
        sum += Li * (fd.refraction ? vec3(1.0) - F : F * mx_ggx_G2(NdotL, NdotV, avgAlpha));
    }
    return sum / (G1V * float(sampleCount)) * u_envLightIntensity;
}

// Irradiance / pi arriving at a point with normal N: what a white Lambert surface reflects.
vec3 mx_environment_irradiance(vec3 N)
{
    return mx_envmap_fetch(u_envIrradiance, N, 0.0) * u_envLightIntensity;
}
