// <multiply> of a closure by a weight (float or colour).
#include "lib/mx_closure_type.glsl"

// A BSDF's response is scaled by the weight clamped to [0, 1]; what it lets through is unchanged.
void mx_multiply_bsdf_color3(ClosureData closureData, BSDF in1, vec3 in2, out BSDF result)
{
    result.response = in1.response * clamp(in2, 0.0, 1.0);
    result.throughput = in1.throughput;
}

void mx_multiply_bsdf_float(ClosureData closureData, BSDF in1, float in2, out BSDF result)
{
    result.response = in1.response * clamp(in2, 0.0, 1.0);
    result.throughput = in1.throughput;
}

// Emission scales freely.
void mx_multiply_edf_color3(ClosureData closureData, EDF in1, vec3 in2, out EDF result)
{
    result = in1 * in2;
}

void mx_multiply_edf_float(ClosureData closureData, EDF in1, float in2, out EDF result)
{
    result = in1 * in2;
}

// A medium's density scales: its own emission/scattering response scales linearly and its
// transmittance exp(-sigma d) goes to the power of the weight (weights below 0 read as 0; the floor
// keeps pow defined where the medium is opaque).
void mx_multiply_vdf_color3(ClosureData closureData, VDF in1, vec3 in2, out VDF result)
{
    vec3 w = max(in2, 0.0);
    result.response = in1.response * w;
    result.throughput = pow(max(in1.throughput, vec3(1.0e-30)), w);
}

void mx_multiply_vdf_float(ClosureData closureData, VDF in1, float in2, out VDF result)
{
    float w = max(in2, 0.0);
    result.response = in1.response * w;
    result.throughput = pow(max(in1.throughput, vec3(1.0e-30)), vec3(w));
}
