// <add> of closures.
#include "lib/mx_closure_type.glsl"

// Responses add; so do the lobes' albedos (1 - throughput), hence t1 + t2 - 1, kept >= 0.
void mx_add_bsdf(ClosureData closureData, BSDF in1, BSDF in2, out BSDF result)
{
    result.response = in1.response + in2.response;
    result.throughput = max(in1.throughput + in2.throughput - 1.0, 0.0);
}

void mx_add_edf(ClosureData closureData, EDF in1, EDF in2, out EDF result)
{
    result = in1 + in2;
}

// Two media in the same volume: their extinctions add, so their transmittances multiply.
void mx_add_vdf(ClosureData closureData, VDF in1, VDF in2, out VDF result)
{
    result.response = in1.response + in2.response;
    result.throughput = in1.throughput * in2.throughput;
}
