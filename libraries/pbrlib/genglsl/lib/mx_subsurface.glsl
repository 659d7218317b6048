// Subsurface scattering at the shading point: Christensen & Burley 2015's normalised diffusion
// profile, integrated around a circle of the surface's local radius of curvature so that light
// diffuses past the terminator (the curvature-wrapped diffusion of Penner & Borshukov 2011).
#include "mx_pbr_common.glsl"

// Profile shape s d for surface albedo A (Christensen & Burley 2015, eq. 6: the fit of s to their
// Monte Carlo references when d is the mean free path).
vec3 mx_diffusion_shape(vec3 albedo)
{
    vec3 A = clamp(albedo, 0.0, 1.0);
    return vec3(1.9) - A + 3.5 * mx_sqr(A - vec3(0.8));
}

// The profile R(r) up to the factor A s / (8 pi), which cancels in the normalised wrap below.
vec3 mx_diffusion_profile(float r, vec3 s)
{
    return (exp(-s * r) + exp(-s * r / 3.0)) / max(r, 1.0e-4);
}

// Irradiance (relative to the light's) diffused to a point whose normal makes angle theta with the
// light, on a circle of radius `radius`, for mean free path `mfp`: the profile-weighted average of
// the clamped cosine over the circle, chord distances between points.
vec3 mx_diffusion_wrap(float cosTheta, float radius, vec3 mfp, vec3 albedo)
{
    const int STEPS = 24;
    vec3 s = mx_diffusion_shape(albedo) / max(mfp, vec3(1.0e-3));
    float theta = acos(clamp(cosTheta, -1.0, 1.0));
    vec3 lit = vec3(0.0);
    vec3 total = vec3(0.0);
    for (int i = 0; i < STEPS; i++)
    {
        float x = MX_PI * ((float(i) + 0.5) / float(STEPS) * 2.0 - 1.0);  // angle along the circle
        vec3 w = mx_diffusion_profile(2.0 * radius * abs(sin(0.5 * x)), s);
        lit += w * max(cos(theta + x), 0.0);
        total += w;
    }
    return lit / max(total, vec3(MX_EPS));
}

// Subsurface reflectance towards L, cosine included, with the radius of curvature estimated from
// screen-space derivatives of the normal and the position.
vec3 mx_subsurface_scatter(vec3 N, vec3 L, vec3 P, vec3 albedo, vec3 mfp)
{
    float curvature = length(fwidth(N)) / max(length(fwidth(P)), MX_EPS);
    float radius = 1.0 / max(curvature, 0.01);
    return albedo * mx_diffusion_wrap(dot(N, L), radius, mfp, albedo) * MX_INV_PI;
}
