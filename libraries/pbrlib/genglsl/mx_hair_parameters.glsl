// Parameter conversions for <chiang_hair_bsdf>.

// <deon_hair_absorption_from_melanin>: absorption of a fibre from its melanin concentration and
// redness (d'Eon et al. 2011); the pigment colours are exp(-absorption) of each pigment.
void mx_deon_hair_absorption_from_melanin(float melanin_concentration, float melanin_redness, vec3 eumelanin_color,
                                          vec3 pheomelanin_color, out vec3 absorption)
{
    float melanin = -log(max(1.0 - melanin_concentration, 0.0001));
    float eumelanin = melanin * (1.0 - melanin_redness);
    float pheomelanin = melanin * melanin_redness;
    absorption = max(eumelanin * -log(eumelanin_color) + pheomelanin * -log(pheomelanin_color), vec3(0.0));
}

// <chiang_hair_absorption_from_color>: the absorption that gives a fibre the colour `color` after
// multiple scattering, for azimuthal roughness betaN (Chiang et al. 2016, eq. 9).
void mx_chiang_hair_absorption_from_color(vec3 color, float betaN, out vec3 absorption)
{
    float b = betaN;
    float b2 = b * b;
    float b4 = b2 * b2;
    float k = 5.969 - 0.215 * b + 2.532 * b2 - 10.73 * b2 * b + 5.574 * b4 + 0.245 * b4 * b;
    vec3 sigma = log(min(max(color, 0.001), vec3(1.0))) / k;
    absorption = sigma * sigma;
}

// <chiang_hair_roughness>: longitudinal variance and azimuthal scale of the R, TT and TRT lobes from
// artist roughnesses (Chiang et al. 2016, eqs. 7 and 8); TT and TRT scale the variance's root.
void mx_chiang_hair_roughness(float longitudinal, float azimuthal, float scale_TT, float scale_TRT,
                              out vec2 roughness_R, out vec2 roughness_TT, out vec2 roughness_TRT)
{
    float lr = clamp(longitudinal, 0.001, 1.0);
    float ar = clamp(azimuthal, 0.001, 1.0);
    float sd = 0.726 * lr + 0.812 * lr * lr + 3.7 * pow(lr, 20.0);  // longitudinal standard deviation
    float v = sd * sd;
    float s = 0.265 * ar + 1.194 * ar * ar + 5.372 * pow(ar, 22.0);
    roughness_R = vec2(v, s);
    roughness_TT = vec2(v * scale_TT * scale_TT, s);
    roughness_TRT = vec2(v * scale_TRT * scale_TRT, s);
}
