#version 400
// An image node as MaterialX generates it for GL: uv scale and offset, then v flipped because
// images are uploaded top row first.
uniform sampler2D image_file;
uniform vec2 image_uvscale = vec2(1.0);
uniform vec2 image_uvoffset = vec2(0.0);

in VertexData
{
    vec3 normalWorld;
    vec3 positionWorld;
    vec2 texcoord_0;
} vd;

out vec4 out1;

void main()
{
    vec2 uv = vd.texcoord_0 * image_uvscale + image_uvoffset;
    out1 = vec4(texture(image_file, vec2(uv.x, 1.0 - uv.y)).rgb, 1.0);
}
