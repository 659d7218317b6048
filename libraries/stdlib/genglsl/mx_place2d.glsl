// <place2d>: place a texture in uv space. Order 0 (SRT) scales, then rotates, then offsets;
// order 1 (TRS) the reverse. Both work about `pivot`; `rotate` is in degrees and turns the
// coordinate clockwise, so the texture turns counter-clockwise.
void mx_place2d_vector2(vec2 texcoord, vec2 pivot, vec2 scale, float rotate, vec2 offset, int operationorder, out vec2 result)
{
    float angle = radians(rotate);
    float c = cos(angle);
    float s = sin(angle);
    vec2 p = texcoord - pivot;
    // the turn written out, not as a mat2: every target prints it alike (OSL has no 2x2 matrix)
    if (operationorder == 0)
    {
        p /= scale;
        p = vec2(c * p.x + s * p.y, c * p.y - s * p.x) - offset;
    }
    else
    {
        p -= offset;
        p = vec2(c * p.x + s * p.y, c * p.y - s * p.x) / scale;
    }
    result = p + pivot;
}
