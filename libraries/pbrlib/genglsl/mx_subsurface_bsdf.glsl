// <subsurface_bsdf>: subsurface scattering approximated at the shading point, with Burley's
// diffusion profile wrapped around the local curvature; the environment lights it as diffuse.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_diffuse.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_subsurface_bsdf(ClosureData closureData, float weight, vec3 color, vec3 radius, float anisotropy, vec3 N,
                        inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (weight < MX_EPS)
        return;

    N = mx_facing_normal(N, closureData.V);
    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        vec3 L = closureData.L;
        vec3 scattered = mx_subsurface_scatter(N, L, closureData.P, color, radius);
        // Occlusion darkens only the part of the light that arrives directly.
        float NdotL = clamp(dot(N, L), MX_EPS, 1.0);
        float visible = 1.0 - NdotL * (1.0 - closureData.occlusion);
        bsdf.response = scattered * (visible * weight);
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(N) * color * weight;
    }
}
