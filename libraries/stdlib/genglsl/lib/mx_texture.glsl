// File-texture sampling shared by the image family (image, tiledimage, triplanarprojection,
// latlongimage).
//
// The renderer binds every file texture with REPEAT wrap, trilinear mipmapping and rows uploaded
// top row first, so address modes and the closest filter are applied here, in the shader:
//   address mode (enum index): 0 constant, 1 clamp, 2 periodic, 3 mirror
//   filter type  (enum index): 0 closest, 1 linear, 2 cubic (sampled as linear)
// Mip levels are chosen from the derivatives of the unwrapped coordinate, so folding or clamping
// never creates a seam of coarse mips where the wrapped coordinate jumps. Every mode matches the
// hardware sampler state MaterialX binds for it (CLAMP_TO_BORDER with the default as border colour,
// CLAMP_TO_EDGE, REPEAT, MIRRORED_REPEAT); desktop GLSL asks textureQueryLod for the level of detail
// it accesses, ESSL 3.00 (which lacks it, and any query of the levels) computes the isotropic one
// from the derivatives and so assumes a full mip chain, as the renderer binds.

// Image-space coordinate of a texture coordinate: scale and offset, then flip v.
vec2 mx_image_uv(vec2 texcoord, vec2 uv_scale, vec2 uv_offset)
{
    vec2 uv = texcoord * uv_scale + uv_offset;
    return vec2(uv.x, 1.0 - uv.y);
}

// Fold a coordinate into [0, 1] for every mode but periodic (left to the sampler's REPEAT).
float mx_address_fold(float x, int mode)
{
    if (mode == 2)
        return x;
    if (mode == 3)
        return 1.0 - abs(mod(x, 2.0) - 1.0);
    return clamp(x, 0.0, 1.0);
}

// Sample `tex` at image-space `uv`. On a constant axis the image fades to `dflt` outside [0, 1] the
// way a border colour does: nearest sampling switches at the edge, linear sampling blends across
// the half texel (of each mip level used) around it. Derivatives and the periodic fast path are
// taken before any per-pixel selection, so they stay in uniform control flow.
vec4 mx_image_fetch(sampler2D tex, vec4 dflt, vec2 uv, int uaddr, int vaddr, int filtertype)
{
    bool periodicU = uaddr == 2;
    bool periodicV = vaddr == 2;
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    if (filtertype != 0 && periodicU && periodicV)
        return texture(tex, uv);

    vec2 size = vec2(textureSize(tex, 0));
    vec2 st = vec2(mx_address_fold(uv.x, uaddr), mx_address_fold(uv.y, vaddr));
    if (filtertype == 0)
    {
        // Nearest texel of the base level, wrapped on integer texel coordinates.
        vec2 t = floor(st * size);
        vec2 clamped = clamp(t, vec2(0.0), size - 1.0);
        vec2 wrapped = mod(t, size);
        t = vec2(periodicU ? wrapped.x : clamped.x, periodicV ? wrapped.y : clamped.y);
        vec2 raw = floor(uv * size);
        vec2 inside = step(vec2(0.0), raw) * step(raw, size - 1.0);
        float weight = (uaddr == 0 ? inside.x : 1.0) * (vaddr == 0 ? inside.y : 1.0);
        return mix(dflt, texelFetch(tex, ivec2(t), 0), weight);
    }

    // Trilinear lookup with clamp-to-edge on a REPEAT sampler. Away from the edges this is the
    // hardware lookup with the unwrapped gradients. Near and beyond an edge the two mip levels are
    // fetched explicitly, each inset by its own half texel so nothing wraps across the seam.
    float maxLevel = floor(log2(max(size.x, size.y)));
#ifdef GL_ES
    vec2 dxt = dx * size;
    vec2 dyt = dy * size;
    float lod = 0.5 * log2(max(max(dot(dxt, dxt), dot(dyt, dyt)), 1e-20));
#else
    // The level the hardware itself reads (x: clamped to the texture's accessible levels, 0 when the
    // sampler has no mipmaps), so each inset below is that of a level the lookup really reads.
    float lod = textureQueryLod(tex, uv).x;
#endif
    lod = clamp(lod, 0.0, maxLevel);
    float l0 = floor(lod);
    float l1 = min(l0 + 1.0, maxLevel);
    vec2 size0 = max(floor(size * exp2(-l0)), vec2(1.0));
    vec2 size1 = max(floor(size * exp2(-l1)), vec2(1.0));
    vec2 st1 = clamp(st, 0.5 / size1, 1.0 - 0.5 / size1);
    if ((periodicU || st1.x == st.x) && (periodicV || st1.y == st.y))
        return textureGrad(tex, st, dx, dy);
    vec2 st0 = clamp(st, 0.5 / size0, 1.0 - 0.5 / size0);
    vec4 t0 = textureLod(tex, vec2(periodicU ? st.x : st0.x, periodicV ? st.y : st0.y), l0);
    vec4 t1 = textureLod(tex, vec2(periodicU ? st.x : st1.x, periodicV ? st.y : st1.y), l1);
    // Border-colour fade per level: the share of the bilinear footprint inside [0, 1].
    vec2 d = 0.5 - abs(uv - 0.5);
    vec2 c0 = clamp(d * size0 + 0.5, 0.0, 1.0);
    vec2 c1 = clamp(d * size1 + 0.5, 0.0, 1.0);
    float w0 = (uaddr == 0 ? c0.x : 1.0) * (vaddr == 0 ? c0.y : 1.0);
    float w1 = (uaddr == 0 ? c1.x : 1.0) * (vaddr == 0 ? c1.y : 1.0);
    return mix(mix(dflt, t0, w0), mix(dflt, t1, w1), lod - l0);
}
