// mix of two surface shaders: blend each member, bg at 0 and fg at 1.
void mx_mix_surfaceshader(surfaceshader fg, surfaceshader bg, float amount, out surfaceshader result)
{
    result.color = mix(bg.color, fg.color, amount);
    result.transparency = mix(bg.transparency, fg.transparency, amount);
}
