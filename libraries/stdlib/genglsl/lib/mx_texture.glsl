// File-texture sampling shared by the image family (image, tiledimage, triplanarprojection,
// latlongimage).
//
// The renderer binds every file texture with REPEAT wrap, trilinear mipmapping and rows uploaded
// top row first, so address modes and the closest filter are applied here, in the shader:
//   address mode (enum index): 0 constant, 1 clamp, 2 periodic, 3 mirror
//   filter type  (enum index): 0 closest, 1 linear, 2 cubic (sampled as linear)
// Mip levels are chosen from the derivatives of the unwrapped coordinate, so folding or clamping
// never creates a seam of coarse mips where the wrapped coordinate jumps.

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

// Sample `tex` at image-space `uv`; a coordinate outside [0, 1] on a constant axis returns `dflt`.
// Derivatives and the periodic fast path are taken before any per-pixel selection, so they stay in
// uniform control flow.
vec4 mx_image_fetch(sampler2D tex, vec4 dflt, vec2 uv, int uaddr, int vaddr, int filtertype)
{
    bool periodicU = uaddr == 2;
    bool periodicV = vaddr == 2;
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    vec4 texel;
    if (filtertype != 0 && periodicU && periodicV)
    {
        texel = texture(tex, uv);
    }
    else
    {
        vec2 size = vec2(textureSize(tex, 0));
        vec2 st = vec2(mx_address_fold(uv.x, uaddr), mx_address_fold(uv.y, vaddr));
        if (filtertype == 0)
        {
            // Nearest texel of the base level, wrapped on integer texel coordinates.
            vec2 t = floor(st * size);
            vec2 clamped = clamp(t, vec2(0.0), size - 1.0);
            vec2 wrapped = mod(t, size);
            t = vec2(periodicU ? wrapped.x : clamped.x, periodicV ? wrapped.y : clamped.y);
            texel = texelFetch(tex, ivec2(t), 0);
        }
        else
        {
            // Clamp-to-edge on a REPEAT sampler: keep the filter footprint half a texel inside
            // the edge, measured at the coarser of the two mip levels the trilinear filter blends.
            vec2 dxt = dx * size;
            vec2 dyt = dy * size;
            float lod = ceil(0.5 * log2(max(max(dot(dxt, dxt), dot(dyt, dyt)), 1.0)));
            vec2 margin = min(vec2(0.5), 0.5 * exp2(lod) / size);
            vec2 edge = clamp(st, margin, 1.0 - margin);
            st = vec2(periodicU ? st.x : edge.x, periodicV ? st.y : edge.y);
            texel = textureGrad(tex, st, dx, dy);
        }
    }
    bool outsideU = uaddr == 0 && (uv.x < 0.0 || uv.x > 1.0);
    bool outsideV = vaddr == 0 && (uv.y < 0.0 || uv.y > 1.0);
    return (outsideU || outsideV) ? dflt : texel;
}
