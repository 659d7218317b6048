// <normalmap>: decode a tangent-space normal stored in [0, 1] and express it in the frame
// (tangent, bitangent, normal); `scale` multiplies the tangent-plane components. An all-zero input
// reads as the unperturbed normal.
void mx_normalmap_vector2(vec3 encoded, vec2 scale, vec3 N, vec3 T, vec3 B, out vec3 result)
{
    vec3 n = dot(encoded, encoded) == 0.0 ? vec3(0.0, 0.0, 1.0) : encoded * 2.0 - 1.0;
    result = normalize(T * (n.x * scale.x) + B * (n.y * scale.y) + N * n.z);
}

void mx_normalmap_float(vec3 encoded, float scale, vec3 N, vec3 T, vec3 B, out vec3 result)
{
    mx_normalmap_vector2(encoded, vec2(scale), N, T, B, result);
}
