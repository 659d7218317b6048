#!/usr/bin/env python3
"""Directional-albedo tables of the PBR library, by numerical integration (issue 10).

The directional albedo E(mu) of a BRDF is the fraction of light arriving from a direction with
cosine mu that it reflects: E(mu) = integral over the hemisphere of f(V, L) cos(L) dL. The shaders
need it for multiple-scattering compensation (Kulla & Conty 2017, Turquin 2019: a single-scattering
microfacet lobe loses 1 - E, which is given back), for layering (what a top layer does not reflect
reaches the base) and for lighting diffuse lobes by an irradiance map. Every table here is computed
by this script from the models' own formulas and written as a GLSL include:

  GGX (Walter et al. 2007; height-correlated Smith masking-shadowing, Heitz 2014), isotropic alpha:
      the Schlick scale and bias (A, B), E = F0 A + F90 B, integrated through visible normals
      (Heitz 2014's estimator: weight G2 / G1 per sampled normal).
  GGX dielectric reflection with the exact Fresnel factor, relative index eta in [1, 3] (entering)
      and [1/3, 1] (leaving the denser side, total internal reflection included).
  Oren-Nayar 1994 (qualitative model), Burley 2012 diffuse, and the microfiber sheen (Estevez &
      Kulla 2017's distribution over the smooth denominator of Ashikhmin & Premoze 2007), all three
      integrated over a cosine-distributed stratified grid of light directions.

Tables are sampled on regular grids in sqrt(mu) (and sqrt(alpha) for GGX), nodes at both ends, so
that nodes crowd where the albedos change fastest (grazing views, near-mirror lobes), and read back
with bilinear (trilinear) interpolation by the generated lookup functions.

    python3 tools/fit_albedo.py            # rewrites libraries/pbrlib/genglsl/lib/mx_albedo_*.glsl
    python3 tools/fit_albedo.py --check    # only prints the largest interpolation errors
"""
import argparse
import os
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIB = os.path.join(ROOT, "libraries", "pbrlib", "genglsl", "lib")

MU_NODES = 16        # view cosines 0..1 (0 evaluated at MU_FLOOR)
ROUGHNESS_NODES = 16
ETA_NODES = 8        # dielectric: normal reflectance F0 of eta in 0..F0(3) = 0.25, eta and its inverse
DIELECTRIC_MU_NODES = 16
DIELECTRIC_ALPHA_NODES = 8
MU_FLOOR = 1.0e-3    # the shaders clamp cosines away from 0 too
ALPHA_FLOOR = 1.0e-4
STRATA = 96          # stratified samples per axis of every integral (STRATA^2 per table entry)


def nodes(count: int) -> np.ndarray:
    return np.linspace(0.0, 1.0, count)


def squared_nodes(count: int) -> np.ndarray:
    """Parameter values whose square roots are evenly spaced: the shaders look up sqrt(value)."""
    return nodes(count) ** 2


def stratified(strata: int = STRATA) -> tuple[np.ndarray, np.ndarray]:
    """Cell centres of a strata x strata grid on the unit square (deterministic quadrature)."""
    u = (np.arange(strata) + 0.5) / strata
    u1, u2 = np.meshgrid(u, u, indexing="ij")
    return u1.ravel(), u2.ravel()


def view(mu: float) -> np.ndarray:
    mu = max(mu, MU_FLOOR)
    return np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])


# -- GGX ------------------------------------------------------------------------------------------

def ggx_lambda(cos_theta: np.ndarray, alpha: float) -> np.ndarray:
    """Smith's Lambda for GGX (Heitz 2014, eq. 72)."""
    c2 = np.clip(cos_theta * cos_theta, 1e-12, 1.0)
    return 0.5 * (np.sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2) - 1.0)


