#include "lib/mx_hsv.glsl"

// <colorcorrect>: the artist-friendly chain, in this order: hue shift (turns), saturation about the
// ACEScg luminance, gamma (sign-preserving power 1/gamma), lift, gain, contrast about a pivot,
// exposure in stops.
vec3 mx_colorcorrect(vec3 c, float hue, float saturation, float gamma, float lift, float gain, float contrast, float contrastpivot, float exposure)
{
    vec3 hsv = mx_rgbtohsv(c);
    c = mx_hsvtorgb(vec3(hsv.x + hue, hsv.yz));
    c = mix(vec3(dot(c, vec3(0.2722287, 0.6740818, 0.0536895))), c, saturation);
    c = sign(c) * pow(abs(c), vec3(1.0 / gamma));
    c = c * (1.0 - lift) + lift;
    c *= gain;
    c = (c - contrastpivot) * contrast + contrastpivot;
    return c * exp2(exposure);
}

void mx_colorcorrect_color3(vec3 c, float hue, float saturation, float gamma, float lift, float gain, float contrast, float contrastpivot, float exposure, out vec3 result)
{
    result = mx_colorcorrect(c, hue, saturation, gamma, lift, gain, contrast, contrastpivot, exposure);
}

void mx_colorcorrect_color4(vec4 c, float hue, float saturation, float gamma, float lift, float gain, float contrast, float contrastpivot, float exposure, out vec4 result)
{
    result = vec4(mx_colorcorrect(c.rgb, hue, saturation, gamma, lift, gain, contrast, contrastpivot, exposure), c.a);
}
