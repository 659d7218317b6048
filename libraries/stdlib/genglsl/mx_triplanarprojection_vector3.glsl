#include "lib/mx_triplanar.glsl"
#pragma shadergen feature CUBIC_FILTER unless filtertype != cubic

// <triplanarprojection> vector3: see lib/mx_triplanar.glsl.
void mx_triplanarprojection_vector3(sampler2D filex, sampler2D filey, sampler2D filez, int layerx, int layery, int layerz, vec3 dflt, vec3 position, vec3 normal, int upaxis, float blend, int filtertype, int framerange, int frameoffset, int frameendaction, out vec3 result)
{
    result = mx_triplanar_fetch(filex, filey, filez, vec4(dflt, 0.0), position, normal, upaxis, blend, filtertype).rgb;
}
