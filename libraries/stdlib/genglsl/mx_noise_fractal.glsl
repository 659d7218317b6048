// <fractal2d> and <fractal3d>: fractal sums of Perlin noise times amplitude. vector2/vector4 add
// a channel read from the scalar sum at a shifted position. color3/color4 use the
// vector3/vector4 functions; the FA variants take a scalar amplitude.

#include "lib/mx_perlin_noise.glsl"

void mx_fractal2d_float(float amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out float result)
{
    result = mx_pn_fractal(texcoord, octaves, lacunarity, diminish) * amplitude;
}

void mx_fractal2d_vector2(vec2 amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out vec2 result)
{
    vec2 n = vec2(mx_pn_fractal(texcoord, octaves, lacunarity, diminish),
                  mx_pn_fractal(texcoord + vec2(19.0, 193.0), octaves, lacunarity, diminish));
    result = n * amplitude;
}

void mx_fractal2d_vector3(vec3 amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out vec3 result)
{
    result = mx_pn_fractal3(texcoord, octaves, lacunarity, diminish) * amplitude;
}

void mx_fractal2d_vector4(vec4 amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out vec4 result)
{
    vec4 n = vec4(mx_pn_fractal3(texcoord, octaves, lacunarity, diminish),
                  mx_pn_fractal(texcoord + vec2(19.0, 193.0), octaves, lacunarity, diminish));
    result = n * amplitude;
}

void mx_fractal2d_vector2FA(float amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out vec2 result)
{
    mx_fractal2d_vector2(vec2(amplitude), octaves, lacunarity, diminish, texcoord, result);
}

void mx_fractal2d_vector3FA(float amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out vec3 result)
{
    mx_fractal2d_vector3(vec3(amplitude), octaves, lacunarity, diminish, texcoord, result);
}

void mx_fractal2d_vector4FA(float amplitude, int octaves, float lacunarity, float diminish, vec2 texcoord, out vec4 result)
{
    mx_fractal2d_vector4(vec4(amplitude), octaves, lacunarity, diminish, texcoord, result);
}

void mx_fractal3d_float(float amplitude, int octaves, float lacunarity, float diminish, vec3 position, out float result)
{
    result = mx_pn_fractal(position, octaves, lacunarity, diminish) * amplitude;
}

void mx_fractal3d_vector2(vec2 amplitude, int octaves, float lacunarity, float diminish, vec3 position, out vec2 result)
{
    vec2 n = vec2(mx_pn_fractal(position, octaves, lacunarity, diminish),
                  mx_pn_fractal(position + vec3(19.0, 193.0, 17.0), octaves, lacunarity, diminish));
    result = n * amplitude;
}

void mx_fractal3d_vector3(vec3 amplitude, int octaves, float lacunarity, float diminish, vec3 position, out vec3 result)
{
    result = mx_pn_fractal3(position, octaves, lacunarity, diminish) * amplitude;
}

void mx_fractal3d_vector4(vec4 amplitude, int octaves, float lacunarity, float diminish, vec3 position, out vec4 result)
{
    vec4 n = vec4(mx_pn_fractal3(position, octaves, lacunarity, diminish),
                  mx_pn_fractal(position + vec3(19.0, 193.0, 17.0), octaves, lacunarity, diminish));
    result = n * amplitude;
}

void mx_fractal3d_vector2FA(float amplitude, int octaves, float lacunarity, float diminish, vec3 position, out vec2 result)
{
    mx_fractal3d_vector2(vec2(amplitude), octaves, lacunarity, diminish, position, result);
}

void mx_fractal3d_vector3FA(float amplitude, int octaves, float lacunarity, float diminish, vec3 position, out vec3 result)
{
    mx_fractal3d_vector3(vec3(amplitude), octaves, lacunarity, diminish, position, result);
}

void mx_fractal3d_vector4FA(float amplitude, int octaves, float lacunarity, float diminish, vec3 position, out vec4 result)
{
    mx_fractal3d_vector4(vec4(amplitude), octaves, lacunarity, diminish, position, result);
}
