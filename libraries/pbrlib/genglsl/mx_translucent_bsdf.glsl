// <translucent_bsdf>: diffuse transmission, light arriving from behind the surface leaving in
// front of it (Lambert about the reversed normal).
#include "lib/mx_closure_type.glsl"
#include "lib/mx_environment_fis.glsl"

void mx_translucent_bsdf(ClosureData closureData, float weight, vec3 color, vec3 N, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (mx_weight_is_zero(weight))
        return;

    vec3 back = -mx_usable_normal(N, closureData.N);
    if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        bsdf.response = mx_environment_irradiance(back) * max(color, 0.0) * weight;
    }
#ifdef MX_FEATURE_LIGHTS
    else if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        float cosine = clamp(dot(back, closureData.L), 0.0, 1.0);
        bsdf.response = max(color, 0.0) * (weight * cosine * MX_INV_PI);
    }
#endif
}
