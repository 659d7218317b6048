#version 400
// Passes on streams a mesh may lack: the renderer supplies MaterialX's defaults for them.
uniform mat4 u_worldViewProjectionMatrix = mat4(1.0);

in vec3 i_position;
in vec4 i_color_0;
in float i_geomprop_age;

out VertexData
{
    vec4 color_0;
    float geomprop_age;
} vd;

void main()
{
    gl_Position = u_worldViewProjectionMatrix * vec4(i_position, 1.0);
    vd.color_0 = i_color_0;
    vd.geomprop_age = i_geomprop_age;
}
