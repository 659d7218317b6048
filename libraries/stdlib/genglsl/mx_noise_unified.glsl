// <unifiednoise2d> and <unifiednoise3d>: one noise chosen by type (0 Perlin, 1 Cell, 2 Worley,
// 3 Fractal; any other value gives 0), then mapped from [0, 1] to [outmin, outmax] and clamped
// when clampoutput is set. Only the chosen noise is evaluated.
//
// The sample position is position * freq + offset. A jitter below 1 decorrelates the Perlin,
// cell and fractal patterns by rotating the sample position through (jitter - 1) * 90000
// degrees (2D: about the origin; 3D: about the axis (0.1, 1, 0)); the 2D fractal instead
// uses that angle as the third coordinate of a 3D fractal. Worley uses jitter directly.

#include "lib/mx_perlin_noise.glsl"
#include "lib/mx_worley_noise.glsl"

vec2 mx_un_rotate(vec2 p, float degrees)
{
    float a = radians(degrees);
    float s = sin(a);
    float c = cos(a);
    return vec2(c * p.x + s * p.y, -s * p.x + c * p.y);
}

vec3 mx_un_rotate(vec3 p, float degrees)
{
    vec3 axis = normalize(vec3(0.1, 1.0, 0.0));
    float a = radians(degrees);
    float s = sin(a);
    float c = cos(a);
    return p * c + cross(p, axis) * s + axis * dot(axis, p) * (1.0 - c);
}

float mx_un_range(float n, float outmin, float outmax, bool clampoutput)
{
    float v = outmin + n * (outmax - outmin);
    return clampoutput ? clamp(v, outmin, outmax) : v;
}

void mx_unifiednoise2d_float(vec2 texcoord, vec2 freq, vec2 offset, float jitter, float outmin, float outmax,
                             bool clampoutput, int octaves, float lacunarity, float diminish, int type, int style,
                             out float result)
{
    vec2 p = texcoord * freq + offset;
    float spin = (jitter - 1.0) * 90000.0;
    float n = 0.0;
    if (type < 1)
        n = mx_pn_perlin(mx_un_rotate(p, spin)) * 0.5 + 0.5;
    else if (type == 1)
        n = mx_hn_cell(mx_un_rotate(p, spin));
    else if (type == 2)
        n = mx_wn_worley(p, jitter, style);
    else if (type == 3)
        n = mx_pn_fractal(vec3(p, spin), octaves, lacunarity, diminish);
    result = mx_un_range(n, outmin, outmax, clampoutput);
}

void mx_unifiednoise3d_float(vec3 position, vec3 freq, vec3 offset, float jitter, float outmin, float outmax,
                             bool clampoutput, int octaves, float lacunarity, float diminish, int type, int style,
                             out float result)
{
    vec3 p = position * freq + offset;
    float spin = (jitter - 1.0) * 90000.0;
    float n = 0.0;
    if (type < 1)
        n = mx_pn_perlin(mx_un_rotate(p, spin)) * 0.5 + 0.5;
    else if (type == 1)
        n = mx_hn_cell(mx_un_rotate(p, spin));
    else if (type == 2)
        n = mx_wn_worley(p, jitter, style);
    else if (type == 3)
        n = mx_pn_fractal(mx_un_rotate(p, spin), octaves, lacunarity, diminish);
    result = mx_un_range(n, outmin, outmax, clampoutput);
}
