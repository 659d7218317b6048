// <generalized_schlick_edf>: the base EDF weighted by a Schlick curve over the view angle, color0
// along the normal and color90 at grazing angles.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_fresnel.glsl"

void mx_generalized_schlick_edf(ClosureData closureData, vec3 color0, vec3 color90, float exponent, EDF base,
                                inout EDF result)
{
    if (closureData.closureType != CLOSURE_TYPE_EMISSION)
        return;
    vec3 V = closureData.V;
    float NdotV = clamp(dot(mx_facing_normal(closureData.N, V), V), MX_EPS, 1.0);
    result = base * mx_fresnel_schlick_exp(NdotV, color0, color90, exponent);
}
