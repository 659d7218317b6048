#version 450

layout(std140, set = 0, binding = 0) uniform VertexUniforms
{
    mat4 u_worldMatrix;  // offset 0
    mat4 u_viewProjectionMatrix;  // offset 64
};

layout(location = 0) in vec3 i_position;
layout(location = 1) in vec2 i_texcoord_0;

layout(location = 0) out vec3 vd_positionObject;
layout(location = 1) out vec2 vd_texcoord_0;

void main()
{
    vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);
    gl_Position = u_viewProjectionMatrix * hPositionWorld;
    vd_positionObject = i_position;
    vd_texcoord_0 = i_texcoord_0;
}
