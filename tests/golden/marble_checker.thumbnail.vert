#version 400

// Uniform block: PrivateUniforms
uniform mat4 u_worldMatrix;
uniform mat4 u_viewProjectionMatrix;

in vec3 i_position;
in vec2 i_texcoord_0;

out VertexData
{
    vec3 positionObject;
    vec2 texcoord_0;
} vd;

void main()
{
    vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);
    gl_Position = u_viewProjectionMatrix * hPositionWorld;
    vd.positionObject = i_position;
    vd.texcoord_0 = i_texcoord_0;
}
