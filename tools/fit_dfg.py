#!/usr/bin/env python3
"""The split-sum DFG table of the prefiltered environment (libraries/pbrlib/genglsl/lib/mx_environment_dfg.glsl).

With the radiance map prefiltered per roughness (shadergen/render/prefilter.py), the GGX reflection
of the environment is split into the prefiltered radiance times the directional albedo of the BRDF,

    E(NdotV, alpha) = integral over L of  F(VdotH) D G2 / (4 NdotV)

(the cosine of L cancels the BRDF's 1 / (4 NdotV NdotL)). F is any of the library's Fresnel models
(dielectric, conductor, Schlick with F82, thin film), so instead of Schlick's scale and bias the
table holds a two-point Gauss quadrature in VdotH of the measure D G2 / (4 NdotV) dL:
E = w1 F(c1) + w2 F(c2), exact when F is a cubic in VdotH, within 1e-3 of the integral for
conductors and 2e-2 for a dielectric of ior 1.5 at grazing angles (Schlick's split is off by 0.1
for a copper-coloured conductor). The nodes and weights come from the measure's moments
m_k = integral of VdotH^k (Golub & Welsch 1969: the roots of the degree-2 orthogonal polynomial).

The moments are computed here by numerical integration: GGX visible normals (Heitz 2018,
"Sampling the GGX Distribution of Visible Normals") drawn on a stratified grid, each weighted by
G2 / G1(V), the Smith height-correlated masking-shadowing (Heitz 2014, "Understanding the
Masking-Shadowing Function", eq. 99) over the masking of V.

The table has TABLE_SIZE x TABLE_SIZE entries: rows sqrt(NdotV) = i / (TABLE_SIZE - 1) (denser at
grazing angles, where the albedo changes fastest), columns roughness = j / (TABLE_SIZE - 1) with
alpha = roughness^2. The shader interpolates it bilinearly.

    .venv/bin/python tools/fit_dfg.py            # rewrites the GLSL file
    .venv/bin/python tools/fit_dfg.py --check    # exits 1 when the file differs from a fresh table
"""
import argparse
import os
import sys

import numpy as np

TABLE_SIZE = 16
GRID = 256            # stratified samples per axis of the visible-normal grid
MIN_NDOTV = 1e-3      # the first row (NdotV = 0) is evaluated here: the integrals' limit
MIN_ALPHA = 1e-4      # the first column (roughness 0) is evaluated here: a near-mirror
GLSL = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                    "libraries", "pbrlib", "genglsl", "lib", "mx_environment_dfg.glsl")


def smith_lambda(cos_theta: np.ndarray, alpha: float) -> np.ndarray:
    """Heitz 2014, eq. 72, for GGX."""
    cos2 = np.clip(cos_theta, 1e-7, 1.0) ** 2
    return 0.5 * (np.sqrt(1.0 + alpha * alpha * (1.0 - cos2) / cos2) - 1.0)


def visible_normals(n_dot_v: float, alpha: float, grid: int) -> tuple[np.ndarray, np.ndarray]:
    """Microfacet normals distributed as GGX's visible normals for V = (sin, 0, cos); and V."""
    view = np.array([np.sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v])
    u1, u2 = np.meshgrid((np.arange(grid) + 0.5) / grid, (np.arange(grid) + 0.5) / grid)
    u1, u2 = u1.ravel(), u2.ravel()
    stretched = np.array([alpha * view[0], 0.0, view[2]])
    stretched /= np.linalg.norm(stretched)
    # Heitz 2018's frame about the stretched view: T1 = normalize(Z x Vh) (here Y), T2 = Vh x T1.
    t1 = np.array([0.0, 1.0, 0.0])
    t2 = np.array([-stretched[2], 0.0, stretched[0]])
    radius, phi = np.sqrt(u1), 2.0 * np.pi * u2
    p1, p2 = radius * np.cos(phi), radius * np.sin(phi)
    s = 0.5 * (1.0 + stretched[2])
    p2 = (1.0 - s) * np.sqrt(1.0 - p1 * p1) + s * p2
    pz = np.sqrt(np.maximum(0.0, 1.0 - p1 * p1 - p2 * p2))
    n = p1[:, None] * t1 + p2[:, None] * t2 + pz[:, None] * stretched
    h = np.stack([alpha * n[:, 0], alpha * n[:, 1], np.maximum(n[:, 2], 1e-7)], 1)
    return h / np.linalg.norm(h, axis=1)[:, None], view


