// <chiang_hair_bsdf>: Chiang et al. 2016 hair scattering (R, TT, TRT and a TRRT+ remainder) for
// fibres along `curve_direction`; the environment term is a GGX approximation.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_hair.glsl"
#include "lib/mx_specular.glsl"

void mx_chiang_hair_bsdf(ClosureData closureData, vec3 tint_R, vec3 tint_TT, vec3 tint_TRT, float ior,
                         vec2 roughness_R, vec2 roughness_TT, vec2 roughness_TRT, float cuticle_angle,
                         vec3 absorption_coefficient, vec3 N, vec3 X, inout BSDF bsdf)
{
    vec3 V = closureData.V;
    N = mx_shading_normal(N, closureData.N, V);
    bsdf.throughput = vec3(0.0);

    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        mat3 frame = mx_tangent_frame(N, X);  // x along the fibre
        vec3 Vt = V * frame;
        vec3 Lt = L * frame;

        // Longitudinal angles (from the normal plane) and the azimuth between L and V.
        float sinThetaO = Vt.x;
        float sinThetaI = Lt.x;
        float cosThetaO = mx_hair_cos_from_sin(sinThetaO);
        float cosThetaI = mx_hair_cos_from_sin(sinThetaI);
        float phi = atan(Lt.z * Vt.y - Vt.z * Lt.y, Lt.y * Vt.y + Lt.z * Vt.z);

        // Offset of the view ray across the fibre, and of the refracted ray.
        vec3 Vperp = normalize(V - frame[0] * sinThetaO);
        float cosGammaO = dot(N, Vperp);
        float sinGammaO = mx_hair_cos_from_sin(cosGammaO) * (dot(Vperp, frame[1]) > 0.0 ? -1.0 : 1.0);
        float gammaO = asin(sinGammaO);
        float cosThetaT = mx_hair_cos_from_sin(sinThetaO / ior);
        float etaP = sqrt(max(ior * ior - sinThetaO * sinThetaO, 0.0)) / max(cosThetaO, MX_EPS);
        float sinGammaT = clamp(sinGammaO / etaP, -1.0, 1.0);
        float cosGammaT = sqrt(1.0 - sinGammaT * sinGammaT);
        float gammaT = asin(sinGammaT);

        // Attenuation of each lobe: Fresnel at the cuticle, absorption across the fibre.
        float f = mx_fresnel_dielectric(cosThetaO * cosGammaO, ior);
        vec3 T = exp(-absorption_coefficient * (2.0 * cosGammaT / cosThetaT));
        vec3 A[4];
        A[0] = vec3(f);
        A[1] = (1.0 - f) * (1.0 - f) * T;
        A[2] = A[1] * T * f;
        A[3] = A[2] * T * f / (vec3(1.0) - T * f);

        vec3 tints[4];
        tints[0] = tint_R;
        tints[1] = tint_TT;
        tints[2] = tint_TRT;
        tints[3] = tint_TRT;
        vec2 rough[4];
        rough[0] = clamp(roughness_R, 0.001, 1.0);
        rough[1] = clamp(roughness_TT, 0.001, 1.0);
        rough[2] = clamp(roughness_TRT, 0.001, 1.0);
        rough[3] = rough[2];

        // Cuticle scales tilt each lobe's incident angle by a multiple of alpha (none for TRRT+).
        float alpha = cuticle_angle * MX_PI - 0.5 * MX_PI;  // [0, 1] -> [-pi/2, pi/2]
        vec3 sum = vec3(0.0);
        for (int p = 0; p < 4; p++)
        {
            float sinI = sinThetaI;
            float cosI = cosThetaI;
            if (alpha != 0.0 && p < 3)
            {
                float tilt = (2.0 - 3.0 * float(p)) * alpha;
                sinI = sinThetaI * cos(tilt) + cosThetaI * sin(tilt);
                cosI = cosThetaI * cos(tilt) - sinThetaI * sin(tilt);
            }
            float Mp = mx_hair_Mp(sinI, cosI, sinThetaO, cosThetaO, rough[p].x);
            // The TRRT+ remainder is spread evenly in azimuth; the weight pi/2 is the reference's.
            float Np = (p == 3) ? 0.5 * MX_PI : mx_hair_Np(phi, p, rough[p].y, gammaO, gammaT);
            sum += Mp * Np * max(tints[p], vec3(0.0)) * A[p];
        }
        bsdf.response = sum * (closureData.occlusion * MX_INV_PI);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        // A rough stand-in: a GGX dielectric lobe with the mean roughness and tint of the three lobes.
        FresnelData fd = mx_fresnel_data(FRESNEL_MODEL_DIELECTRIC, vec3(ior), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0),
                                         0.0, 0.0, 1.0);
        vec2 alpha = mx_ggx_clamp_alpha((roughness_R + roughness_TT + roughness_TRT) / vec2(3.0));
        vec3 tint = max((tint_R + tint_TT + tint_TRT) / vec3(3.0), 0.0);
        bsdf.response = mx_environment_radiance(N, V, X, alpha, 0, fd) * tint;
    }
}
