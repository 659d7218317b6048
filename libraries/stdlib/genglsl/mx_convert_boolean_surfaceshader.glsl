// <convert> boolean -> surfaceshader: an unlit surface emitting the value as colour (opaque).
void mx_convert_boolean_surfaceshader(bool v, out surfaceshader result)
{
    result.color = vec3(v ? 1.0 : 0.0);
    result.transparency = vec3(0.0);
}
