// Constants and small helpers shared by the PBR library.

const float MX_PI = 3.1415926535897932;
const float MX_INV_PI = 1.0 / MX_PI;
const float MX_EPS = 1.0e-8;  // floor for cosines and weights, as in MaterialX's hardware shading

float mx_sqr(float x) { return x * x; }
vec2 mx_sqr(vec2 x) { return x * x; }
vec3 mx_sqr(vec3 x) { return x * x; }

// x^y for x >= 0 and any y: GLSL leaves pow(0, y <= 0) undefined; here 0^y is 1 for y <= 0.
float mx_power(float x, float y)
{
    return (y <= 0.0) ? 1.0 : pow(max(x, 0.0), y);
}

// x^5 and x^6 by multiplication (pow() would round differently).
float mx_pow_5(float x)
{
    float x2 = x * x;
    return x2 * x2 * x;
}

float mx_pow_6(float x)
{
    float x2 = x * x;
    return x2 * x2 * x2;
}

// Largest index of refraction (real or imaginary part) a lobe takes: far above any material's
// (metals' extinction stays below ~10), low enough that its fourth power is a finite float.
const float MX_MAX_IOR = 1000.0;

// x clamped to [lo, hi], NaN taken as lo. A lobe's parameters may be computed by the graph (a
// division by zero, the log of a negative): each lobe passes them through this once, so they
// arrive finite and in range. GLSL leaves clamp() of a NaN undefined, hence the test.
float mx_clamp_finite(float x, float lo, float hi)
{
    return isnan(x) ? lo : clamp(x, lo, hi);
}

vec2 mx_clamp_finite(vec2 x, float lo, float hi)
{
    return vec2(mx_clamp_finite(x.x, lo, hi), mx_clamp_finite(x.y, lo, hi));
}

vec3 mx_clamp_finite(vec3 x, float lo, float hi)
{
    return vec3(mx_clamp_finite(x.x, lo, hi), mx_clamp_finite(x.y, lo, hi), mx_clamp_finite(x.z, lo, hi));
}

// The normal flipped, where needed, to the side of the surface that `V` sees.
vec3 mx_facing_normal(vec3 N, vec3 V)
{
    return (dot(N, V) < 0.0) ? -N : N;
}

// Any orthonormal frame around the unit vector N, columns (X, Y, N) (Duff et al. 2017).
mat3 mx_frame_from_normal(vec3 N)
{
    float s = (N.z < 0.0) ? -1.0 : 1.0;
    float a = -1.0 / (s + N.z);
    float b = N.x * N.y * a;
    return mat3(vec3(1.0 + s * N.x * N.x * a, s * b, -s * N.x),
                vec3(b, s + N.y * N.y * a, -N.y),
                N);
}

// A lobe's weight that scatters nothing: zero, negative, or NaN (a NaN computed in the graph, which
// compares false with everything, is absorbed rather than spread over the image).
bool mx_weight_is_zero(float weight)
{
    return isnan(weight) || weight < MX_EPS;
}

// The normal a closure shades with: N when it is a usable direction, else the interpolated
// surface normal (a normal map whose perturbation cancels to zero, or a NaN from the graph).
vec3 mx_usable_normal(vec3 N, vec3 surfaceNormal)
{
    float len2 = dot(N, N);
    return (isnan(len2) || isinf(len2) || len2 < MX_EPS) ? surfaceNormal : N * inversesqrt(len2);
}

// The normal a closure shades with, on the side of the surface that V sees.
vec3 mx_shading_normal(vec3 N, vec3 surfaceNormal, vec3 V)
{
    return mx_facing_normal(mx_usable_normal(N, surfaceNormal), V);
}

// Columns (X, Y, N): `X` made orthogonal to the unit normal `N`, then Y = N x X; any frame about N
// when X is zero or along N.
mat3 mx_tangent_frame(vec3 N, vec3 X)
{
    vec3 T = X - N * dot(X, N);
    float len2 = dot(T, T);
    if (isnan(len2) || len2 < MX_EPS)
        return mx_frame_from_normal(N);
    T *= inversesqrt(len2);
    return mat3(T, cross(N, T), N);
}

// Point `i` of a `count`-point spherical Fibonacci set in [0, 1)^2: a stratified first coordinate
// and the golden-ratio sequence as the second. Every sampled integral of the library uses it, so
// the sample pattern (and the image) matches the reference renderer's.
vec2 mx_fibonacci_point(int i, int count)
{
    const float GOLDEN_RATIO = 1.6180339887498948;
    return vec2((float(i) + 0.5) / float(count), fract((float(i) + 1.0) * GOLDEN_RATIO));
}

// Density of a cosine-distributed direction with cosine `cosTheta` to the pole.
float mx_cosine_pdf(float cosTheta)
{
    return max(cosTheta, 0.0) * MX_INV_PI;
}

// A direction about the pole (0, 0, 1) with density mx_cosine_pdf, from a point of the unit square.
vec3 mx_cosine_sample(vec2 u)
{
    float sinTheta = sqrt(u.x);
    float phi = 2.0 * MX_PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
}