def ggx_visible_normals(V: np.ndarray, alpha: float, u1: np.ndarray, u2: np.ndarray) -> np.ndarray:
    """Normals distributed as GGX's visible normals for view V (Heitz 2018's stretch, sampled on
    the spherical cap of Dupuy & Benyoub 2023), shape (n, 3)."""
    Vh = np.array([V[0] * alpha, V[1] * alpha, V[2]])
    Vh /= np.linalg.norm(Vh)
    phi = 2.0 * np.pi * u1
    z = (1.0 - u2) * (1.0 + Vh[2]) - Vh[2]
    r = np.sqrt(np.clip(1.0 - z * z, 0.0, 1.0))
    Hh = np.stack([r * np.cos(phi), r * np.sin(phi), z], -1) + Vh
    H = np.stack([Hh[:, 0] * alpha, Hh[:, 1] * alpha, np.maximum(Hh[:, 2], 0.0)], -1)
    return H / np.linalg.norm(H, axis=1, keepdims=True)


def fresnel_dielectric(cos_i: np.ndarray, eta: float) -> np.ndarray:
    """Unpolarised reflectance at relative index eta (transmitted / incident), 1 under TIR."""
    g2 = eta * eta - 1.0 + cos_i * cos_i
    g = np.sqrt(np.maximum(g2, 0.0))
    s = (g - cos_i) / (g + cos_i)
    p = (cos_i * (g + cos_i) - 1.0) / (cos_i * (g - cos_i) + 1.0)
    return np.where(g2 > 0.0, 0.5 * s * s * (1.0 + p * p), 1.0)


def ggx_reflection_weights(mu: float, alpha: float, samples) -> tuple[np.ndarray, np.ndarray]:
    """(G2 / G1 per sampled visible normal, cosine between V and that normal): the per-sample
    reflected energy of the lobe with F = 1 (0 where the reflection goes below the horizon)."""
    alpha = max(alpha, ALPHA_FLOOR)
    V = view(mu)
    H = ggx_visible_normals(V, alpha, *samples)
    VdotH = np.clip(H @ V, 0.0, 1.0)
    L = 2.0 * VdotH[:, None] * H - V
    lambda_v = ggx_lambda(np.array(V[2]), alpha)
    weight = (1.0 + lambda_v) / (1.0 + lambda_v + ggx_lambda(L[:, 2], alpha))
    return np.where(L[:, 2] > 0.0, weight, 0.0), VdotH


def ggx_schlick_albedo(mu: float, alpha: float, samples) -> tuple[float, float]:
    """(A, B) with E = F0 A + F90 B for Schlick's Fresnel between F0 and F90."""
    weight, VdotH = ggx_reflection_weights(mu, alpha, samples)
    grazing = (1.0 - VdotH) ** 5
    return float(np.mean(weight * (1.0 - grazing))), float(np.mean(weight * grazing))


def ggx_dielectric_albedo(mu: float, alpha: float, eta: float, samples) -> tuple[float, float]:
    """(reflection, transmission) single-scattering albedo of a GGX dielectric interface of
    relative index eta: refraction through each visible normal weighted by G2 / G1 (Walter et al.
    2007's BTDF sampled as in Heitz 2014)."""
    alpha = max(alpha, ALPHA_FLOOR)
    weight, VdotH = ggx_reflection_weights(mu, alpha, samples)
    F = fresnel_dielectric(VdotH, eta)
    V = view(mu)
    H = ggx_visible_normals(V, alpha, *samples)
    cos_t2 = 1.0 - (1.0 - VdotH * VdotH) / (eta * eta)
    cos_t = np.sqrt(np.maximum(cos_t2, 0.0))
    T = (VdotH / eta - cos_t)[:, None] * H - V / eta  # refracted direction, below the surface
    lambda_v = ggx_lambda(np.array(V[2]), alpha)
    t_weight = (1.0 + lambda_v) / (1.0 + lambda_v + ggx_lambda(T[:, 2], alpha))
    transmitted = np.where((cos_t2 > 0.0) & (T[:, 2] < 0.0), (1.0 - F) * t_weight, 0.0)
    return float(np.mean(weight * F)), float(np.mean(transmitted))


# -- Cosine-weighted quadrature for the non-microfacet models -------------------------------------

def cosine_directions(samples) -> np.ndarray:
    """Cosine-distributed unit directions about +z from the unit square (Malley's method)."""
    u1, u2 = samples
    r, phi = np.sqrt(u1), 2.0 * np.pi * u2
    return np.stack([r * np.cos(phi), r * np.sin(phi), np.sqrt(np.maximum(1.0 - u1, 0.0))], -1)


