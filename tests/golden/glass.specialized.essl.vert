#version 300 es
precision highp float;
precision highp int;

// Uniform block: PrivateUniforms
uniform mat4 u_worldMatrix;
uniform mat4 u_viewProjectionMatrix;
uniform mat4 u_worldInverseTransposeMatrix;

in vec3 i_position;
in vec3 i_normal;
in vec3 i_tangent;

out vec3 vd_normalWorld;
out vec3 vd_tangentWorld;
out vec3 vd_positionWorld;

void main()
{
    vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);
    gl_Position = u_viewProjectionMatrix * hPositionWorld;
    vd_normalWorld = normalize((u_worldInverseTransposeMatrix * vec4(i_normal, 0.0)).xyz);
    vd_tangentWorld = normalize((u_worldMatrix * vec4(i_tangent, 0.0)).xyz);
    vd_positionWorld = hPositionWorld.xyz;
}
