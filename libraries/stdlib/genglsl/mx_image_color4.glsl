#include "lib/mx_texture.glsl"
#pragma shadergen feature CUBIC_FILTER unless filtertype != cubic

// <image> color4: texcoord * uv_scale + uv_offset, v flipped, address modes and filter applied in the shader.
void mx_image_color4(sampler2D file, int layer, vec4 dflt, vec2 texcoord, int uaddressmode, int vaddressmode, int filtertype, int framerange, int frameoffset, int frameendaction, vec2 uv_scale, vec2 uv_offset, out vec4 result)
{
    vec2 uv = mx_image_uv(texcoord, uv_scale, uv_offset);
    result = mx_image_fetch(file, dflt, uv, uaddressmode, vaddressmode, filtertype);
}