def cosine_albedo(brdf_over_lambert, mu: float, samples) -> float:
    """E(mu) of a BRDF given relative to Lambert (f pi): the mean of f pi over cosine samples."""
    L = cosine_directions(samples)
    return float(np.mean(brdf_over_lambert(view(mu), L)))


def oren_nayar(sigma: float):
    """Oren & Nayar 1994, the qualitative model (their eq. 30) relative to Lambert."""
    s2 = sigma * sigma
    A = 1.0 - 0.5 * s2 / (s2 + 0.33)
    B = 0.45 * s2 / (s2 + 0.09)

    def f(V, L):
        cos_phi_term = L @ V - L[:, 2] * V[2]  # sin(theta_i) sin(theta_o) cos(phi difference)
        return A + B * np.maximum(cos_phi_term, 0.0) / np.maximum(np.maximum(L[:, 2], V[2]), 1e-6)
    return f


def burley(roughness: float):
    """Burley 2012's diffuse, relative to Lambert."""
    def f(V, L):
        H = L + V
        H /= np.linalg.norm(H, axis=1, keepdims=True)
        F90 = 0.5 + 2.0 * roughness * np.sum(L * H, axis=1) ** 2
        towards = lambda c: 1.0 + (F90 - 1.0) * (1.0 - c) ** 5
        return towards(L[:, 2]) * towards(V[2])
    return f


def sheen(roughness: float):
    """Microfiber sheen relative to Lambert: Estevez & Kulla 2017's distribution
    D = (2 + 1/r) sin(theta_h)^(1/r) / (2 pi), over Ashikhmin & Premoze 2007's denominator
    4 (NdotL + NdotV - NdotL NdotV) in place of masking."""
    k = 1.0 / max(roughness, 0.005)  # the shaders' floor too

    def f(V, L):
        H = L + V
        H /= np.linalg.norm(H, axis=1, keepdims=True)
        sin2 = np.clip(1.0 - H[:, 2] ** 2, 0.0, 1.0)
        D = (2.0 + k) * sin2 ** (0.5 * k) / (2.0 * np.pi)
        return np.pi * D / (4.0 * (L[:, 2] + V[2] - L[:, 2] * V[2]))
    return f


# -- Tables ---------------------------------------------------------------------------------------

def table_ggx(samples) -> np.ndarray:
    """(roughness alpha, mu, 2): Schlick scale and bias."""
    return np.array([[ggx_schlick_albedo(mu, a, samples) for mu in squared_nodes(MU_NODES)]
                     for a in squared_nodes(ROUGHNESS_NODES)])


def eta_of(t: float, leaving: bool) -> float:
    """The index of slab coordinate t: slabs are evenly spaced in normal reflectance
    F0 = ((eta - 1) / (eta + 1))^2 from 0 to 0.25 (eta 3), in which the albedo is nearly linear
    (Schlick's F0 A + B), so interpolating between slabs stays accurate."""
    r = np.sqrt(0.25 * t)
    eta = (1.0 + r) / (1.0 - r)
    return 1.0 / eta if leaving else eta


def table_dielectric(samples, leaving: bool) -> np.ndarray:
    """(eta node, alpha, mu): reflection albedo."""
    return np.array([[[ggx_dielectric_albedo(mu, a, eta_of(t, leaving), samples)[0]
                       for mu in squared_nodes(DIELECTRIC_MU_NODES)]
                      for a in squared_nodes(DIELECTRIC_ALPHA_NODES)] for t in nodes(ETA_NODES)])


