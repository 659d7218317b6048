// mix of two displacement shaders: blend offset and scale, bg at 0 and fg at 1.
void mx_mix_displacementshader(displacementshader fg, displacementshader bg, float amount, out displacementshader result)
{
    result.offset = mix(bg.offset, fg.offset, amount);
    result.scale = mix(bg.scale, fg.scale, amount);
}
