#include "lib/mx_hextile.glsl"

// <hextiledimage>: hex-tiled lookup of a periodic image (see lib/mx_hextile.glsl). Brighter samples
// win near tile borders by `falloffcontrast`, measured with `lumacoeffs`; alpha blends without it.
vec4 mx_hextiledimage_fetch(sampler2D file, vec2 texcoord, vec2 tiling, float rotation, vec2 rotationrange,
                            float scale, vec2 scalerange, float offset, vec2 offsetrange,
                            float falloff, float falloffcontrast, vec3 lumacoeffs)
{
    vec2 uv1, uv2, uv3, dx1, dx2, dx3, dy1, dy2, dy3;
    vec3 tile, angles;
    vec2 uv = texcoord * tiling;
    mx_hextile_lookups(vec2(uv.x, 1.0 - uv.y), rotation, rotationrange, scale, scalerange,
                       offset, offsetrange, uv1, uv2, uv3, dx1, dx2, dx3, dy1, dy2, dy3, tile, angles);
    vec4 c1 = textureGrad(file, uv1, dx1, dy1);
    vec4 c2 = textureGrad(file, uv2, dx2, dy2);
    vec4 c3 = textureGrad(file, uv3, dx3, dy3);
    vec3 luma = vec3(dot(c1.rgb, lumacoeffs), dot(c2.rgb, lumacoeffs), dot(c3.rgb, lumacoeffs));
    vec3 w = mx_hextile_weights(mix(vec3(1.0), luma, falloffcontrast), tile, falloff);
    vec3 wa = mx_hextile_weights(vec3(1.0), tile, falloff);
    return vec4(c1.rgb * w.x + c2.rgb * w.y + c3.rgb * w.z, c1.a * wa.x + c2.a * wa.y + c3.a * wa.z);
}

void mx_hextiledimage_color3(sampler2D file, vec3 dflt, vec2 texcoord, vec2 tiling, float rotation, vec2 rotationrange, float scale, vec2 scalerange, float offset, vec2 offsetrange, float falloff, float falloffcontrast, vec3 lumacoeffs, out vec3 result)
{
    result = mx_hextiledimage_fetch(file, texcoord, tiling, rotation, rotationrange, scale, scalerange, offset, offsetrange, falloff, falloffcontrast, lumacoeffs).rgb;
}

void mx_hextiledimage_color4(sampler2D file, vec4 dflt, vec2 texcoord, vec2 tiling, float rotation, vec2 rotationrange, float scale, vec2 scalerange, float offset, vec2 offsetrange, float falloff, float falloffcontrast, vec3 lumacoeffs, out vec4 result)
{
    result = mx_hextiledimage_fetch(file, texcoord, tiling, rotation, rotationrange, scale, scalerange, offset, offsetrange, falloff, falloffcontrast, lumacoeffs);
}
