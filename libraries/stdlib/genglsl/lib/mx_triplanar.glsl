#include "mx_texture.glsl"

// Triplanar projection: three periodic image lookups, one per axis, blended by the normal.
// The plane coordinates depend on the up axis (0 X, 1 Y, 2 Z) so the images stay upright.
vec4 mx_triplanar_fetch(sampler2D filex, sampler2D filey, sampler2D filez, vec4 dflt, vec3 P, vec3 N, int upaxis, float blend, int filtertype)
{
    vec2 uvx = upaxis == 2 ? P.yz : P.zy;
    vec2 uvy = upaxis == 0 ? P.zx : P.xz;
    vec2 uvz = upaxis == 0 ? vec2(-P.y, P.x) : P.xy;
    vec4 cx = mx_image_fetch(filex, dflt, vec2(uvx.x, 1.0 - uvx.y), 2, 2, filtertype);
    vec4 cy = mx_image_fetch(filey, dflt, vec2(uvy.x, 1.0 - uvy.y), 2, 2, filtertype);
    vec4 cz = mx_image_fetch(filez, dflt, vec2(uvz.x, 1.0 - uvz.y), 2, 2, filtertype);

    // Weights: |N| normalized to sum 1, sharpened by 1/blend (blend kept in [0.03, 1]), renormalized.
    vec3 w = abs(normalize(N));
    w /= w.x + w.y + w.z;
    w = pow(w, vec3(1.0 / clamp(blend, 0.03, 1.0)));
    w /= w.x + w.y + w.z;
    return cx * w.x + cy * w.y + cz * w.z;
}
