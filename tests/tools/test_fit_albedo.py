"""The albedo tables the shaders read (written by tools/fit_albedo.py) against a direct numerical
integration of the same BRDFs over the hemisphere of light directions: a different quadrature
(a polar grid instead of visible-normal or cosine sampling) of the models' formulas."""
import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
LIB = ROOT / "libraries" / "pbrlib" / "genglsl" / "lib"


def table(file: str, name: str) -> np.ndarray:
    text = (LIB / file).read_text()
    match = re.search(rf"const float {name}\[(\d+)\] = float\[\d+\]\(([^;]*)\);", text)
    values = np.array([float(v) for v in match[2].replace("\n", " ").split(",")])
    assert len(values) == int(match[1])
    return values


def hemisphere(n: int = 600):
    """Midpoint grid over (cos theta, phi) of the upper hemisphere: directions and solid angles."""
    mu = (np.arange(n) + 0.5) / n
    phi = (np.arange(2 * n) + 0.5) / (2 * n) * 2.0 * np.pi
    m, p = np.meshgrid(mu, phi, indexing="ij")
    s = np.sqrt(1.0 - m * m)
    L = np.stack([s * np.cos(p), s * np.sin(p), m], -1).reshape(-1, 3)
    return L, (1.0 / n) * (np.pi / n)


def view(mu):
    return np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])


def ggx_lambda(c, a):
    return 0.5 * (np.sqrt(1.0 + a * a * (1.0 - c * c) / (c * c)) - 1.0)


def ggx_albedo(mu, alpha, fresnel):
    """E = integral of D G2 F / (4 mu) over light directions (Walter et al. 2007, Heitz 2014)."""
    L, dw = hemisphere()
    V = view(mu)
    H = L + V
    H /= np.linalg.norm(H, axis=1, keepdims=True)
    c = H[:, 2]
    D = alpha ** 2 / (np.pi * (c * c * (alpha ** 2 - 1.0) + 1.0) ** 2)
    G2 = 1.0 / (1.0 + ggx_lambda(mu, alpha) + ggx_lambda(L[:, 2], alpha))
    return float(np.sum(D * G2 * fresnel(H @ V) / (4.0 * mu)) * dw)


def dielectric_fresnel(eta):
    def F(c):
        g2 = eta * eta - 1.0 + c * c
        g = np.sqrt(np.maximum(g2, 0.0))
        s, p = (g - c) / (g + c), (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
        return np.where(g2 > 0.0, 0.5 * s * s * (1.0 + p * p), 1.0)
    return F


# (table row, column): alpha = (row / 15)^2, mu = (column / 15)^2
@pytest.mark.parametrize("row,column", [(6, 4), (8, 12), (10, 8), (15, 3), (15, 15)])
def test_ggx_schlick_table_matches_direct_integration(row, column):
    alpha, mu = (row / 15.0) ** 2, (column / 15.0) ** 2
    entry = table("mx_albedo_ggx.glsl", "MX_ALBEDO_GGX_SCHLICK").reshape(16, 16, 2)[row, column]
    A = ggx_albedo(mu, alpha, lambda c: 1.0 - (1.0 - c) ** 5)
    B = ggx_albedo(mu, alpha, lambda c: (1.0 - c) ** 5)
    assert entry == pytest.approx([A, B], abs=5e-3)


# (slab, row, column): eta of normal reflectance F0 = slab / 28 (or its inverse), alpha = (row / 7)^2,
# mu = (column / 15)^2
@pytest.mark.parametrize("leaving,slab,row,column", [(False, 2, 3, 5), (False, 7, 7, 12), (True, 2, 4, 10), (True, 5, 7, 4)])
def test_dielectric_table_matches_direct_integration(leaving, slab, row, column):
    root = np.sqrt(slab / 28.0)
    eta = (1.0 + root) / (1.0 - root)
    eta = 1.0 / eta if leaving else eta
    name = "MX_ALBEDO_DIELECTRIC_" + ("LEAVING" if leaving else "ENTERING")
    entry = table("mx_albedo_dielectric.glsl", name).reshape(8, 8, 16)[slab, row, column]
    assert entry == pytest.approx(ggx_albedo((column / 15.0) ** 2, (row / 7.0) ** 2, dielectric_fresnel(eta)), abs=5e-3)


@pytest.mark.parametrize("row,column", [(4, 4), (15, 3), (15, 15)])
def test_burley_table_matches_direct_integration(row, column):
    r, mu = row / 15.0, (column / 15.0) ** 2
    L, dw = hemisphere()
    V = view(mu)
    H = L + V
    H /= np.linalg.norm(H, axis=1, keepdims=True)
    F90 = 0.5 + 2.0 * r * np.sum(L * H, axis=1) ** 2
    f = (1.0 + (F90 - 1.0) * (1.0 - L[:, 2]) ** 5) * (1.0 + (F90 - 1.0) * (1.0 - mu) ** 5) / np.pi
    entry = table("mx_albedo_burley.glsl", "MX_ALBEDO_BURLEY").reshape(16, 16)[row, column]
    assert entry == pytest.approx(float(np.sum(f * L[:, 2]) * dw), abs=5e-3)


def test_renormalised_tables_never_exceed_one():
    for file, name in (("mx_albedo_burley.glsl", "MX_ALBEDO_BURLEY_RENORMALISED"),
                       ("mx_albedo_oren_nayar.glsl", "MX_ALBEDO_OREN_NAYAR_RENORMALISED"),
                       ("mx_albedo_sheen.glsl", "MX_ALBEDO_SHEEN_RENORMALISED")):
        assert table(file, name).max() <= 1.0 + 1e-4, name
