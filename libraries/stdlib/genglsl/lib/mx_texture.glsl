// File-texture sampling shared by the image family (image, tiledimage, triplanarprojection,
// latlongimage).
//
// The renderer binds every file texture with REPEAT wrap, trilinear mipmapping and rows uploaded
// top row first, so address modes and the closest filter are applied here, in the shader:
//   address mode (enum index): 0 constant, 1 clamp, 2 periodic, 3 mirror
//   filter type  (enum index): 0 closest, 1 linear, 2 cubic (a bicubic B-spline of 16 texels, in
//                              shaders whose filter type may be cubic: feature CUBIC_FILTER)
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

// The level of detail of a lookup at `uv` (derivatives dx, dy), from 0 to the last level read.
float mx_image_lod(sampler2D tex, vec2 uv, vec2 dx, vec2 dy)
{
    vec2 size = vec2(textureSize(tex, 0));
    float maxLevel = floor(log2(max(size.x, size.y)));
#ifdef GL_ES
    vec2 dxt = dx * size;
    vec2 dyt = dy * size;
    float lod = 0.5 * log2(max(max(dot(dxt, dxt), dot(dyt, dyt)), 1e-20));
#else
    // The level the hardware itself reads (x: clamped to the texture's accessible levels, 0 when the
    // sampler has no mipmaps), so each level a caller reads or insets by exists.
    float lod = textureQueryLod(tex, uv).x;
#endif
    return clamp(lod, 0.0, maxLevel);
}

#ifdef MX_FEATURE_CUBIC_FILTER
// The weights of the four texels around a sample at fraction t in [0, 1) past texel i, for the
// texels i - 1, i, i + 1, i + 2. The uniform cubic B-spline kernel at distance d is
//   (4 - 6 d^2 + 3 |d|^3) / 6 for |d| < 1,   (2 - |d|)^3 / 6 for 1 <= |d| < 2,
// and the four texels lie at distances 1 + t, t, 1 - t, 2 - t:
//   i - 1: (2 - (1 + t))^3 / 6                = (1 - t)^3 / 6
//   i    : (4 - 6 t^2 + 3 t^3) / 6
//   i + 1: (4 - 6 (1 - t)^2 + 3 (1 - t)^3) / 6 = (1 + 3 t + 3 t^2 - 3 t^3) / 6
//   i + 2: (2 - (2 - t))^3 / 6                = t^3 / 6
// They sum to 1 for every t. The kernel smooths (it does not pass through the texels, a texel
// between two others of 0 reads 4/6 of itself) and is C2: OIIO's "cubic" interpolation, so a cubic
// image reads the same in OSL.
vec4 mx_bspline_weights(float t)
{
    float t2 = t * t;
    float t3 = t2 * t;
    float s = 1.0 - t;
    return vec4(s * s * s, 4.0 - 6.0 * t2 + 3.0 * t3, 1.0 + 3.0 * t + 3.0 * t2 - 3.0 * t3, t3) / 6.0;
}

// Texel index i (a whole number, perhaps outside [0, n)) of an axis of n texels under an address
// mode: repeated, mirrored, or clamped (constant too: its caller reads the default outside).
float mx_address_texel(float i, float n, int mode)
{
    if (mode == 2)
        return mod(i, n);
    if (mode == 3)
    {
        float m = mod(i, 2.0 * n);
        return m < n ? m : 2.0 * n - 1.0 - m;
    }
    return clamp(i, 0.0, n - 1.0);
}

// Texel p of `level` (size texels) wrapped by the address modes; outside a constant axis the
// default, as a border colour.
vec4 mx_image_texel(sampler2D tex, vec4 dflt, vec2 p, vec2 size, int uaddr, int vaddr, int level)
{
    if ((uaddr == 0 && (p.x < 0.0 || p.x >= size.x)) || (vaddr == 0 && (p.y < 0.0 || p.y >= size.y)))
        return dflt;
    vec2 q = vec2(mx_address_texel(p.x, size.x, uaddr), mx_address_texel(p.y, size.y, vaddr));
    return texelFetch(tex, ivec2(q), level);
}

// One row of the 4 x 4 texels: texels x - 1 .. x + 2 of row y, weighted by w.
vec4 mx_image_cubic_row(sampler2D tex, vec4 dflt, float x, float y, vec4 w, vec2 size, int uaddr, int vaddr, int level)
{
    return w.x * mx_image_texel(tex, dflt, vec2(x - 1.0, y), size, uaddr, vaddr, level)
         + w.y * mx_image_texel(tex, dflt, vec2(x, y), size, uaddr, vaddr, level)
         + w.z * mx_image_texel(tex, dflt, vec2(x + 1.0, y), size, uaddr, vaddr, level)
         + w.w * mx_image_texel(tex, dflt, vec2(x + 2.0, y), size, uaddr, vaddr, level);
}

// The bicubic B-spline of one level at image-space uv: texel centres lie at (i + 0.5) / size, so
// the sample lies at uv * size - 0.5 texels; its whole part is texel i, its fraction t.
vec4 mx_image_cubic_level(sampler2D tex, vec4 dflt, vec2 uv, int uaddr, int vaddr, int level)
{
    vec2 size = vec2(textureSize(tex, level));
    vec2 x = uv * size - 0.5;
    vec2 i = floor(x);
    vec4 wu = mx_bspline_weights(x.x - i.x);
    vec4 wv = mx_bspline_weights(x.y - i.y);
    return wv.x * mx_image_cubic_row(tex, dflt, i.x, i.y - 1.0, wu, size, uaddr, vaddr, level)
         + wv.y * mx_image_cubic_row(tex, dflt, i.x, i.y, wu, size, uaddr, vaddr, level)
         + wv.z * mx_image_cubic_row(tex, dflt, i.x, i.y + 1.0, wu, size, uaddr, vaddr, level)
         + wv.w * mx_image_cubic_row(tex, dflt, i.x, i.y + 2.0, wu, size, uaddr, vaddr, level);
}

// A cubic read: the bicubic B-spline of the two levels around `lod`, blended as trilinear blends
// its bilinear ones (one level where lod is whole: a sampler without mipmaps reads level 0 only).
vec4 mx_image_fetch_cubic(sampler2D tex, vec4 dflt, vec2 uv, int uaddr, int vaddr, float lod)
{
    float l0 = floor(lod);
    vec4 c0 = mx_image_cubic_level(tex, dflt, uv, uaddr, vaddr, int(l0));
    if (lod == l0)
        return c0;
    return mix(c0, mx_image_cubic_level(tex, dflt, uv, uaddr, vaddr, int(l0) + 1), lod - l0);
}
#endif

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
#ifdef MX_FEATURE_CUBIC_FILTER
    if (filtertype == 2)
        return mx_image_fetch_cubic(tex, dflt, uv, uaddr, vaddr, mx_image_lod(tex, uv, dx, dy));
#endif
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
    float lod = mx_image_lod(tex, uv, dx, dy);
    float maxLevel = floor(log2(max(size.x, size.y)));
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
