// <layer>: vertical layering. The base is lit by what the top layer lets through.
#include "lib/mx_closure_type.glsl"

void mx_layer_bsdf(ClosureData closureData, BSDF top, BSDF base, out BSDF result)
{
    result.response = top.response + base.response * top.throughput;
    result.throughput = top.throughput * base.throughput;
#ifdef MX_FEATURE_TRANSMISSION
    // What a transmitting top lets through enters the base, so what is seen through the layers is
    // the base's view through the top, not the top's own view through itself.
    if (closureData.closureType == CLOSURE_TYPE_TRANSMISSION)
        result.response = base.response * top.throughput;
#endif
}

// A BSDF over a medium: the medium filters what the top layer scatters and lets through.
void mx_layer_vdf(ClosureData closureData, BSDF top, VDF base, out BSDF result)
{
    result.response = top.response * base.throughput;
    result.throughput = top.throughput * base.throughput;
}
