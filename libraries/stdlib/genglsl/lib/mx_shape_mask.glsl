// 2D shape masks: 1.0 inside (boundary included), 0.0 outside.

float mx_shape_circle(vec2 p, vec2 center, float radius)
{
    vec2 d = p - center;
    return (dot(d, d) > radius * radius) ? 0.0 : 1.0;
}

// Four circles of the given radius whose centres sit radius/2 from `center` along +-x and +-y
// (evaluated at doubled scale, as the union of circles of radius r around 2*center -+ r).
float mx_shape_cloverleaf(vec2 p, vec2 center, float radius)
{
    vec2 s = p + p;
    vec2 c = center + center;
    float a = max(mx_shape_circle(vec2(s.x + radius, s.y), c, radius),
                  mx_shape_circle(vec2(s.x - radius, s.y), c, radius));
    float b = max(mx_shape_circle(vec2(s.x, s.y - radius), c, radius),
                  mx_shape_circle(vec2(s.x, s.y + radius), c, radius));
    return max(a, b);
}

// Hexagon with corners on the circle of the given radius, flat sides left and right: the
// point is folded into one sector by two mirror lines, then compared against the edge
// (after Inigo Quilez's hexagon distance, with the sign test on the sum of the components).
float mx_shape_hexagon(vec2 p, vec2 center, float radius)
{
    vec3 k = vec3(-0.866025, 0.5, 0.57735);
    vec2 q = abs(p - center).yx;
    q -= k.xy * min(dot(k.xy, q), 0.0) * 2.0;
    vec2 m = vec2(-k.x, k.y);
    q -= m * min(dot(m, q), 0.0) * 2.0;
    q -= vec2(clamp(q.x, -k.z * radius, k.z * radius), radius);
    return (q.x + q.y > 0.0) ? 0.0 : 1.0;
}

// Capsule around the segment point1-point2 (relative to center) of the given radius.
float mx_shape_line(vec2 p, vec2 center, float radius, vec2 point1, vec2 point2)
{
    vec2 pa = (p - center) - point1;
    vec2 ba = point2 - point1;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return (distance(pa, ba * h) > radius) ? 0.0 : 1.0;
}
