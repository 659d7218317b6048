// Integer lattice hashing and cell noise, shared by the procedural nodes.
//
// Lattice points are hashed with Bob Jenkins' lookup3 ("hashword": initial value
// 0xdeadbeef + (length << 2) + 13, then mix per 3 words and a final avalanche), the hash that
// OSL's noise uses, so cell values agree with renderers that follow OSL and MaterialX.
// Works in GLSL 4.00 and ESSL 3.00: plain uint arithmetic, no bit-field built-ins.

uint mx_hn_rotl(uint x, uint k)
{
    return (x << k) | (x >> (32u - k));
}

// lookup3 final(): avalanche a, b, c into c.
uint mx_hn_final(uint a, uint b, uint c)
{
    c = (c ^ b) - mx_hn_rotl(b, 14u);
    a = (a ^ c) - mx_hn_rotl(c, 11u);
    b = (b ^ a) - mx_hn_rotl(a, 25u);
    c = (c ^ b) - mx_hn_rotl(b, 16u);
    a = (a ^ c) - mx_hn_rotl(c, 4u);
    b = (b ^ a) - mx_hn_rotl(a, 14u);
    c = (c ^ b) - mx_hn_rotl(b, 24u);
    return c;
}

// lookup3 mix(): consumes one full block of three words (used for keys longer than three).
void mx_hn_mix(inout uint a, inout uint b, inout uint c)
{
    a -= c; a ^= mx_hn_rotl(c, 4u);  c += b;
    b -= a; b ^= mx_hn_rotl(a, 6u);  a += c;
    c -= b; c ^= mx_hn_rotl(b, 8u);  b += a;
    a -= c; a ^= mx_hn_rotl(c, 16u); c += b;
    b -= a; b ^= mx_hn_rotl(a, 19u); a += c;
    c -= b; c ^= mx_hn_rotl(b, 4u);  b += a;
}

// Hashes of 2, 3, 4 and 5 integer words; the seed is 0xdeadbeef + 4 * length + 13.
uint mx_hn_hash(int x, int y)
{
    uint s = 0xdeadbeefu + 21u;
    return mx_hn_final(s + uint(x), s + uint(y), s);
}

uint mx_hn_hash(int x, int y, int z)
{
    uint s = 0xdeadbeefu + 25u;
    return mx_hn_final(s + uint(x), s + uint(y), s + uint(z));
}

uint mx_hn_hash(int x, int y, int z, int w)
{
    uint s = 0xdeadbeefu + 29u;
    uint a = s + uint(x);
    uint b = s + uint(y);
    uint c = s + uint(z);
    mx_hn_mix(a, b, c);
    return mx_hn_final(a + uint(w), b, c);
}

uint mx_hn_hash(int x, int y, int z, int w, int v)
{
    uint s = 0xdeadbeefu + 33u;
    uint a = s + uint(x);
    uint b = s + uint(y);
    uint c = s + uint(z);
    mx_hn_mix(a, b, c);
    return mx_hn_final(a + uint(w), b + uint(v), c);
}

// Map 32 hash bits to [0, 1]: divide by 2^32 (the float nearest to 0xffffffff).
float mx_hn_unit(uint h)
{
    return float(h) * 2.3283064365386963e-10;
}

// Cell noise: one random value per unit cell of the integer lattice.
float mx_hn_cell(vec2 p)
{
    ivec2 i = ivec2(floor(p));
    return mx_hn_unit(mx_hn_hash(i.x, i.y));
}

float mx_hn_cell(vec3 p)
{
    ivec3 i = ivec3(floor(p));
    return mx_hn_unit(mx_hn_hash(i.x, i.y, i.z));
}

float mx_hn_cell(vec4 p)
{
    ivec4 i = ivec4(floor(p));
    return mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, i.w));
}

// Three independent values per cell: the channel index is appended to the key.
vec3 mx_hn_cell3(ivec2 i)
{
    return vec3(mx_hn_unit(mx_hn_hash(i.x, i.y, 0)),
                mx_hn_unit(mx_hn_hash(i.x, i.y, 1)),
                mx_hn_unit(mx_hn_hash(i.x, i.y, 2)));
}

vec3 mx_hn_cell3(ivec3 i)
{
    return vec3(mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, 0)),
                mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, 1)),
                mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, 2)));
}

vec3 mx_hn_cell3(ivec4 i)
{
    return vec3(mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, i.w, 0)),
                mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, i.w, 1)),
                mx_hn_unit(mx_hn_hash(i.x, i.y, i.z, i.w, 2)));
}

vec3 mx_hn_cell3(vec2 p) { return mx_hn_cell3(ivec2(floor(p))); }
vec3 mx_hn_cell3(vec3 p) { return mx_hn_cell3(ivec3(floor(p))); }
vec3 mx_hn_cell3(vec4 p) { return mx_hn_cell3(ivec4(floor(p))); }
