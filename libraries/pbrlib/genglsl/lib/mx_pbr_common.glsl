// Constants and small helpers shared by the PBR library.

const float MX_PI = 3.1415926535897932;
const float MX_INV_PI = 1.0 / MX_PI;
const float MX_EPS = 1.0e-8;  // floor for cosines and weights, as in MaterialX's hardware shading

float mx_sqr(float x) { return x * x; }
vec2 mx_sqr(vec2 x) { return x * x; }
vec3 mx_sqr(vec3 x) { return x * x; }

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

// The normal flipped, where needed, to the side of the surface that `V` sees.
vec3 mx_facing_normal(vec3 N, vec3 V)
{
    return (dot(N, V) < 0.0) ? -N : N;
}

// Columns (X, Y, N): `X` made orthogonal to the unit normal `N`, then Y = N x X.
mat3 mx_tangent_frame(vec3 N, vec3 X)
{
    vec3 T = normalize(X - N * dot(X, N));
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
