// mix of two volume shaders: blend each member, bg at 0 and fg at 1.
void mx_mix_volumeshader(volumeshader fg, volumeshader bg, float amount, out volumeshader result)
{
    result.color = mix(bg.color, fg.color, amount);
    result.transparency = mix(bg.transparency, fg.transparency, amount);
}
