// Transmission rendered by refraction: what is seen through the surface is the environment,
// refracted through a solid sphere of the surface's index; scene geometry behind is ignored.
#include "mx_environment_fis.glsl"

vec3 mx_surface_transmission(vec3 N, vec3 V, vec3 X, vec2 alpha, int distribution, FresnelData fd, vec3 tint)
{
    fd.refraction = true;
    // A two-sided interface filters the light twice.
    vec3 through = u_refractionTwoSided ? tint * tint : tint;
    vec3 transmitted;
    return mx_environment_radiance(N, V, X, alpha, distribution, fd, transmitted) * through;
}
