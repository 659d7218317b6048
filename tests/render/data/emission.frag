#version 400
// A constant-colour emission: every covered pixel is exactly u_color.
uniform vec3 u_color = vec3(1.0, 0.0, 1.0);  // the record's value must replace this

in VertexData
{
    vec3 normalWorld;
    vec3 positionWorld;
    vec2 texcoord_0;
} vd;

out vec4 out1;

void main()
{
    out1 = vec4(u_color, 1.0);
}
