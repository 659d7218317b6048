// Shader constructors of the PBR library other than <surface> (which the generator writes).

// <volume>: a volume shader from a medium and its emission: the colour is the emitted and
// in-scattered light, the transparency what the medium lets through.
void mx_volume(VDF vdf, EDF edf, out volumeshader result)
{
    result.color = edf + vdf.response;
    result.transparency = vdf.throughput;
}

// <light>: a light shader from an EDF (evaluated in the EMISSION context) scaled by intensity and
// 2^exposure. The direction towards the light and any falloff with distance belong to the light
// rig's code that calls the light shader; here the direction is left as zero.
void mx_light(EDF edf, float intensity, float exposure, out lightshader result)
{
    result.intensity = edf * (intensity * exp2(exposure));
    result.direction = vec3(0.0);
}
