#include "lib/mx_hsv.glsl"

// <hsvadjust>: in HSV, add amount.x to hue (in turns) and scale saturation and value by amount.y, amount.z.
vec3 mx_hsvadjust(vec3 c, vec3 amount)
{
    vec3 hsv = mx_rgbtohsv(c);
    return mx_hsvtorgb(vec3(hsv.x + amount.x, hsv.yz * amount.yz));
}

void mx_hsvadjust_color3(vec3 c, vec3 amount, out vec3 result)
{
    result = mx_hsvadjust(c, amount);
}

void mx_hsvadjust_color4(vec4 c, vec3 amount, out vec4 result)
{
    result = vec4(mx_hsvadjust(c.rgb, amount), c.a);
}
