// <noise2d> and <noise3d>: Perlin noise scaled by amplitude and shifted by pivot.
// vector2 takes the first two channels of the three-channel noise; vector4 adds a fourth
// channel read from a shifted copy of the scalar noise. color3/color4 use the vector3/vector4
// functions; the FA variants take a scalar amplitude.

#include "lib/mx_perlin_noise.glsl"

void mx_noise2d_float(float amplitude, float pivot, vec2 texcoord, out float result)
{
    result = mx_pn_perlin(texcoord) * amplitude + pivot;
}

void mx_noise2d_vector2(vec2 amplitude, float pivot, vec2 texcoord, out vec2 result)
{
    result = mx_pn_perlin3(texcoord).xy * amplitude + pivot;
}

void mx_noise2d_vector3(vec3 amplitude, float pivot, vec2 texcoord, out vec3 result)
{
    result = mx_pn_perlin3(texcoord) * amplitude + pivot;
}

void mx_noise2d_vector4(vec4 amplitude, float pivot, vec2 texcoord, out vec4 result)
{
    vec4 n = vec4(mx_pn_perlin3(texcoord), mx_pn_perlin(texcoord + vec2(19.0, 73.0)));
    result = n * amplitude + pivot;
}

void mx_noise2d_vector2FA(float amplitude, float pivot, vec2 texcoord, out vec2 result)
{
    mx_noise2d_vector2(vec2(amplitude), pivot, texcoord, result);
}

void mx_noise2d_vector3FA(float amplitude, float pivot, vec2 texcoord, out vec3 result)
{
    mx_noise2d_vector3(vec3(amplitude), pivot, texcoord, result);
}

void mx_noise2d_vector4FA(float amplitude, float pivot, vec2 texcoord, out vec4 result)
{
    mx_noise2d_vector4(vec4(amplitude), pivot, texcoord, result);
}

void mx_noise3d_float(float amplitude, float pivot, vec3 position, out float result)
{
    result = mx_pn_perlin(position) * amplitude + pivot;
}

void mx_noise3d_vector2(vec2 amplitude, float pivot, vec3 position, out vec2 result)
{
    result = mx_pn_perlin3(position).xy * amplitude + pivot;
}

void mx_noise3d_vector3(vec3 amplitude, float pivot, vec3 position, out vec3 result)
{
    result = mx_pn_perlin3(position) * amplitude + pivot;
}

void mx_noise3d_vector4(vec4 amplitude, float pivot, vec3 position, out vec4 result)
{
    vec4 n = vec4(mx_pn_perlin3(position), mx_pn_perlin(position + vec3(19.0, 73.0, 29.0)));
    result = n * amplitude + pivot;
}

void mx_noise3d_vector2FA(float amplitude, float pivot, vec3 position, out vec2 result)
{
    mx_noise3d_vector2(vec2(amplitude), pivot, position, result);
}

void mx_noise3d_vector3FA(float amplitude, float pivot, vec3 position, out vec3 result)
{
    mx_noise3d_vector3(vec3(amplitude), pivot, position, result);
}

void mx_noise3d_vector4FA(float amplitude, float pivot, vec3 position, out vec4 result)
{
    mx_noise3d_vector4(vec4(amplitude), pivot, position, result);
}
