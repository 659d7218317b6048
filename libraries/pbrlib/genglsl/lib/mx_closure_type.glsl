// Closure contexts. The surface node evaluates a BSDF graph once per context and every closure
// function branches on it: REFLECTION (one light, closureData.L towards it), TRANSMISSION (what is
// seen through the surface along the view direction), INDIRECT (the environment, sampled by the
// closure itself) and EMISSION (EDF graphs). The numbers are the generator's context ids.
#define CLOSURE_TYPE_DEFAULT 0
#define CLOSURE_TYPE_REFLECTION 1
#define CLOSURE_TYPE_TRANSMISSION 2
#define CLOSURE_TYPE_INDIRECT 3
#define CLOSURE_TYPE_EMISSION 4

// The shading point as a closure sees it: the context, the light direction (REFLECTION only), the
// direction to the viewer, the interpolated normal, the world position and the light's visibility.
struct ClosureData
{
    int closureType;
    vec3 L;
    vec3 V;
    vec3 N;
    vec3 P;
    float occlusion;
};
