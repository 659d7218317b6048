// RGB <-> HSV (hexcone model). Hue is in [0, 1) turns; a hue outside that range wraps.

vec3 mx_rgbtohsv(vec3 c)
{
    float hi = max(c.r, max(c.g, c.b));
    float lo = min(c.r, min(c.g, c.b));
    float chroma = hi - lo;
    float s = hi > 0.0 ? chroma / hi : 0.0;
    float h = 0.0;
    if (s > 0.0)
    {
        // Sector of the hexagon from the largest channel, red first on ties.
        if (c.r >= hi)
            h = (c.g - c.b) / chroma;
        else if (c.g >= hi)
            h = 2.0 + (c.b - c.r) / chroma;
        else
            h = 4.0 + (c.r - c.g) / chroma;
        h /= 6.0;
        if (h < 0.0)
            h += 1.0;
    }
    return vec3(h, s, hi);
}

vec3 mx_hsvtorgb(vec3 hsv)
{
    // Nearly unsaturated colours are grey; otherwise each channel is a clamped triangle wave of
    // hue, scaled between v * (1 - s) and v.
    if (hsv.y < 0.0001)
        return vec3(hsv.z);
    vec3 wave = clamp(abs(fract(hsv.x + vec3(0.0, 2.0, 1.0) / 3.0) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
    return hsv.z * mix(vec3(1.0), wave, hsv.y);
}
