// Media. The hardware targets answer a medium in the TRANSMISSION context (the only one that looks
// through a surface) by its transmittance along the light's path inside the object. They have no
// geometry there: a transmitting surface refracts as a solid unit sphere (mx_refraction_solid_sphere),
// so the path is that sphere's chord along the refracted view ray, 2 cos(theta_t). Averaged over the
// sphere as a camera sees it (parallel rays over its disk, sin(theta_i) = rho, density 2 rho) it is
// (4 n^2 / 3) (1 - (1 - 1/n^2)^(3/2)): Cauchy's mean chord 4/3 at n = 1, 1.76 at n = 1.5, 2 as n
// grows. A medium does not see its interface's index: the chord is taken at n = 1.5, whose mean
// is within 9 % of any index from 1.2 to 2.4 (a unit distance, 1, would be short of all of them).
#include "lib/mx_closure_type.glsl"

#define MX_MEDIUM_IOR 1.5

float mx_medium_path(ClosureData closureData)
{
    float NdotV = clamp(dot(closureData.N, closureData.V), 0.0, 1.0);
    float sinThetaT2 = (1.0 - NdotV * NdotV) / (MX_MEDIUM_IOR * MX_MEDIUM_IOR);
    return 2.0 * sqrt(1.0 - sinThetaT2);
}

// <absorption_vdf>: a purely absorbing medium.
void mx_absorption_vdf(ClosureData closureData, vec3 absorption, inout VDF result)
{
    if (closureData.closureType == CLOSURE_TYPE_TRANSMISSION)
    {
        result.response = vec3(0.0);
        result.throughput = exp(-absorption * mx_medium_path(closureData));
    }
}

// <anisotropic_vdf>: absorption and Henyey-Greenstein scattering; scattering is not rendered by the
// hardware targets, so only absorption filters the light (as in MaterialX's GLSL).
void mx_anisotropic_vdf(ClosureData closureData, vec3 absorption, vec3 scattering, float anisotropy, inout VDF result)
{
    mx_absorption_vdf(closureData, absorption, result);
}
