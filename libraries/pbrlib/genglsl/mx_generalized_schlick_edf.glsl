// <generalized_schlick_edf>: the base EDF weighted by a Schlick curve over the view angle, color0
// along the normal and color90 at grazing angles.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_fresnel.glsl"

// Largest weight the curve takes: any real use is far below (the coat's transmittance is <= 1).
const float MX_MAX_EDF_WEIGHT = 1.0e6;

void mx_generalized_schlick_edf(ClosureData closureData, vec3 color0, vec3 color90, float exponent, EDF base,
                                inout EDF result)
{
    if (closureData.closureType != CLOSURE_TYPE_EMISSION)
        return;
    vec3 V = closureData.V;
    float NdotV = clamp(dot(mx_facing_normal(closureData.N, V), V), MX_EPS, 1.0);
    // the colours may be computed by the graph (a shading model's coat transmittance): finite, >= 0
    vec3 weight = mx_fresnel_schlick_exp(NdotV, mx_clamp_finite(color0, 0.0, MX_MAX_EDF_WEIGHT),
                                         mx_clamp_finite(color90, 0.0, MX_MAX_EDF_WEIGHT),
                                         mx_clamp_finite(exponent, 0.0, MX_MAX_EDF_WEIGHT));
    result = base * weight;
}
