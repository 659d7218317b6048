// <convert> color4 -> surfaceshader: an unlit surface emitting the value as colour (the fourth component is the opacity).
void mx_convert_color4_surfaceshader(vec4 v, out surfaceshader result)
{
    result.color = v.rgb * v.a;
    result.transparency = vec3(1.0 - v.a);
}
