#include "lib/mx_hsv.glsl"

void mx_rgbtohsv_color4(vec4 c, out vec4 result)
{
    result = vec4(mx_rgbtohsv(c.rgb), c.a);
}
