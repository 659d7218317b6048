// <conical_edf>: emission inside a cone about the normal. Full radiance within inner_angle
// (degrees from the normal), fading smoothly to none at outer_angle; when outer_angle is not larger
// than inner_angle the cone has a hard edge at inner_angle. Like the other EDFs it emits from the
// side of the surface that is seen.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_pbr_common.glsl"

void mx_conical_edf(ClosureData closureData, vec3 color, vec3 N, float inner_angle, float outer_angle, inout EDF result)
{
    if (closureData.closureType != CLOSURE_TYPE_EMISSION)
        return;
    vec3 V = closureData.V;
    float cosView = dot(mx_facing_normal(N, V), V);
    float cosInner = cos(radians(clamp(inner_angle, 0.0, 180.0)));
    float cosOuter = cos(radians(clamp(outer_angle, 0.0, 180.0)));
    float inside = (cosOuter < cosInner) ? smoothstep(cosOuter, cosInner, cosView) : step(cosInner, cosView);
    result = color * inside;
}
