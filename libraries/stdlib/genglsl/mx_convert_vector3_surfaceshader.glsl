// <convert> vector3 -> surfaceshader: an unlit surface emitting the value as colour (opaque).
void mx_convert_vector3_surfaceshader(vec3 v, out surfaceshader result)
{
    result.color = v;
    result.transparency = vec3(0.0);
}
