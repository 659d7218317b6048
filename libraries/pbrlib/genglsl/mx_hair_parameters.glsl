// Parameter conversions for <chiang_hair_bsdf> (Chiang et al. 2016, sect. 4; d'Eon et al. 2011).
#include "lib/mx_pbr_common.glsl"

// <deon_hair_absorption_from_melanin>: a fibre's absorption as the sum of its two pigments'. The
// concentration in [0, 1) is read as the fraction of light one unit of fibre lets through being
// 1 - concentration, i.e. an optical amount -ln(1 - concentration) of melanin, split between
// eumelanin and pheomelanin by `redness`; each pigment absorbs -ln(its colour) per unit amount.
void mx_deon_hair_absorption_from_melanin(float melanin_concentration, float melanin_redness, vec3 eumelanin_color,
                                          vec3 pheomelanin_color, out vec3 absorption)
{
    float amount = -log(max(1.0 - melanin_concentration, 1.0e-4));
    float redness = clamp(melanin_redness, 0.0, 1.0);
    vec3 perEumelanin = -log(clamp(eumelanin_color, 1.0e-4, 1.0));
    vec3 perPheomelanin = -log(clamp(pheomelanin_color, 1.0e-4, 1.0));
    absorption = max(amount * mix(perEumelanin, perPheomelanin, redness), vec3(0.0));
}

// <chiang_hair_absorption_from_color>: the absorption that gives hair of azimuthal roughness betaN
// the multiply-scattered colour `color`: sigma = (ln(color) / poly(betaN))^2 with the paper's
// fifth-degree polynomial (Chiang et al. 2016, eq. 9).
void mx_chiang_hair_absorption_from_color(vec3 color, float betaN, out vec3 absorption)
{
    const float POLY[6] = float[6](5.969, -0.215, 2.532, -10.73, 5.574, 0.245);
    float poly = 0.0;
    for (int i = 5; i >= 0; i--)
        poly = poly * betaN + POLY[i];
    absorption = mx_sqr(log(clamp(color, 0.001, 1.0)) / poly);
}

// <chiang_hair_roughness>: from artist roughnesses in [0, 1] to the longitudinal variance v and the
// azimuthal logistic scale s of each lobe (Chiang et al. 2016, eqs. 7 and 8: polynomial fits that
// make the perceived width linear in the parameter); TT and TRT scale the longitudinal width.
void mx_chiang_hair_roughness(float longitudinal, float azimuthal, float scale_TT, float scale_TRT,
                              out vec2 roughness_R, out vec2 roughness_TT, out vec2 roughness_TRT)
{
    float bm = clamp(longitudinal, 0.001, 1.0);
    float bn = clamp(azimuthal, 0.001, 1.0);
    float width = 0.726 * bm + 0.812 * bm * bm + 3.7 * pow(bm, 20.0);
    float s = 0.265 * bn + 1.194 * bn * bn + 5.372 * pow(bn, 22.0);
    roughness_R = vec2(width * width, s);
    roughness_TT = vec2(mx_sqr(width * scale_TT), s);
    roughness_TRT = vec2(mx_sqr(width * scale_TRT), s);
}
