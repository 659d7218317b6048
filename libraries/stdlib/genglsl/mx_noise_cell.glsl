// <cellnoise2d> and <cellnoise3d>: one random value in [0, 1] per unit cell.

#include "lib/mx_hash_noise.glsl"

void mx_cellnoise2d_float(vec2 texcoord, out float result)
{
    result = mx_hn_cell(texcoord);
}

void mx_cellnoise3d_float(vec3 position, out float result)
{
    result = mx_hn_cell(position);
}
