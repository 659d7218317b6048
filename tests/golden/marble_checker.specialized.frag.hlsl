cbuffer PixelUniforms
{
    float u_n2_in2;
};

struct VertexData
{
    float4 position : SV_Position;
    float3 positionObject : TEXCOORD0;
    float2 texcoord_0 : TEXCOORD1;
};

static VertexData vd;

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

uint mx_hn_hash(int x, int y, int z)
{
    uint s = 0xdeadbeefu + 25u;
    return mx_hn_final(s + uint(x), s + uint(y), s + uint(z));
}

float mx_pn_fade(float t)
{
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

float3 mx_pn_fade(float3 t)
{
    return float3(mx_pn_fade(t.x), mx_pn_fade(t.y), mx_pn_fade(t.z));
}

// 3D: the low 4 hash bits choose one of the 12 cube-edge gradients (4 of them repeated).
float mx_pn_grad(uint h, float3 f)
{
    h &= 15u;
    float u = (h < 8u) ? f.x : f.y;
    float v = (h < 4u) ? f.y : (h == 12u || h == 14u) ? f.x : f.z;
    return (((h & 1u) != 0u) ? -u : u) + (((h & 2u) != 0u) ? -v : v);
}

float mx_pn_perlin(float3 p)
{
    float3 fl = floor(p);
    int3 i = int3(int3(fl));
    float3 f = p - fl;
    float3 w = mx_pn_fade(f);
    float n000 = mx_pn_grad(mx_hn_hash(i.x, i.y, i.z), f);
    float n100 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y, i.z), f - float3(1.0, 0.0, 0.0));
    float n010 = mx_pn_grad(mx_hn_hash(i.x, i.y + 1, i.z), f - float3(0.0, 1.0, 0.0));
    float n110 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1, i.z), f - float3(1.0, 1.0, 0.0));
    float n001 = mx_pn_grad(mx_hn_hash(i.x, i.y, i.z + 1), f - float3(0.0, 0.0, 1.0));
    float n101 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y, i.z + 1), f - float3(1.0, 0.0, 1.0));
    float n011 = mx_pn_grad(mx_hn_hash(i.x, i.y + 1, i.z + 1), f - float3(0.0, 1.0, 1.0));
    float n111 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1, i.z + 1), f - float3(1.0, 1.0, 1.0));
    float z0 = lerp(lerp(n000, n100, w.x), lerp(n010, n110, w.x), w.y);
    float z1 = lerp(lerp(n001, n101, w.x), lerp(n011, n111, w.x), w.y);
    return 0.9820 * lerp(z0, z1, w.z);
}

float mx_pn_fractal(float3 p, int octaves, float lacunarity, float diminish)
{
    float sum = 0.0;
    float weight = 1.0;
    for (int k = 0; k < octaves; k++)
    {
        sum += weight * mx_pn_perlin(p);
        weight *= diminish;
        p *= lacunarity;
    }
    return sum;
}

void mx_fractal3d_float(float amplitude, int octaves, float lacunarity, float diminish, float3 position,
                        out float result)
{
    result = mx_pn_fractal(position, octaves, lacunarity, diminish) * amplitude;
}

[shader("pixel")]
float4 fragmentMain(VertexData vertexData) : SV_Target
{
    vd = vertexData;
    float4 out1;
    float3 n0_out = float3(0.9, 0.88, 0.85) > (float3)0.04045 ? pow(max(float3(0.9, 0.88, 0.85) + 0.055, (float3)0.0) / 1.055, (float3)2.4) : float3(0.9, 0.88, 0.85) / 12.92;
    float3 n1_out = vd.positionObject;
    float3 n2_out = n1_out * u_n2_in2;
    float n3_out;
    mx_fractal3d_float(1.0, 4, 2.0, 0.5, n2_out, n3_out);
    float3 n4_out = lerp(n0_out, float3(0.25, 0.22, 0.2), n3_out);
    float2 n5_out = vd.texcoord_0;
    float2 n6_out = n5_out * float2(8.0, 8.0);
    float2 n7_out = floor(n6_out);
    float n8_out = dot(n7_out, float2(1.0, 1.0));
    float n9_out = n8_out - 2.0 * floor(n8_out / 2.0);
    float3 n10_out = lerp(float3(0.0, 0.0, 0.0), float3(1.0, 1.0, 1.0), n9_out);
    float3 n11_out = n4_out * n10_out;
    out1 = float4(n11_out, 1.0);
    return out1;
}
