// rotate3d: turn a vector by `degrees` about `axis` (normalized here).
// MaterialX multiplies row vectors (v' = v * M), so the sense of rotation is that of
// Rodrigues' formula with the cross product taken as v x k.
void mx_rotate3d_vector3(vec3 v, float degrees, vec3 axis, out vec3 result)
{
    vec3 k = normalize(axis);
    float angle = radians(degrees);
    float c = cos(angle);
    float s = sin(angle);
    result = v * c + cross(v, k) * s + k * (dot(k, v) * (1.0 - c));
}
