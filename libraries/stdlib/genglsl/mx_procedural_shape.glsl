// Shape nodes (<line>, <cloverleaf>, <hexagon>; <circle> is inline) and the tiled patterns
// built from them: <grid>, <crosshatch>, <tiledcircles>, <tiledcloverleafs>, <tiledhexagons>.
// Tiled patterns work in tile space uv = texcoord * uvtiling - uvoffset; "staggered" shifts
// every other row by half a tile.

#include "lib/mx_shape_mask.glsl"

void mx_line_float(vec2 texcoord, vec2 center, float radius, vec2 point1, vec2 point2, out float result)
{
    result = mx_shape_line(texcoord, center, radius, point1, point2);
}

void mx_cloverleaf_float(vec2 texcoord, vec2 center, float radius, out float result)
{
    result = mx_shape_cloverleaf(texcoord, center, radius);
}

void mx_hexagon_float(vec2 texcoord, vec2 center, float radius, out float result)
{
    result = mx_shape_hexagon(texcoord, center, radius);
}

// Position inside the unit tile mapped to [-1, 1]^2, rows of two tiles shifted when staggered.
vec2 mx_tile_local(vec2 texcoord, vec2 uvtiling, vec2 uvoffset, bool staggered)
{
    vec2 uv = texcoord * uvtiling - uvoffset;
    float x = uv.x;
    if (staggered && mod(uv.y, 2.0) > 1.0)
        x += 0.5;
    return vec2(mod(x, 1.0), mod(uv.y, 1.0)) * 2.0 - 1.0;
}

void mx_grid_color3(vec2 texcoord, vec2 uvtiling, vec2 uvoffset, float thickness, bool staggered, out vec3 result)
{
    vec2 a = abs(mx_tile_local(texcoord, uvtiling, uvoffset, staggered));
    float edge = 1.0 - thickness;
    result = vec3((a.x > edge || a.y > edge) ? 1.0 : 0.0);
}

void mx_crosshatch_color3(vec2 texcoord, vec2 uvtiling, vec2 uvoffset, float thickness, bool staggered, out vec3 result)
{
    vec2 s = mx_tile_local(texcoord, uvtiling, uvoffset, staggered);
    float d1 = mx_shape_line(s, vec2(0.0), thickness, vec2(1.0, 1.0), vec2(-1.0, -1.0));
    float d2 = mx_shape_line(s, vec2(0.0), thickness, vec2(-1.0, 1.0), vec2(1.0, -1.0));
    result = vec3(max(d1, d2));
}

float mx_tiled_mask(int shape, vec2 p, float radius)
{
    if (shape == 0)
        return mx_shape_circle(p, vec2(0.0), radius);
    if (shape == 1)
        return mx_shape_cloverleaf(p, vec2(0.0), radius);
    return mx_shape_hexagon(p, vec2(0.0), radius);
}

// Regular: one shape of diameter `size` (in tile units) per tile. Staggered: shapes of half
// that radius on rows `rowstep` apart, alternate rows offset by half a tile; each sample tests
// the three nearest shape centres of its row pair.
float mx_tiled_shapes(int shape, float rowstep, vec2 texcoord, vec2 uvtiling, vec2 uvoffset, float size, bool staggered)
{
    vec2 uv = texcoord * uvtiling - uvoffset;
    if (!staggered)
        return mx_tiled_mask(shape, mod(uv, 1.0) * 2.0 - 1.0, size);
    float x = uv.x;
    if (mod(uv.y, rowstep * 2.0) > rowstep)
        x += 0.5;
    float mx = mod(x, 1.0);
    float my = mod(uv.y, rowstep);
    float r = size / 2.0;
    float a = max(mx_tiled_mask(shape, vec2(mx, my), r), mx_tiled_mask(shape, vec2(1.0 - mx, my), r));
    return max(a, mx_tiled_mask(shape, vec2(mx - 0.5, rowstep - my), r));
}

void mx_tiledcircles_color3(vec2 texcoord, vec2 uvtiling, vec2 uvoffset, float size, bool staggered, out vec3 result)
{
    result = vec3(mx_tiled_shapes(0, 0.866025, texcoord, uvtiling, uvoffset, size, staggered));
}

void mx_tiledcloverleafs_color3(vec2 texcoord, vec2 uvtiling, vec2 uvoffset, float size, bool staggered, out vec3 result)
{
    result = vec3(mx_tiled_shapes(1, 0.5, texcoord, uvtiling, uvoffset, size, staggered));
}

void mx_tiledhexagons_color3(vec2 texcoord, vec2 uvtiling, vec2 uvoffset, float size, bool staggered, out vec3 result)
{
    result = vec3(mx_tiled_shapes(2, 0.866025, texcoord, uvtiling, uvoffset, size, staggered));
}
