// <flake2d> and <flake3d>: flakes of a metallic paint, one per cell of a jittered lattice.
//
// Space is cut into cubic cells of edge `size`; each cell has a seed point at a random position
// inside it, and every point belongs to the nearest seed (a Voronoi partition, as in Worley's
// cellular noise), so the flakes are convex polyhedra that tile space. A cell holds a flake with
// probability `coverage`; since every cell's region is chosen independently, `coverage` is also
// the expected fraction of the surface the flakes cover, with no fitted mapping. A flake's normal
// is the shading normal tilted by a GGX-distributed angle of alpha = roughness^2 (Walter et al.
// 2007, eqs. 35-36). flake2d uses the plane z = 0 of (texcoord, z).
#include "lib/mx_hash_noise.glsl"

// Random numbers of a cell, by purpose (the fourth key word keeps the streams independent).
const float MX_FLAKE_SEED = 0.0;
const float MX_FLAKE_PRESENCE = 1.0;
const float MX_FLAKE_TILT = 2.0;

void mx_flake_eval(float size, float roughness, float coverage, vec3 position, vec3 normal, vec3 tangent,
                   vec3 bitangent, out int id, out float rand, out float presence, out vec3 flakenormal)
{
    vec3 P = position / max(size, 1.0e-6);
    vec3 home = floor(P);
    vec3 nearestCell = home;
    float nearest2 = 1.0e30;
    for (int i = 0; i < 27; ++i)
    {
        vec3 cell = home + vec3(float(i % 3), float((i / 3) % 3), float(i / 9)) - vec3(1.0);
        vec3 seed = cell + mx_hn_cell3(vec4(cell, MX_FLAKE_SEED));
        vec3 d = P - seed;
        float d2 = dot(d, d);
        if (d2 < nearest2)
        {
            nearest2 = d2;
            nearestCell = cell;
        }
    }

    vec3 tilt = mx_hn_cell3(vec4(nearestCell, MX_FLAKE_TILT));
    if (mx_hn_cell(vec4(nearestCell, MX_FLAKE_PRESENCE)) >= clamp(coverage, 0.0, 1.0))
    {
        id = 0;
        rand = 0.0;
        presence = 0.0;
        flakenormal = normal;
        return;
    }
    rand = tilt.z;
    id = int(rand * 16777215.0);
    presence = 1.0;

    // GGX: tan(theta) = alpha sqrt(u / (1 - u)), azimuth uniform.
    float alpha = roughness * roughness;
    float tanTheta = alpha * sqrt(tilt.y / max(1.0 - tilt.y, 1.0e-6));
    float cosTheta = inversesqrt(1.0 + tanTheta * tanTheta);
    float sinTheta = tanTheta * cosTheta;
    float phi = 6.283185307179586 * tilt.x;
    flakenormal = normalize((tangent * cos(phi) + bitangent * sin(phi)) * sinTheta + normal * cosTheta);
}

void mx_flake2d(float size, float roughness, float coverage, vec2 texcoord, vec3 normal, vec3 tangent,
                vec3 bitangent, out int id, out float rand, out float presence, out vec3 flakenormal)
{
    mx_flake_eval(size, roughness, coverage, vec3(texcoord, 0.0), normal, tangent, bitangent, id, rand, presence,
                  flakenormal);
}

void mx_flake3d(float size, float roughness, float coverage, vec3 position, vec3 normal, vec3 tangent,
                vec3 bitangent, out int id, out float rand, out float presence, out vec3 flakenormal)
{
    mx_flake_eval(size, roughness, coverage, position, normal, tangent, bitangent, id, rand, presence, flakenormal);
}
