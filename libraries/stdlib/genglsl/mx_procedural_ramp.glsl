// <ramp> and <ramp_gradient>: a colour ramp of up to 10 control points over one coordinate.
//
// ramp_gradient handles one interval [interval1, interval2] between color1 and color2: for
// x > interval1 it returns the interpolated colour (0 linear, 1 smooth, 2 step: color1 below
// interval2, color2 from it on; other values give 0 weights / black), else prev_color; from
// interval number num_intervals on it passes prev_color through. ramp chains the intervals,
// with x taken from texcoord by type: 0 standard (u), 1 radial (angle around the centre),
// 2 circular (distance from the centre), 3 box (largest axis distance from the centre).

vec4 mx_ramp_interval(float x, float lo, float hi, vec4 c1, vec4 c2, int interpolation, vec4 prev,
                      int interval_num, int num_intervals)
{
    if (interval_num >= num_intervals || !(x > lo))
        return prev;
    if (interpolation == 2)
        return (hi > x) ? c1 : c2;
    if (interpolation > 2)
        return vec4(0.0);
    float w = 0.0;
    if (interpolation < 1)
        w = (clamp(x, lo, hi) - lo) / (hi - lo);
    else
        w = (x >= hi) ? 1.0 : smoothstep(lo, hi, x);   // x > lo holds here
    return mix(c1, c2, w);
}

void mx_ramp_gradient(float x, float interval1, float interval2, vec4 color1, vec4 color2, int interpolation,
                      vec4 prev_color, int interval_num, int num_intervals, out vec4 result)
{
    result = mx_ramp_interval(x, interval1, interval2, color1, color2, interpolation, prev_color,
                              interval_num, num_intervals);
}

float mx_ramp_coordinate(vec2 texcoord, int type)
{
    vec2 d = texcoord - 0.5;
    if (type < 1)
        return texcoord.x;
    if (type == 1)
        return atan(d.x, d.y) / 6.28319 + 0.5;
    if (type == 2)
        return length(d * 1.414);
    if (type == 3)
    {
        vec2 a = abs(d);
        return (a.x > a.y) ? a.x * 2.0 : a.y * 2.0;
    }
    return 0.0;
}

void mx_ramp(vec2 texcoord, int type, int interpolation, int num_intervals,
             float interval1, vec4 color1, float interval2, vec4 color2, float interval3, vec4 color3,
             float interval4, vec4 color4, float interval5, vec4 color5, float interval6, vec4 color6,
             float interval7, vec4 color7, float interval8, vec4 color8, float interval9, vec4 color9,
             float interval10, vec4 color10, out vec4 result)
{
    float x = mx_ramp_coordinate(texcoord, type);
    float stops[10] = float[10](interval1, interval2, interval3, interval4, interval5,
                                interval6, interval7, interval8, interval9, interval10);
    vec4 colors[10] = vec4[10](color1, color2, color3, color4, color5,
                               color6, color7, color8, color9, color10);
    vec4 c = color1;
    for (int k = 0; k < 9; ++k)
    {
        if (k + 1 >= num_intervals)
            break;
        c = mx_ramp_interval(x, stops[k], stops[k + 1], colors[k], colors[k + 1], interpolation, c,
                             k + 1, num_intervals);
    }
    result = c;
}
