// Perlin's improved gradient noise on the integer lattice, and its fractal sum.
//
// Corner gradients are picked by the lookup3 lattice hash (mx_hash_noise.glsl), blended with
// the quintic fade 6t^5 - 15t^4 + 10t^3, and scaled to about [-1, 1] by 0.6616 (2D) and
// 0.9820 (3D), the factors OSL and MaterialX use, so the patterns line up with theirs.

#include "mx_hash_noise.glsl"

float mx_pn_fade(float t)
{
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

vec2 mx_pn_fade(vec2 t) { return vec2(mx_pn_fade(t.x), mx_pn_fade(t.y)); }
vec3 mx_pn_fade(vec3 t) { return vec3(mx_pn_fade(t.x), mx_pn_fade(t.y), mx_pn_fade(t.z)); }

// 2D: the low 3 hash bits choose one of the 8 gradients (+-1, +-2) and (+-2, +-1).
float mx_pn_grad(uint h, vec2 f)
{
    h &= 7u;
    vec2 uv = (h < 4u) ? f : f.yx;
    uv.y *= 2.0;
    return ((h & 1u) != 0u ? -uv.x : uv.x) + ((h & 2u) != 0u ? -uv.y : uv.y);
}

// 3D: the low 4 hash bits choose one of the 12 cube-edge gradients (4 of them repeated).
float mx_pn_grad(uint h, vec3 f)
{
    h &= 15u;
    float u = (h < 8u) ? f.x : f.y;
    float v = (h < 4u) ? f.y : ((h == 12u || h == 14u) ? f.x : f.z);
    return ((h & 1u) != 0u ? -u : u) + ((h & 2u) != 0u ? -v : v);
}

// Three channels from one hash: each channel uses its own byte of the 32 bits.
vec3 mx_pn_grad3(uint h, vec2 f)
{
    return vec3(mx_pn_grad(h, f), mx_pn_grad(h >> 8u, f), mx_pn_grad(h >> 16u, f));
}

vec3 mx_pn_grad3(uint h, vec3 f)
{
    return vec3(mx_pn_grad(h, f), mx_pn_grad(h >> 8u, f), mx_pn_grad(h >> 16u, f));
}

float mx_pn_perlin(vec2 p)
{
    vec2 fl = floor(p);
    ivec2 i = ivec2(fl);
    vec2 f = p - fl;
    vec2 w = mx_pn_fade(f);
    float n00 = mx_pn_grad(mx_hn_hash(i.x,     i.y),     f);
    float n10 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y),     f - vec2(1.0, 0.0));
    float n01 = mx_pn_grad(mx_hn_hash(i.x,     i.y + 1), f - vec2(0.0, 1.0));
    float n11 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1), f - vec2(1.0, 1.0));
    return 0.6616 * mix(mix(n00, n10, w.x), mix(n01, n11, w.x), w.y);
}

vec3 mx_pn_perlin3(vec2 p)
{
    vec2 fl = floor(p);
    ivec2 i = ivec2(fl);
    vec2 f = p - fl;
    vec2 w = mx_pn_fade(f);
    vec3 n00 = mx_pn_grad3(mx_hn_hash(i.x,     i.y),     f);
    vec3 n10 = mx_pn_grad3(mx_hn_hash(i.x + 1, i.y),     f - vec2(1.0, 0.0));
    vec3 n01 = mx_pn_grad3(mx_hn_hash(i.x,     i.y + 1), f - vec2(0.0, 1.0));
    vec3 n11 = mx_pn_grad3(mx_hn_hash(i.x + 1, i.y + 1), f - vec2(1.0, 1.0));
    return 0.6616 * mix(mix(n00, n10, w.x), mix(n01, n11, w.x), w.y);
}

