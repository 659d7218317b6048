#include <metal_stdlib>
using namespace metal;

struct PixelUniforms
{
    packed_float3 u_n0_in;  // offset 0
    float u_n2_in2;  // offset 12
    float u_n3_amplitude;  // offset 16
    int u_n3_octaves;  // offset 20
    float u_n3_lacunarity;  // offset 24
    float u_n3_diminish;  // offset 28
    packed_float3 u_n4_fg;  // offset 32
    int u_n5_index;  // offset 44
    packed_float3 u_n13_color1;  // offset 48
    char pad_60[4];
    packed_float3 u_n13_color2;  // offset 64
    char pad_76[4];
    float2 u_n13_uvtiling;  // offset 80
    float2 u_n13_uvoffset;  // offset 88
};

struct VertexData
{
    float4 position [[position]];
    float3 positionObject [[user(locn0)]];
    float2 texcoord_0 [[user(locn1)]];
};

struct PixelStage
{
    constant PixelUniforms& pu;
    VertexData vd;

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
        float z0 = mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y);
        float z1 = mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y);
        return 0.9820 * mix(z0, z1, w.z);
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
                            thread float& result)
    {
        result = mx_pn_fractal(position, octaves, lacunarity, diminish) * amplitude;
    }

    float4 shade()
    {
        float4 out1;
        float3 n0_out = select(pu.u_n0_in / 12.92,
                               pow(max(pu.u_n0_in + 0.055, float3(0.0)) / 1.055, float3(2.4)),
                               pu.u_n0_in > float3(0.04045));
        float3 n1_out = vd.positionObject;
        float3 n2_out = n1_out * pu.u_n2_in2;
        float n3_out;
        mx_fractal3d_float(pu.u_n3_amplitude, pu.u_n3_octaves, pu.u_n3_lacunarity, pu.u_n3_diminish, n2_out,
                           n3_out);
        float3 n4_out = mix(n0_out, pu.u_n4_fg, float3(n3_out));
        float2 n5_out = vd.texcoord_0;
        float2 n6_out = n5_out * pu.u_n13_uvtiling;
        float2 n7_out = n6_out - pu.u_n13_uvoffset;
        float2 n8_out = floor(n7_out);
        float n9_out = dot(n8_out, float2(1.0, 1.0));
        float n10_out = n9_out - 2.0 * floor(n9_out / 2.0);
        float3 n11_out = mix(pu.u_n13_color2, pu.u_n13_color1, float3(n10_out));
        float3 n12_out = n4_out * n11_out;
        out1 = float4(n12_out, 1.0);
        return out1;
    }
};

fragment float4 fragmentMain(VertexData vertexData [[stage_in]],
                             constant PixelUniforms& pu [[buffer(0)]])
{
    PixelStage stage{pu, vertexData};
    return stage.shade();
}
