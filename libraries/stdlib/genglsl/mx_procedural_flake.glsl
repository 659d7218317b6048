// <flake2d> and <flake3d>: randomly oriented cubic flakes on a lattice of cells of edge `size`.
// Each cell holds a flake with a probability derived from `coverage`; the flake is a cube of
// half-width 1.5/sqrt(3) (in cell units) around the cell centre, turned by a random rotation
// (Arvo, "Fast Random Rotation Matrices", Graphics Gems III). Where flakes overlap, the one with
// the highest random priority wins. Its normal tilts the shading normal by a GGX sample of the
// given roughness. flake2d uses the 3D flakes on the plane z = 0 of texture space.

#include "lib/mx_hash_noise.glsl"

// Uniformly random rotation of p from three uniform numbers in [0, 1] (Arvo): a rotation about
// z by 2*pi*r.x, composed with a reflection through the plane normal to a random direction
// v (azimuth 2*pi*r.y, |v|^2 = 2, v.z = sqrt(2 - 2*r.z)), negated to keep it a rotation.
vec3 mx_flake_rotate(vec3 p, vec3 r)
{
    float theta = 6.283185307179586 * r.x;
    float phi = 6.283185307179586 * r.y;
    float z = 2.0 * r.z;
    float rad = sqrt(z);
    vec3 v = vec3(sin(phi) * rad, cos(phi) * rad, sqrt(2.0 - z));
    float st = sin(theta);
    float ct = cos(theta);
    float sx = v.x * ct - v.y * st;
    float sy = v.x * st + v.y * ct;
    vec3 col0 = vec3(v.x * sx - ct, v.x * sy - st, v.x * v.z);
    vec3 col1 = vec3(v.y * sx + st, v.y * sy - ct, v.y * v.z);
    vec3 col2 = vec3(v.z * sx, v.z * sy, 1.0 - z);
    return mat3(col0, col1, col2) * p;
}

// Probability that a cell holds a flake for a requested coverage in [0, 1] (a rational fit of
// the observed coverage of the overlapping cubes).
float mx_flake_probability(float coverage)
{
    float x = coverage;
    float x2 = x * x;
    return (-26.19771808 * x2 + 26.39663835 * x) /
           (85.53857017 * x2 * x - 102.35069432 * x2 - 101.42634862 * x + 118.45082288);
}

void mx_flake_eval(float size, float roughness, float coverage, vec3 position, vec3 normal, vec3 tangent,
                   vec3 bitangent, out int id, out float rand, out float presence, out vec3 flakenormal)
{
    float probability = mx_flake_probability(clamp(coverage, 0.0, 1.0));
    float halfwidth = 1.5 / sqrt(3.0);
    float reach2 = halfwidth * halfwidth * 3.0;

    vec3 P = position / vec3(size);
    vec3 base = floor(P);
    float best = 0.0;
    vec3 bestCell = vec3(0.0);
    for (int i = -1; i < 2; ++i)
    {
        for (int j = -1; j < 2; ++j)
        {
            for (int k = -1; k < 2; ++k)
            {
                vec3 cell = base + vec3(float(i), float(j), float(k));
                vec3 local = P - cell - vec3(0.5);
                if (dot(local, local) >= reach2)
                    continue;
                if (mx_hn_cell(cell) > probability)
                    continue;
                float priority = mx_hn_cell(vec4(cell, 3.0));
                if (priority < best)
                    continue;
                local = mx_flake_rotate(local, mx_hn_cell3(cell));
                if (all(lessThanEqual(abs(local), vec3(halfwidth))))
                {
                    best = priority;
                    bestCell = cell;
                }
            }
        }
    }

    if (best <= 0.0)
    {
        id = 0;
        rand = 0.0;
        presence = 0.0;
        flakenormal = normal;
        return;
    }

    vec3 xi = mx_hn_cell3(vec4(bestCell, 2.0));
    rand = xi.z;
    id = int(rand * 16777215.0);
    presence = best;

    // GGX importance sample of the flake's tilt: tan(theta) = alpha * sqrt(u / (1 - u)).
    float phi = 6.283185307179586 * xi.x;
    float tanTheta = roughness * roughness * sqrt(xi.y) / sqrt(1.0 - xi.y);
    float sinTheta = tanTheta / sqrt(1.0 + tanTheta * tanTheta);
    float cosTheta = sqrt(1.0 - sinTheta * sinTheta);
    flakenormal = normalize(tangent * cos(phi) * sinTheta + bitangent * sin(phi) * sinTheta + normal * cosTheta);
}

void mx_flake2d(float size, float roughness, float coverage, vec2 texcoord, vec3 normal, vec3 tangent,
                vec3 bitangent, out int id, out float rand, out float presence, out vec3 flakenormal)
{
    mx_flake_eval(size, roughness, coverage, vec3(texcoord, 0.0), normal, tangent, bitangent,
                  id, rand, presence, flakenormal);
}

void mx_flake3d(float size, float roughness, float coverage, vec3 position, vec3 normal, vec3 tangent,
                vec3 bitangent, out int id, out float rand, out float presence, out vec3 flakenormal)
{
    mx_flake_eval(size, roughness, coverage, position, normal, tangent, bitangent,
                  id, rand, presence, flakenormal);
}
