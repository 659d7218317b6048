// Worley (cellular) noise: one feature point per unit cell, placed at the cell centre plus a
// cell-noise offset scaled by jitter; the 3x3 (2D) or 3x3x3 (3D) neighbourhood is searched for
// the nearest three points, by Euclidean distance.
//
// mx_wn_search* return the three smallest squared distances, sorted, and the offset from the
// sample to the nearest point. Style "Solid" (1) reads cell noise at that nearest point,
// style "Distance" (0) returns the distances themselves.

#include "mx_hash_noise.glsl"

void mx_wn_search(vec2 p, float jitter, out vec3 dist, out vec2 nearest)
{
    vec2 fl = floor(p);
    ivec2 base = ivec2(fl);
    vec2 local = p - fl;
    dist = vec3(1.0e6);
    nearest = vec2(0.0);
    for (int i = -1; i <= 1; ++i)
    {
        for (int j = -1; j <= 1; ++j)
        {
            ivec2 cell = base + ivec2(i, j);
            vec2 jit = vec2(mx_hn_unit(mx_hn_hash(cell.x, cell.y, 0)),
                            mx_hn_unit(mx_hn_hash(cell.x, cell.y, 1)));
            vec2 d = (vec2(float(i), float(j)) + ((jit - 0.5) * jitter + 0.5)) - local;
            float dd = dot(d, d);
            if (dd < dist.x)
            {
                dist = vec3(dd, dist.x, dist.y);
                nearest = d;
            }
            else if (dd < dist.y)
            {
                dist.z = dist.y;
                dist.y = dd;
            }
            else if (dd < dist.z)
            {
                dist.z = dd;
            }
        }
    }
}

void mx_wn_search(vec3 p, float jitter, out vec3 dist, out vec3 nearest)
{
    vec3 fl = floor(p);
    ivec3 base = ivec3(fl);
    vec3 local = p - fl;
    dist = vec3(1.0e6);
    nearest = vec3(0.0);
    for (int i = -1; i <= 1; ++i)
    {
        for (int j = -1; j <= 1; ++j)
        {
            for (int k = -1; k <= 1; ++k)
            {
                ivec3 cell = base + ivec3(i, j, k);
                vec3 jit = mx_hn_cell3(cell);
                vec3 d = (vec3(float(i), float(j), float(k)) + ((jit - 0.5) * jitter + 0.5)) - local;
                float dd = dot(d, d);
                if (dd < dist.x)
                {
                    dist = vec3(dd, dist.x, dist.y);
                    nearest = d;
                }
                else if (dd < dist.y)
                {
                    dist.z = dist.y;
                    dist.y = dd;
                }
                else if (dd < dist.z)
                {
                    dist.z = dd;
                }
            }
        }
    }
}

float mx_wn_worley(vec2 p, float jitter, int style)
{
    vec3 dist;
    vec2 nearest;
    mx_wn_search(p, jitter, dist, nearest);
    return (style == 1) ? mx_hn_cell(nearest + p) : sqrt(dist.x);
}

vec2 mx_wn_worley2(vec2 p, float jitter, int style)
{
    vec3 dist;
    vec2 nearest;
    mx_wn_search(p, jitter, dist, nearest);
    return (style == 1) ? mx_hn_cell3(nearest + p).xy : sqrt(dist.xy);
}

vec3 mx_wn_worley3(vec2 p, float jitter, int style)
{
    vec3 dist;
    vec2 nearest;
    mx_wn_search(p, jitter, dist, nearest);
    return (style == 1) ? mx_hn_cell3(nearest + p) : sqrt(dist);
}

float mx_wn_worley(vec3 p, float jitter, int style)
{
    vec3 dist;
    vec3 nearest;
    mx_wn_search(p, jitter, dist, nearest);
    return (style == 1) ? mx_hn_cell(nearest + p) : sqrt(dist.x);
}

vec2 mx_wn_worley2(vec3 p, float jitter, int style)
{
    vec3 dist;
    vec3 nearest;
    mx_wn_search(p, jitter, dist, nearest);
    return (style == 1) ? mx_hn_cell3(nearest + p).xy : sqrt(dist.xy);
}

vec3 mx_wn_worley3(vec3 p, float jitter, int style)
{
    vec3 dist;
    vec3 nearest;
    mx_wn_search(p, jitter, dist, nearest);
    return (style == 1) ? mx_hn_cell3(nearest + p) : sqrt(dist);
}
