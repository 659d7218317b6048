#include "lib/mx_hextile.glsl"

// Rotate v about unit axis a by `angle` radians (right-handed, Rodrigues).
vec3 mx_hextile_axis_rotate(vec3 v, vec3 a, float angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return v * c + cross(a, v) * s + a * (dot(a, v) * (1.0 - c));
}

// normalize(), except that a zero vector (a fully cancelled perturbation) falls back to `n`
// instead of producing NaN.
vec3 mx_hextile_unit(vec3 v, vec3 n)
{
    float len2 = dot(v, v);
    return len2 > 1e-20 ? v * inversesqrt(len2) : n;
}

// Surface gradient of perturbed normal Np relative to N (Mikkelsen, "Surface Gradient-Based Bump
// Mapping Framework", JCGT 9(3), 2020).
vec3 mx_hextile_surface_gradient(vec3 N, vec3 Np)
{
    float d = dot(N, Np);
    return (d * N - Np) / max(1e-8, abs(d));
}

// <hextilednormalmap>: hex-tiled lookup of a tangent-space normal map. Each of the three samples is
// decoded in a tangent frame turned about N by its tile's rotation, so the bumps rotate with the
// texture; the three normals are blended as surface gradients.
void mx_hextilednormalmap_vector3(sampler2D file, vec3 dflt, vec2 texcoord, vec2 tiling, float rotation, vec2 rotationrange, float scale, vec2 scalerange, float offset, vec2 offsetrange, float falloff, float strength, bool flip_g, vec3 N, vec3 T, vec3 B, out vec3 result)
{
    vec2 uv1, uv2, uv3, dx1, dx2, dx3, dy1, dy2, dy3;
    vec3 tile, angles;
    vec2 uv = texcoord * tiling;
    mx_hextile_lookups(vec2(uv.x, 1.0 - uv.y), rotation, rotationrange, scale, scalerange,
                       offset, offsetrange, uv1, uv2, uv3, dx1, dx2, dx3, dy1, dy2, dy3, tile, angles);
    vec3 n1 = textureGrad(file, uv1, dx1, dy1).xyz;
    vec3 n2 = textureGrad(file, uv2, dx2, dy2).xyz;
    vec3 n3 = textureGrad(file, uv3, dx3, dy3).xyz;
    if (flip_g)
    {
        n1.y = 1.0 - n1.y;
        n2.y = 1.0 - n2.y;
        n3.y = 1.0 - n3.y;
    }
    n1 = n1 * 2.0 - 1.0;
    n2 = n2 * 2.0 - 1.0;
    n3 = n3 * 2.0 - 1.0;
    vec3 N1 = mx_hextile_unit(mx_hextile_axis_rotate(T, N, angles.x) * (strength * n1.x) + mx_hextile_axis_rotate(B, N, angles.x) * (strength * n1.y) + N * n1.z, N);
    vec3 N2 = mx_hextile_unit(mx_hextile_axis_rotate(T, N, angles.y) * (strength * n2.x) + mx_hextile_axis_rotate(B, N, angles.y) * (strength * n2.y) + N * n2.z, N);
    vec3 N3 = mx_hextile_unit(mx_hextile_axis_rotate(T, N, angles.z) * (strength * n3.x) + mx_hextile_axis_rotate(B, N, angles.z) * (strength * n3.y) + N * n3.z, N);

    vec3 w = clamp(mx_hextile_weights(vec3(1.0), tile, falloff), 0.0, 1.0);
    vec3 g = mx_hextile_surface_gradient(N, N1) * w.x + mx_hextile_surface_gradient(N, N2) * w.y + mx_hextile_surface_gradient(N, N3) * w.z;
    result = mx_hextile_unit(N - g, N);
}
