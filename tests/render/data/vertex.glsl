#version 400
// The vertex stage MaterialX's GLSL generator writes for a lit material, reduced to what the tests use.
uniform mat4 u_worldMatrix = mat4(1.0);
uniform mat4 u_viewProjectionMatrix = mat4(1.0);
uniform mat4 u_worldInverseTransposeMatrix = mat4(1.0);

in vec3 i_position;
in vec3 i_normal;
in vec2 i_texcoord_0;

out VertexData
{
    vec3 normalWorld;
    vec3 positionWorld;
    vec2 texcoord_0;
} vd;

void main()
{
    vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);
    gl_Position = u_viewProjectionMatrix * hPositionWorld;
    vd.normalWorld = normalize((u_worldInverseTransposeMatrix * vec4(i_normal, 0.0)).xyz);
    vd.positionWorld = hPositionWorld.xyz;
    vd.texcoord_0 = i_texcoord_0;
}