def moments(n_dot_v: float, alpha: float, grid: int = GRID) -> np.ndarray:
    """m_k = integral of VdotH^k D G2 / (4 NdotV) over L, k = 0..3, by visible-normal quadrature."""
    h, view = visible_normals(n_dot_v, alpha, grid)
    v_dot_h = np.clip(h @ view, 0.0, 1.0)
    n_dot_l = (2.0 * v_dot_h[:, None] * h - view)[:, 2]
    lambda_v = smith_lambda(np.array(n_dot_v), alpha)
    weight = np.where(n_dot_l > 0.0, (1.0 + lambda_v) / (1.0 + lambda_v + smith_lambda(n_dot_l, alpha)), 0.0)
    return np.array([np.mean(weight * v_dot_h ** k) for k in range(4)])


def gauss_rule(m: np.ndarray) -> tuple[float, float, float, float]:
    """(c1, c2, w1, w2): the two-point Gauss rule of moments m0..m3, c1 <= c2 in [0, 1]: in units
    of the measure's spread around its mean, a two-point rule with the measure's skewness g has
    nodes (g -+ sqrt(g^2 + 4)) / 2. A measure without spread (a mirror) gets one node, twice."""
    mean = m[1] / m[0]
    variance = m[2] / m[0] - mean * mean
    if variance < 1e-8:
        return mean, mean, m[0] / 2.0, m[0] / 2.0
    spread = np.sqrt(variance)
    skewness = (m[3] / m[0] - 3.0 * mean * variance - mean ** 3) / spread ** 3
    root = np.sqrt(skewness * skewness + 4.0)
    z1, z2 = (skewness - root) / 2.0, (skewness + root) / 2.0
    c1, c2 = np.clip([mean + spread * z1, mean + spread * z2], 0.0, 1.0)
    return float(c1), float(c2), float(m[0] * z2 / (z2 - z1)), float(-m[0] * z1 / (z2 - z1))


def table(size: int = TABLE_SIZE, grid: int = GRID) -> np.ndarray:
    """(size, size, 4): [row sqrt(NdotV), column roughness] -> (c1, c2, w1, w2)."""
    steps = np.arange(size) / (size - 1)
    return np.array([[gauss_rule(moments(max(s * s, MIN_NDOTV), max(r * r, MIN_ALPHA), grid)) for r in steps]
                     for s in steps])


NAMES = ("MX_DFG_C1", "MX_DFG_C2", "MX_DFG_W1", "MX_DFG_W2")


def glsl(values: np.ndarray) -> str:
    size = values.shape[0]

    def array(name: str, channel: int) -> list[str]:
        rows = [", ".join(f"{x:.4f}" for x in values[i, :, channel]) for i in range(size)]
        return [f"const float {name}[{size * size}] = float[](", *(f"    {r}," for r in rows[:-1]),
                f"    {rows[-1]});"]

    def corner(offset: str) -> str:
        return "vec4(" + ", ".join(f"{name}[k{offset}]" for name in NAMES) + ")"

    return "\n".join([
        "// Split-sum DFG table of GGX: the BRDF's directional albedo for any Fresnel F is",
        "// w1 F(c1) + w2 F(c2), a two-point Gauss quadrature in VdotH. Written by tools/fit_dfg.py",
        "// (numerical integration over GGX visible normals, Heitz 2018, with Smith height-correlated",
        "// masking-shadowing, Heitz 2014); do not edit by hand.",
        f"// Rows: sqrt(NdotV) = i / {size - 1}; columns: roughness = sqrt(alpha) = j / {size - 1}.",
        "",
        *(line for channel, name in enumerate(NAMES) for line in array(name, channel)),
        "",
        "// (c1, c2, w1, w2) at NdotV and alpha, interpolated bilinearly.",
        "vec4 mx_environment_dfg_rule(float NdotV, float alpha)",
        "{",
        f"    vec2 p = clamp(vec2(sqrt(NdotV), sqrt(alpha)), 0.0, 1.0) * {float(size - 1):.1f};",
        f"    ivec2 i = min(ivec2(p), ivec2({size - 2}));",
        "    vec2 f = p - vec2(i);",
        f"    int k = i.x * {size} + i.y;",
        f"    vec4 low = mix({corner('')}, {corner(' + 1')}, f.y);",
        f"    vec4 high = mix({corner(f' + {size}')}, {corner(f' + {size + 1}')}, f.y);",
        "    return mix(low, high, f.x);",
        "}",
        "",
    ])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true", help="compare with the file instead of writing it")
    args = parser.parse_args()
    text = glsl(table())
    if args.check:
        with open(GLSL, encoding="utf-8") as f:
            same = f.read() == text
        print(f"{GLSL}: {'up to date' if same else 'differs from a fresh table'}")
        return 0 if same else 1
    with open(GLSL, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {GLSL}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
