// <uniform_edf>: the same radiance in every direction.
#include "lib/mx_closure_type.glsl"

void mx_uniform_edf(ClosureData closureData, vec3 color, inout EDF result)
{
    if (closureData.closureType == CLOSURE_TYPE_EMISSION)
        result = color;
}