def table_cosine(model, samples) -> tuple[np.ndarray, np.ndarray]:
    """(roughness, mu) albedo of a model given relative to Lambert, and the albedo of the same model
    renormalised as f / max(1, E(mu_l), E(mu_v)): symmetric in the two directions (so still
    reciprocal) and never reflecting more than arrives, since E'(mu_v) <= E(mu_v) / max(1, E(mu_v))."""
    mus = squared_nodes(MU_NODES)
    L = cosine_directions(samples)
    plain, renormalised = [], []
    for r in nodes(ROUGHNESS_NODES):
        f = model(r)
        row = np.array([np.mean(f(view(mu), L)) for mu in mus])
        E_light = np.interp(np.sqrt(L[:, 2]), np.sqrt(mus), row)  # what the shader's lookup reads at this row
        scaled = [np.mean(f(view(mu), L) / np.maximum(np.maximum(E_light, E_view), 1.0)) for mu, E_view in zip(mus, row)]
        plain.append(row)
        renormalised.append(scaled)
    return np.array(plain), np.array(renormalised)


# -- GLSL -----------------------------------------------------------------------------------------

def glsl_array(name: str, values: np.ndarray, comment: str) -> str:
    flat = values.ravel()
    rows = [", ".join(f"{v:.6f}" for v in flat[i:i + 8]) for i in range(0, len(flat), 8)]
    body = ",\n    ".join(rows)
    return f"// {comment}\nconst float {name}[{len(flat)}] = float[{len(flat)}](\n    {body});\n"


HEADER = """// Generated by tools/fit_albedo.py from numerical integration of the models' formulas; do not
// edit: change the script and run it again. {what}
#include "mx_albedo_lookup.glsl"
"""


def lookup_2d(function: str, table: str, rows: int, columns: int, doc: str, components: int = 1,
              squared_roughness: bool = False) -> str:
    """A bilinear reader of a (rows, columns[, components]) table, rows along roughness (or its
    square root), columns along sqrt(mu)."""
    result = "float" if components == 1 else "vec2"
    roughness_coordinate = "sqrt(max(roughness, 0.0))" if squared_roughness else "roughness"

    def fetch(di: int, dj: int) -> str:
        index = f"mx_albedo_index(i + ivec2({di}, {dj}), {columns})"
        if components == 1:
            return f"{table}[{index}]"
        return f"vec2({table}[2 * {index}], {table}[2 * {index} + 1])"
    return f"""
// {doc}
{result} {function}(float mu, float roughness)
{{
    vec4 c = mx_albedo_cell(vec2(sqrt(max(mu, 0.0)), {roughness_coordinate}), vec2({columns}.0, {rows}.0));
    ivec2 i = ivec2(c.xy);
    return mix(mix({fetch(0, 0)}, {fetch(1, 0)}, c.z),
               mix({fetch(0, 1)}, {fetch(1, 1)}, c.z), c.w);
}}
"""