float mx_pn_perlin(vec3 p)
{
    vec3 fl = floor(p);
    ivec3 i = ivec3(fl);
    vec3 f = p - fl;
    vec3 w = mx_pn_fade(f);
    float n000 = mx_pn_grad(mx_hn_hash(i.x,     i.y,     i.z),     f);
    float n100 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y,     i.z),     f - vec3(1.0, 0.0, 0.0));
    float n010 = mx_pn_grad(mx_hn_hash(i.x,     i.y + 1, i.z),     f - vec3(0.0, 1.0, 0.0));
    float n110 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1, i.z),     f - vec3(1.0, 1.0, 0.0));
    float n001 = mx_pn_grad(mx_hn_hash(i.x,     i.y,     i.z + 1), f - vec3(0.0, 0.0, 1.0));
    float n101 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y,     i.z + 1), f - vec3(1.0, 0.0, 1.0));
    float n011 = mx_pn_grad(mx_hn_hash(i.x,     i.y + 1, i.z + 1), f - vec3(0.0, 1.0, 1.0));
    float n111 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1, i.z + 1), f - vec3(1.0, 1.0, 1.0));
    float z0 = mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y);
    float z1 = mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y);
    return 0.9820 * mix(z0, z1, w.z);
}

vec3 mx_pn_perlin3(vec3 p)
{
    vec3 fl = floor(p);
    ivec3 i = ivec3(fl);
    vec3 f = p - fl;
    vec3 w = mx_pn_fade(f);
    vec3 n000 = mx_pn_grad3(mx_hn_hash(i.x,     i.y,     i.z),     f);
    vec3 n100 = mx_pn_grad3(mx_hn_hash(i.x + 1, i.y,     i.z),     f - vec3(1.0, 0.0, 0.0));
    vec3 n010 = mx_pn_grad3(mx_hn_hash(i.x,     i.y + 1, i.z),     f - vec3(0.0, 1.0, 0.0));
    vec3 n110 = mx_pn_grad3(mx_hn_hash(i.x + 1, i.y + 1, i.z),     f - vec3(1.0, 1.0, 0.0));
    vec3 n001 = mx_pn_grad3(mx_hn_hash(i.x,     i.y,     i.z + 1), f - vec3(0.0, 0.0, 1.0));
    vec3 n101 = mx_pn_grad3(mx_hn_hash(i.x + 1, i.y,     i.z + 1), f - vec3(1.0, 0.0, 1.0));
    vec3 n011 = mx_pn_grad3(mx_hn_hash(i.x,     i.y + 1, i.z + 1), f - vec3(0.0, 1.0, 1.0));
    vec3 n111 = mx_pn_grad3(mx_hn_hash(i.x + 1, i.y + 1, i.z + 1), f - vec3(1.0, 1.0, 1.0));
    vec3 z0 = mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y);
    vec3 z1 = mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y);
    return 0.9820 * mix(z0, z1, w.z);
}

// Fractal sum: octave k adds diminish^k * noise(p * lacunarity^k).
float mx_pn_fractal(vec2 p, int octaves, float lacunarity, float diminish)
{
    float sum = 0.0;
    float weight = 1.0;
    for (int k = 0; k < octaves; ++k)
    {
        sum += weight * mx_pn_perlin(p);
        weight *= diminish;
        p *= lacunarity;
    }
    return sum;
}

vec3 mx_pn_fractal3(vec2 p, int octaves, float lacunarity, float diminish)
{
    vec3 sum = vec3(0.0);
    float weight = 1.0;
    for (int k = 0; k < octaves; ++k)
    {
        sum += weight * mx_pn_perlin3(p);
        weight *= diminish;
        p *= lacunarity;
    }
    return sum;
}

float mx_pn_fractal(vec3 p, int octaves, float lacunarity, float diminish)
{
    float sum = 0.0;
    float weight = 1.0;
    for (int k = 0; k < octaves; ++k)
    {
        sum += weight * mx_pn_perlin(p);
        weight *= diminish;
        p *= lacunarity;
    }
    return sum;
}

vec3 mx_pn_fractal3(vec3 p, int octaves, float lacunarity, float diminish)
{
    vec3 sum = vec3(0.0);
    float weight = 1.0;
    for (int k = 0; k < octaves; ++k)
    {
        sum += weight * mx_pn_perlin3(p);
        weight *= diminish;
        p *= lacunarity;
    }
    return sum;
}
