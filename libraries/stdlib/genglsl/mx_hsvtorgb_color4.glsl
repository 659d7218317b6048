#include "lib/mx_hsv.glsl"

void mx_hsvtorgb_color4(vec4 c, out vec4 result)
{
    result = vec4(mx_hsvtorgb(c.rgb), c.a);
}
