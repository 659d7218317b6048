// <convert> integer -> surfaceshader: an unlit surface emitting the value as colour (opaque).
void mx_convert_integer_surfaceshader(int v, out surfaceshader result)
{
    result.color = vec3(float(v));
    result.transparency = vec3(0.0);
}
