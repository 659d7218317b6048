// disjointover: the background shows through only where the two alphas together exceed one,
// scaled so that the summed coverage stays at one. A background alpha of ~0 in that case gives black.
void mx_disjointover_color4(vec4 fg, vec4 bg, float amount, out vec4 result)
{
    float coverage = fg.a + bg.a;
    vec3 rgb = fg.rgb + bg.rgb;
    if (coverage > 1.0)
        rgb = (abs(bg.a) < 1.0e-8) ? vec3(0.0) : fg.rgb + bg.rgb * ((1.0 - fg.a) / bg.a);
    result = mix(bg, vec4(rgb, min(coverage, 1.0)), amount);
}
