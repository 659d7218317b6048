// <worleynoise2d> and <worleynoise3d>: distance to the nearest 1, 2 or 3 feature points
// (style "Distance"), or a random value per nearest feature (style "Solid").

#include "lib/mx_worley_noise.glsl"

void mx_worleynoise2d_float(vec2 texcoord, float jitter, int style, out float result)
{
    result = mx_wn_worley(texcoord, jitter, style);
}

void mx_worleynoise2d_vector2(vec2 texcoord, float jitter, int style, out vec2 result)
{
    result = mx_wn_worley2(texcoord, jitter, style);
}

void mx_worleynoise2d_vector3(vec2 texcoord, float jitter, int style, out vec3 result)
{
    result = mx_wn_worley3(texcoord, jitter, style);
}

void mx_worleynoise3d_float(vec3 position, float jitter, int style, out float result)
{
    result = mx_wn_worley(position, jitter, style);
}

void mx_worleynoise3d_vector2(vec3 position, float jitter, int style, out vec2 result)
{
    result = mx_wn_worley2(position, jitter, style);
}

void mx_worleynoise3d_vector3(vec3 position, float jitter, int style, out vec3 result)
{
    result = mx_wn_worley3(position, jitter, style);
}
