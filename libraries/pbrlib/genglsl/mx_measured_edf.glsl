// <measured_edf>: emission shaped by a measured profile. The hardware targets read the profile
// from the texture bound to `file` as a table over the angle from the normal: u = angle / 180
// degrees, along the middle row, red channel, relative to the radiance along the normal (1 there).
// A file the renderer cannot bind as an image therefore reads as its fallback texture.
#include "lib/mx_closure_type.glsl"
#include "lib/mx_pbr_common.glsl"

void mx_measured_edf(ClosureData closureData, vec3 color, vec3 N, sampler2D file, inout EDF result)
{
    if (closureData.closureType != CLOSURE_TYPE_EMISSION)
        return;
    vec3 V = closureData.V;
    float angle = acos(clamp(dot(mx_facing_normal(N, V), V), -1.0, 1.0));
    float profile = textureLod(file, vec2(angle * MX_INV_PI, 0.5), 0.0).r;
    result = color * profile;
}
