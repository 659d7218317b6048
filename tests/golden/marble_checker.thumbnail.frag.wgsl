struct PixelUniforms {
    u_n2_in2: f32,  // offset 0
}
@group(1) @binding(0) var<uniform> pu: PixelUniforms;

struct VertexData {
    @builtin(position) position: vec4f,
    @location(0) positionObject: vec3f,
    @location(1) texcoord_0: vec2f,
}

var<private> vd: VertexData;

fn mx_runtime_vec3f(value: vec3f) -> vec3f {
    return value;
}

fn mx_hn_rotl(x: u32, k: u32) -> u32 {
    return (x << k) | (x >> (32u - k));
}

// lookup3 final(): avalanche a, b, c into c.
fn mx_hn_final(a__in: u32, b__in: u32, c__in: u32) -> u32 {
    var a: u32 = a__in;
    var b: u32 = b__in;
    var c: u32 = c__in;
    c = (c ^ b) - mx_hn_rotl(b, 14u);
    a = (a ^ c) - mx_hn_rotl(c, 11u);
    b = (b ^ a) - mx_hn_rotl(a, 25u);
    c = (c ^ b) - mx_hn_rotl(b, 16u);
    a = (a ^ c) - mx_hn_rotl(c, 4u);
    b = (b ^ a) - mx_hn_rotl(a, 14u);
    c = (c ^ b) - mx_hn_rotl(b, 24u);
    return c;
}

fn mx_hn_hash(x: i32, y: i32, z: i32) -> u32 {
    let s: u32 = 0xdeadbeefu + 25u;
    return mx_hn_final(s + u32(x), s + u32(y), s + u32(z));
}

fn mx_pn_fade_float(t: f32) -> f32 {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

fn mx_pn_fade_vec3(t: vec3f) -> vec3f {
    return vec3f(mx_pn_fade_float(t.x), mx_pn_fade_float(t.y), mx_pn_fade_float(t.z));
}

// 3D: the low 4 hash bits choose one of the 12 cube-edge gradients (4 of them repeated).
fn mx_pn_grad(h__in: u32, f: vec3f) -> f32 {
    var h: u32 = h__in;
    h &= 15u;
    let u: f32 = select(f.y, f.x, h < 8u);
    let v: f32 = select(select(f.z, f.x, h == 12u || h == 14u), f.y, h < 4u);
    return select(u, -u, (h & 1u) != 0u) + select(v, -v, (h & 2u) != 0u);
}

fn mx_pn_perlin(p: vec3f) -> f32 {
    let fl: vec3f = floor(p);
    let i: vec3i = vec3i(fl);
    let f: vec3f = p - fl;
    let w: vec3f = mx_pn_fade_vec3(f);
    let n000: f32 = mx_pn_grad(mx_hn_hash(i.x, i.y, i.z), f);
    let n100: f32 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y, i.z), f - vec3f(1.0, 0.0, 0.0));
    let n010: f32 = mx_pn_grad(mx_hn_hash(i.x, i.y + 1, i.z), f - vec3f(0.0, 1.0, 0.0));
    let n110: f32 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1, i.z), f - vec3f(1.0, 1.0, 0.0));
    let n001: f32 = mx_pn_grad(mx_hn_hash(i.x, i.y, i.z + 1), f - vec3f(0.0, 0.0, 1.0));
    let n101: f32 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y, i.z + 1), f - vec3f(1.0, 0.0, 1.0));
    let n011: f32 = mx_pn_grad(mx_hn_hash(i.x, i.y + 1, i.z + 1), f - vec3f(0.0, 1.0, 1.0));
    let n111: f32 = mx_pn_grad(mx_hn_hash(i.x + 1, i.y + 1, i.z + 1), f - vec3f(1.0, 1.0, 1.0));
    let z0: f32 = mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y);
    let z1: f32 = mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y);
    return 0.9820 * mix(z0, z1, w.z);
}

fn mx_pn_fractal(p__in: vec3f, octaves: i32, lacunarity: f32, diminish: f32) -> f32 {
    var p: vec3f = p__in;
    var sum: f32 = 0.0;
    var weight: f32 = 1.0;
    for (var k: i32 = 0; k < octaves; k++) {
        sum += weight * mx_pn_perlin(p);
        weight *= diminish;
        p *= lacunarity;
    }
    return sum;
}

fn mx_fractal3d_float(amplitude: f32, octaves: i32, lacunarity: f32, diminish: f32, position: vec3f,
                      result: ptr<function, f32>) {
    *result = mx_pn_fractal(position, octaves, lacunarity, diminish) * amplitude;
}

@fragment
fn fragmentMain(vertexData: VertexData) -> @location(0) vec4f {
    vd = vertexData;
    var out1: vec4f;
    var n0_out: vec3f = select(mx_runtime_vec3f(vec3f(0.9, 0.88, 0.85)) / 12.92,
                               pow(max(mx_runtime_vec3f(vec3f(0.9, 0.88, 0.85)) + 0.055, vec3f(0.0)) / 1.055,
                                   vec3f(2.4)), mx_runtime_vec3f(vec3f(0.9, 0.88, 0.85)) > vec3f(0.04045));
    var n1_out: vec3f = vd.positionObject;
    var n2_out: vec3f = n1_out * pu.u_n2_in2;
    var n3_out: f32;
    mx_fractal3d_float(1.0, 4, 2.0, 0.5, n2_out, &n3_out);
    var n4_out: vec3f = mix(n0_out, vec3f(0.25, 0.22, 0.2), vec3f(n3_out));
    var n5_out: vec2f = vd.texcoord_0;
    var n6_out: vec2f = n5_out * vec2f(8.0, 8.0);
    var n7_out: vec2f = floor(n6_out);
    var n8_out: f32 = dot(n7_out, vec2f(1.0, 1.0));
    var n9_out: f32 = n8_out - 2.0 * floor(n8_out / 2.0);
    var n10_out: vec3f = mix(vec3f(0.0, 0.0, 0.0), vec3f(1.0, 1.0, 1.0), vec3f(n9_out));
    var n11_out: vec3f = n4_out * n10_out;
    out1 = vec4f(n11_out, 1.0);
    return out1;
}
