// <convert> vector2 -> surfaceshader: an unlit surface emitting the value as colour (opaque).
void mx_convert_vector2_surfaceshader(vec2 v, out surfaceshader result)
{
    result.color = vec3(v, 0.0);
    result.transparency = vec3(0.0);
}
