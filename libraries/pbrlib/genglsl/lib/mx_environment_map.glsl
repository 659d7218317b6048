// The lat-long environment map: lookups along world directions, shared by the two ways of lighting
// with it (mx_environment_fis.glsl, mx_environment_prefilter.glsl).
//
// Map convention: texel (u, v) with v = 0 the top row holds map direction
// (cos(lat) sin(lon), sin(lat), -cos(lat) cos(lon)), lat = (0.5 - v) pi, lon = (u - 0.5) 2 pi.
#include "mx_pbr_common.glsl"

// The texel coordinates of map direction `mapDir`, a unit vector up to rounding.
vec2 mx_envmap_uv(vec3 mapDir)
{
    return vec2(atan(mapDir.x, -mapDir.z) * MX_INV_PI * 0.5 + 0.5, 0.5 - asin(clamp(mapDir.y, -1.0, 1.0)) * MX_INV_PI);
}

// The map `envMap` seen along map direction `mapDir`, at mip level `lod`.
vec3 mx_envmap_lookup(sampler2D envMap, vec3 mapDir, float lod)
{
    return textureLod(envMap, mx_envmap_uv(mapDir), lod).rgb;
}

// The map `envMap` seen along world direction `dir`, at mip level `lod`.
vec3 mx_envmap_fetch(sampler2D envMap, vec3 dir, float lod)
{
    return mx_envmap_lookup(envMap, normalize((u_envMatrix * vec4(dir, 0.0)).xyz), lod);
}

// Direction leaving a solid sphere of index `ior` that ray direction R enters where the normal is N.
// Where a refraction is total internal reflection the ray reflects instead, so a direction always
// comes back.
vec3 mx_refraction_solid_sphere(vec3 R, vec3 N, float ior)
{
    float eta = max(ior, 1.0e-3);
    vec3 inside = refract(R, N, 1.0 / eta);
    if (dot(inside, inside) == 0.0)
        return reflect(R, N);
    vec3 exitNormal = normalize(inside * dot(inside, N) - N * 0.5);
    vec3 leaving = refract(inside, exitNormal, eta);
    return (dot(leaving, leaving) == 0.0) ? reflect(inside, exitNormal) : leaving;
}

// Irradiance / pi arriving at a point with normal N: what a white Lambert surface reflects.
vec3 mx_environment_irradiance(vec3 N)
{
    return mx_envmap_fetch(u_envIrradiance, N, 0.0) * u_envLightIntensity;
}
