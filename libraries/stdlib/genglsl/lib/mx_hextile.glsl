// Hex tiling: break up the repetition of a tiled texture by sampling it three times per point,
// once per vertex of the surrounding triangle of a hexagonal lattice, each lookup with its own
// random rotation, scale and offset, and blending the three by barycentric weight.
// After Morten S. Mikkelsen, "Practical Real-Time Hex-Tiling", JCGT 11(2), 2022.

// 2D -> 2D hash in [0, 1) (Dave Hoskins, "Hash without Sine", hash22; MIT licence).
vec2 mx_hextile_hash(vec2 p)
{
    vec3 p3 = fract(p.xyx * vec3(0.1031, 0.1030, 0.0973));
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.xx + p3.yz) * p3.zy);
}

// Schlick's gain: an S-curve on [0, 1] that is the identity at r = 0.5.
float mx_hextile_gain(float x, float r)
{
    float k = (1.0 / clamp(r, 0.001, 0.999) - 2.0) * (1.0 - 2.0 * x);
    return x < 0.5 ? x / (k + 1.0) : (k - x) / (k - 1.0);
}

// Blend weights from the barycentric tile weights, biased by per-sample `luma` (vec3(1.0) for none).
vec3 mx_hextile_weights(vec3 luma, vec3 tile, float falloff)
{
    vec3 t2 = tile * tile;
    vec3 t7 = t2 * t2 * t2 * tile;
    vec3 w = luma * t7;
    w /= w.x + w.y + w.z;
    if (falloff != 0.5)
    {
        w = vec3(mx_hextile_gain(w.x, falloff), mx_hextile_gain(w.y, falloff), mx_hextile_gain(w.z, falloff));
        w /= w.x + w.y + w.z;
    }
    return w;
}

// Rotate v by `angle` radians counter-clockwise.
vec2 mx_hextile_rotate(vec2 v, float c, float s)
{
    return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

// The three lookups for image-space coordinate `uv`: their coordinates and gradients, their
// barycentric weights and their rotation angles (radians).
void mx_hextile_lookups(vec2 uv, float rotation, vec2 rotationrange, float scale, vec2 scalerange,
                        float offset, vec2 offsetrange,
                        out vec2 uv1, out vec2 uv2, out vec2 uv3,
                        out vec2 dx1, out vec2 dx2, out vec2 dx3,
                        out vec2 dy1, out vec2 dy2, out vec2 dy3,
                        out vec3 tile_weights, out vec3 angles)
{
    // Lattice of unit-side triangles scaled so one hexagon covers about one texture tile.
    const float LATTICE = 3.4641016151377544;  // 2 * sqrt(3)
    vec2 st = uv * LATTICE;
    vec2 skewed = vec2(st.x - 0.57735027 * st.y, 1.15470054 * st.y);
    vec2 base = floor(skewed);
    vec2 f = skewed - base;
    float z = 1.0 - f.x - f.y;
    float upper = z > 0.0 ? 0.0 : 1.0;  // which triangle of the skewed cell
    float sgn = 2.0 * upper - 1.0;
    tile_weights = vec3(-z * sgn, upper - f.y * sgn, upper - f.x * sgn);

    vec2 id1 = base + vec2(upper, upper);
    vec2 id2 = base + vec2(upper, 1.0 - upper);
    vec2 id3 = base + vec2(1.0 - upper, upper);

    // Tile centres back in uv space (inverse skew, inverse lattice scale).
    vec2 c1 = id1 / LATTICE;
    vec2 c2 = id2 / LATTICE;
    vec2 c3 = id3 / LATTICE;
    c1 = vec2(c1.x + 0.5 * c1.y, c1.y / 1.15470054);
    c2 = vec2(c2.x + 0.5 * c2.y, c2.y / 1.15470054);
    c3 = vec2(c3.x + 0.5 * c3.y, c3.y / 1.15470054);

    vec2 r1 = mx_hextile_hash(id1 + vec2(0.12345));
    vec2 r2 = mx_hextile_hash(id2 + vec2(0.12345));
    vec2 r3 = mx_hextile_hash(id3 + vec2(0.12345));

    vec2 rr = radians(rotationrange);
    angles = mix(vec3(rr.x), vec3(rr.y), vec3(r1.x, r2.x, r3.x) * rotation);
    vec3 cs = cos(angles);
    vec3 sn = sin(angles);
    vec3 sizes = mix(vec3(1.0), mix(vec3(scalerange.x), vec3(scalerange.y), vec3(r1.y, r2.y, r3.y)), scale);
    vec2 o1 = mix(vec2(offsetrange.x), vec2(offsetrange.y), r1 * offset);
    vec2 o2 = mix(vec2(offsetrange.x), vec2(offsetrange.y), r2 * offset);
    vec2 o3 = mix(vec2(offsetrange.x), vec2(offsetrange.y), r3 * offset);

    uv1 = mx_hextile_rotate(uv - c1, cs.x, sn.x) / sizes.x + c1 + o1;
    uv2 = mx_hextile_rotate(uv - c2, cs.y, sn.y) / sizes.y + c2 + o2;
    uv3 = mx_hextile_rotate(uv - c3, cs.z, sn.z) / sizes.z + c3 + o3;

    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    dx1 = mx_hextile_rotate(dx, cs.x, sn.x) / sizes.x;
    dx2 = mx_hextile_rotate(dx, cs.y, sn.y) / sizes.y;
    dx3 = mx_hextile_rotate(dx, cs.z, sn.z) / sizes.z;
    dy1 = mx_hextile_rotate(dy, cs.x, sn.x) / sizes.x;
    dy2 = mx_hextile_rotate(dy, cs.y, sn.y) / sizes.y;
    dy3 = mx_hextile_rotate(dy, cs.z, sn.z) / sizes.z;
}
