#include "lib/mx_triplanar.glsl"
#pragma shadergen feature CUBIC_FILTER unless filtertype != cubic

// <triplanarprojection> vector4: see lib/mx_triplanar.glsl.
void mx_triplanarprojection_vector4(sampler2D filex, sampler2D filey, sampler2D filez, int layerx, int layery, int layerz, vec4 dflt, vec3 position, vec3 normal, int upaxis, float blend, int filtertype, int framerange, int frameoffset, int frameendaction, out vec4 result)
{
    result = mx_triplanar_fetch(filex, filey, filez, dflt, position, normal, upaxis, blend, filtertype);
}
