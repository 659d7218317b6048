// <place2d>: place a texture in uv space. Order 0 (SRT) scales, then rotates, then offsets;
// order 1 (TRS) the reverse. Both work about `pivot`; `rotate` is in degrees and turns the
// coordinate clockwise, so the texture turns counter-clockwise.
void mx_place2d_vector2(vec2 texcoord, vec2 pivot, vec2 scale, float rotate, vec2 offset, int operationorder, out vec2 result)
{
    float angle = radians(rotate);
    float c = cos(angle);
    float s = sin(angle);
    mat2 turn = mat2(c, -s, s, c);  // columns: (c, -s), (s, c)
    vec2 p = texcoord - pivot;
    if (operationorder == 0)
        p = turn * (p / scale) - offset;
    else
        p = (turn * (p - offset)) / scale;
    result = p + pivot;
}
