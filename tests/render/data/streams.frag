#version 400
// Shows the default vertex streams: colour set 0 in rgb, a geometric property in alpha.
in VertexData
{
    vec4 color_0;
    float geomprop_age;
} vd;

out vec4 out1;

void main()
{
    out1 = vec4(vd.color_0.rgb, 1.0 - vd.geomprop_age);
}
