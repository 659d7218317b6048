// Media. The hardware targets model a medium by its transmittance over a unit distance,
// exp(-absorption), answered in the TRANSMISSION context (the only one that looks through a surface).
#include "lib/mx_closure_type.glsl"

// <absorption_vdf>: a purely absorbing medium.
void mx_absorption_vdf(ClosureData closureData, vec3 absorption, inout VDF result)
{
    if (closureData.closureType == CLOSURE_TYPE_TRANSMISSION)
    {
        result.response = vec3(0.0);
        result.throughput = exp(-absorption);
    }
}

// <anisotropic_vdf>: absorption and Henyey-Greenstein scattering; scattering is not rendered by the
// hardware targets, so only absorption filters the light (as in MaterialX's GLSL).
void mx_anisotropic_vdf(ClosureData closureData, vec3 absorption, vec3 scattering, float anisotropy, inout VDF result)
{
    mx_absorption_vdf(closureData, absorption, result);
}
