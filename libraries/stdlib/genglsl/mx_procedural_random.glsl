// <randomfloat> and <randomcolor>: cell noise of (input, seed) as a repeatable random value.
// A float input is scaled by 4096 first so that nearby inputs land in different cells; an
// integer input is used as is. randomcolor draws hue, saturation and brightness with three
// seeds derived from the given one, maps each into its [low, high] range and converts HSV to
// RGB.

#include "lib/mx_hash_noise.glsl"

float mx_rand_unit(float x, int seed)
{
    return mx_hn_cell(vec2(x, float(seed)));
}

void mx_randomfloat_float(float value, float minval, float maxval, int seed, out float result)
{
    float r = mx_rand_unit(value * 4096.0, seed);
    result = clamp(minval + r * (maxval - minval), minval, maxval);
}

void mx_randomfloat_integer(int value, float minval, float maxval, int seed, out float result)
{
    float r = mx_rand_unit(float(value), seed);
    result = clamp(minval + r * (maxval - minval), minval, maxval);
}

// HSV to RGB (hexcone model, Foley & van Dam); h wraps around, s and v as given.
vec3 mx_rand_hsv_to_rgb(vec3 hsv)
{
    float v = hsv.z;
    if (hsv.y < 0.0001)
        return vec3(v);
    float h = 6.0 * (hsv.x - floor(hsv.x));
    int sector = int(h);
    float f = h - float(sector);
    float p = v * (1.0 - hsv.y);
    float q = v * (1.0 - hsv.y * f);
    float t = v * (1.0 - hsv.y * (1.0 - f));
    if (sector == 0) return vec3(v, t, p);
    if (sector == 1) return vec3(q, v, p);
    if (sector == 2) return vec3(p, v, t);
    if (sector == 3) return vec3(p, q, v);
    if (sector == 4) return vec3(t, p, v);
    return vec3(v, p, q);
}

// One HSV channel: a random value for the seed shifted by `salt`, mapped to [low, high].
float mx_rand_channel(float value, int seed, float salt, float low, float high)
{
    int s = int(ceil(float(seed) + salt));
    float r = mx_rand_unit(value * 4096.0, s);
    return low + r * (high - low);
}

void mx_randomcolor_float(float value, float huelow, float huehigh, float saturationlow, float saturationhigh,
                          float brightnesslow, float brightnesshigh, int seed, out vec3 result)
{
    vec3 hsv = vec3(mx_rand_channel(value, seed, 413.3, huelow, huehigh),
                    mx_rand_channel(value, seed, 1522.4, saturationlow, saturationhigh),
                    mx_rand_channel(value, seed, 1813.8, brightnesslow, brightnesshigh));
    result = mx_rand_hsv_to_rgb(hsv);
}
