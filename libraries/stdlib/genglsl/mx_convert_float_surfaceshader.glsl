// <convert> float -> surfaceshader: an unlit surface emitting the value as colour (opaque).
void mx_convert_float_surfaceshader(float v, out surfaceshader result)
{
    result.color = vec3(v);
    result.transparency = vec3(0.0);
}