def write(path: str, text: str) -> None:
    with open(path, "w") as f:
        f.write(text)
    print(f"wrote {os.path.relpath(path, ROOT)}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--strata", type=int, default=STRATA)
    args = parser.parse_args()
    samples = stratified(args.strata)

    ggx = table_ggx(samples)
    write(os.path.join(LIB, "mx_albedo_ggx.glsl"),
          HEADER.format(what="GGX directional albedo with Schlick's Fresnel.") + "\n" +
          glsl_array("MX_ALBEDO_GGX_SCHLICK", ggx,
                     f"(A, B) at alpha = (row / {ROUGHNESS_NODES - 1})^2, mu = (column / {MU_NODES - 1})^2 (mu 0 evaluated at "
                     f"{MU_FLOOR}); {args.strata}^2 visible normals each") +
          lookup_2d("mx_ggx_albedo_schlick_scale_bias", "MX_ALBEDO_GGX_SCHLICK", ROUGHNESS_NODES, MU_NODES,
                    "Albedo = F0 A + F90 B of the GGX lobe at view cosine mu and isotropic alpha.", components=2,
                    squared_roughness=True))

    entering, leaving = table_dielectric(samples, False), table_dielectric(samples, True)
    write(os.path.join(LIB, "mx_albedo_dielectric.glsl"),
          HEADER.format(what="GGX dielectric reflection albedo.") + "\n" +
          glsl_array("MX_ALBEDO_DIELECTRIC_ENTERING", entering,
                     f"[F0 of eta = t / 4, t = slab / {ETA_NODES - 1}][alpha = (row / {DIELECTRIC_ALPHA_NODES - 1})^2]"
                     f"[mu = (column / {DIELECTRIC_MU_NODES - 1})^2]") + "\n" +
          glsl_array("MX_ALBEDO_DIELECTRIC_LEAVING", leaving, "the same for 1 / eta: from the dense side") +
          dielectric_lookup())

    for name, model, what in (("oren_nayar", oren_nayar, "Oren-Nayar 1994 (qualitative model), roughness sigma"),
                              ("burley", burley, "Burley 2012 diffuse, roughness"),
                              ("sheen", sheen, "microfiber sheen (Estevez & Kulla 2017 distribution), roughness r")):
        plain, renormalised = table_cosine(model, samples)
        text = HEADER.format(what=f"Directional albedo of {what}.")
        for suffix, table, doc in (("", plain, "the model as published"),
                                   ("_renormalised", renormalised, "the model divided by max(1, E(mu_l), E(mu_v))")):
            array = f"MX_ALBEDO_{name.upper()}{suffix.upper()}"
            text += "\n" + glsl_array(array, table, f"{doc}, at roughness = row / {ROUGHNESS_NODES - 1}, mu = (column / "
                                                     f"{MU_NODES - 1})^2; {args.strata}^2 cosine-distributed directions each")
            text += lookup_2d(f"mx_{name}_albedo{suffix}", array, ROUGHNESS_NODES, MU_NODES,
                              f"Directional albedo of {doc}, at view cosine mu.")
        write(os.path.join(LIB, f"mx_albedo_{name}.glsl"), text)
        print(f"  {name}: albedo {plain.min():.4f} .. {plain.max():.4f}, renormalised "
              f"{renormalised.min():.4f} .. {renormalised.max():.4f}")
    return 0


def dielectric_lookup() -> str:
    rows, columns, slabs = DIELECTRIC_ALPHA_NODES, DIELECTRIC_MU_NODES, ETA_NODES
    def fetch(table, di, dj, slab):
        return f"{table}[{slab} * {rows * columns} + mx_albedo_index(i + ivec2({di}, {dj}), {columns})]"
    def bilinear(table, slab):
        return (f"mix(mix({fetch(table, 0, 0, slab)}, {fetch(table, 1, 0, slab)}, c.z),\n"
                f"               mix({fetch(table, 0, 1, slab)}, {fetch(table, 1, 1, slab)}, c.z), c.w)")
    def reader(table):
        return f"""
float {table.lower()}(vec4 c, ivec2 i, int slab)
{{
    return {bilinear(table, 'slab')};
}}
"""
    return reader("MX_ALBEDO_DIELECTRIC_ENTERING") + reader("MX_ALBEDO_DIELECTRIC_LEAVING") + f"""
// Reflection albedo of a GGX dielectric interface at view cosine mu, isotropic alpha and relative
// index eta (transmitted side over incident side), eta clamped to [1/3, 3]. The table of the dense
// side is read only in shaders where some dielectric's index may be below 1 (shadergen/features.py).
float mx_dielectric_albedo(float mu, float alpha, float eta)
{{
    bool leaving = eta < 1.0;
    float above = leaving ? 1.0 / max(eta, 1.0e-6) : eta;
    float r = (above - 1.0) / (above + 1.0);
    float t = clamp(4.0 * r * r, 0.0, 1.0) * {slabs - 1}.0;  // slabs evenly spaced in F0
    int slab = min(int(t), {slabs - 2});
    vec4 c = mx_albedo_cell(sqrt(max(vec2(mu, alpha), 0.0)), vec2({columns}.0, {rows}.0));
    ivec2 i = ivec2(c.xy);
#ifdef MX_FEATURE_DIELECTRIC_LEAVING
    if (leaving)
        return mix(mx_albedo_dielectric_leaving(c, i, slab), mx_albedo_dielectric_leaving(c, i, slab + 1), t - float(slab));
#endif
    return mix(mx_albedo_dielectric_entering(c, i, slab), mx_albedo_dielectric_entering(c, i, slab + 1), t - float(slab));
}}
"""


if __name__ == "__main__":
    sys.exit(main())
