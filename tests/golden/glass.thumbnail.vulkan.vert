#version 450

layout(std140, set = 0, binding = 0) uniform VertexUniforms
{
    mat4 u_worldMatrix;  // offset 0
    mat4 u_viewProjectionMatrix;  // offset 64
    mat4 u_worldInverseTransposeMatrix;  // offset 128
};

layout(location = 0) in vec3 i_position;
layout(location = 1) in vec3 i_normal;
layout(location = 2) in vec3 i_tangent;

layout(location = 0) out vec3 vd_normalWorld;
layout(location = 1) out vec3 vd_tangentWorld;
layout(location = 2) out vec3 vd_positionWorld;

void main()
{
    vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);
    gl_Position = u_viewProjectionMatrix * hPositionWorld;
    vd_normalWorld = normalize((u_worldInverseTransposeMatrix * vec4(i_normal, 0.0)).xyz);
    vd_tangentWorld = normalize((u_worldMatrix * vec4(i_tangent, 0.0)).xyz);
    vd_positionWorld = hPositionWorld.xyz;
}
