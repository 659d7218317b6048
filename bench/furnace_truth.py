#!/usr/bin/env python3
"""The white furnace judged by a path tracer (issue 26, item 5): each plausible case of the stress
set (bench/stress.py) whose closure OSL 1.13 has, our real-time furnace image against OSL
`testrender`'s furnace image of the same closure with the same parameters.

Both draw the thumbnail's sphere in a constant white environment (radiance 1): ours is the stress
set's record on our GL renderer (fis, --samples), testrender's is a hand-written OSL surface
calling OSL's own MaterialX closure (stdosl.h: oren_nayar_diffuse_bsdf, burley_diffuse_bsdf,
dielectric_bsdf, conductor_bsdf, generalized_schlick_bsdf, sheen_bsdf, translucent_bsdf,
subsurface_bssrdf, layer) with the case's inputs, in tools/ground_truth_scene.py's scene (the same
camera and sphere). Compared over the sphere's pixels (2 pixels inside the silhouette): the mean
of each channel (the furnace value) and the means per band of N.V (where on the sphere they part).

testrender's closures are its own, and not every one is the ideal answer; the cause column says
which of its limitations (read in its shading.cpp) a case meets, and a case with a known exact
answer says it (a lossless closure in a furnace returns 1 whatever its roughness):
  - microfacets are single-scattering GGX (no multiple-scattering energy): rough ones lose light;
    for a white conductor (F = 1) the column `single` gives that loss by an independent quadrature
    of GGX's single-scattering albedo over the sphere's N.V, which testrender should equal;
  - thin films are ignored (thinfilm_* are parsed and never read), and so are media: medium_vdf
    and anisotropic_vdf set a ShadingResult's sigma_t that its integrator (simpleraytracer.cpp)
    never reads; testrender 1.13 cannot judge a thin film's colours or a transmission depth;
  - subsurface_bssrdf is a Lambertian of its albedo;
  - layer() weights the base by 1 - F(N.V) of the top (its own comment: "looses energy");
  - a transmitting microfacet's sample() multiplies a sampled reflection's pdf by the probability
    of transmission (pdf *= probT where the reflection's probability is meant): a white generalized
    Schlick with R and T (F = 1, probT = 0) gets pdf 0, its paths end, and it renders black;
  - its microfacet sample() keeps reflected directions below the horizon (eval() refuses them):
    with more than one bounce they enter the sphere and come out as light a convex reflector
    cannot have. A closure that only reflects is therefore rendered with one bounce (exact on a
    convex sphere); a transmitting one needs many, and meets the leak when rough.
One difference of the models: burley_diffuse_bsdf in testrender is Burley's diffuse as published,
whose albedo exceeds 1 at grazing angles for rough surfaces (a quadrature gives the sphere's mean
1.042 at roughness 1, as testrender does); ours is renormalised to conserve energy.
And one difference of the scenes, not of the closures: testrender's sphere is solid, so light
that a T-only dielectric transmits crosses a second interface, whose reflection is dropped too;
our real-time furnace sees the environment through one interface.
Cases OSL 1.13 cannot express are left out and counted: chiang_hair (no closure), sheen mode
zeltner (one sheen model), generalized Schlick with color82 != 1 (no F82 tint), the shading models
(their graphs need our OSL target's closures).

    .venv/bin/python bench/furnace_truth.py [--size 64] [--samples 64] [--spp 64] [--family dielectric]
        [--table docs/furnace_truth.md]
"""
import argparse
import math
import os
import re
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from typing import NamedTuple

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.join(ROOT, "tools"))

import ground_truth_scene as gts  # noqa: E402
import stress  # noqa: E402

INSET = 2.0
BANDS = (0.0, 0.2, 0.4, 0.6, 0.8, 1.0)  # N.V bands of the sphere's image
AGREE = 0.02  # a furnace value within this of testrender's agrees
GGX_MIN_ALPHA = 1.0e-4  # lib/mx_ggx.glsl's MX_GGX_MIN_ALPHA
ROUGH_ALPHA = 0.1  # from here single scattering loses about 2 % of a white conductor's light or more (the quadrature)
# the testrender limitations (its shading.cpp) a case can meet
SINGLE_SCATTERING = "testrender: single-scattering GGX"
THIN_FILM = "testrender: thin film ignored"
BSSRDF = "testrender: BSSRDF as a Lambertian"
LAYER = "testrender: layer() weights the base by 1 - F(N.V)"
TWO_INTERFACES = ("scene: testrender's solid sphere has a second interface (T only: what either reflects is lost); "
                  "ours draws one")
RT_PDF = ("testrender: a reflection sampled from a transmitting microfacet gets the transmission's probability as "
          "its pdf (0 when F = 1)")
BURLEY = "model: Burley 2012 as published gains light at grazing (testrender); ours is renormalised"
BELOW_HORIZON = "testrender: rough reflections sampled below the horizon continue into the sphere"
DEFS = os.path.join(ROOT, "libraries", "pbrlib", "pbrlib_defs.mtlx")


def nodedef_defaults() -> dict:
    """node category -> {input: (type, value string)} of pbrlib's nodedefs (the standard's defaults)."""
    out = {}
    for nd in ET.parse(DEFS).getroot().iter("nodedef"):
        out.setdefault(nd.get("node"), {i.get("name"): (i.get("type"), i.get("value")) for i in nd.iter("input")})
    return out


def parse_value(type_name: str, text: str | None):
    if text is None:
        return None
    if type_name == "boolean":
        return text.strip() == "true"
    if type_name == "string":
        return text.strip()
    numbers = [float(v) for v in text.split(",")]
    return numbers[0] if type_name in ("float", "integer") else tuple(numbers)


def osl_number(x: float) -> str:
    return repr(float(x))


def osl_color(c) -> str:
    c = (c,) * 3 if isinstance(c, float) else c
    return f"color({', '.join(osl_number(v) for v in c)})"


class Untranslatable(Exception):
    """A case whose closure or parameter OSL 1.13's MaterialX closures do not have."""


class Translation(NamedTuple):
    expression: str          # the OSL closure
    limitations: list[str]   # the testrender limitations it meets (the module's docstring)
    transmits: bool          # light enters the sphere


def osl_closure(case: stress.Case, defaults: dict | None = None) -> Translation:
    """The OSL closure of the case's BSDF named "bsdf" (its nodes: stress's XML)."""
    defaults = defaults or nodedef_defaults()
    nodes = {e.get("name"): e for e in ET.fromstring(f"<nodes>{case.xml}</nodes>")}
    if "bsdf" not in nodes:
        raise Untranslatable(f"{nodes['shader'].tag}: a shading model (needs our OSL target's closures)")
    limits: list[str] = []
    transmits = False

    def limit(text: str):
        if text not in limits:
            limits.append(text)

    def expression(name: str) -> str:
        nonlocal transmits
        element = nodes[name]
        category = element.tag
        if category == "layer":
            inputs = {i.get("name"): i.get("nodename") for i in element.iter("input")}
            limit(LAYER)
            return f"layer({expression(inputs['top'])}, {expression(inputs['base'])})"
        if category not in defaults:
            raise Untranslatable(f"{category}: no pbrlib nodedef")
        v = {k: parse_value(t, text) for k, (t, text) in defaults[category].items()}
        for i in element.iter("input"):
            if i.get("nodename"):
                raise Untranslatable(f"{category}.{i.get('name')}: a connected input")
            v[i.get("name")] = parse_value(i.get("type"), i.get("value"))
        film = ""
        if v.get("thinfilm_thickness"):
            limit(THIN_FILM)
            film = (f', "thinfilm_thickness", {osl_number(v["thinfilm_thickness"])}, '
                    f'"thinfilm_ior", {osl_number(v["thinfilm_ior"])}')
        if isinstance(v.get("roughness"), tuple):
            # ours clamps GGX's alpha to [GGX_MIN_ALPHA, 1] (lib/mx_ggx.glsl); testrender divides by it
            alpha = [min(max(a, GGX_MIN_ALPHA), 1.0) for a in v["roughness"]]
            rough = ", ".join(osl_number(a) for a in alpha)
            if math.sqrt(alpha[0] * alpha[1]) >= ROUGH_ALPHA:
                limit(SINGLE_SCATTERING)
        mode = v.get("scatter_mode", "R")
        tint = v.get("tint", (1.0, 1.0, 1.0))
        reflect, transmit = (osl_color(tint if "R" in mode else 0.0), osl_color(tint if "T" in mode else 0.0))
        transmits |= category == "translucent_bsdf" or "T" in mode
        if mode == "T" and v.get("ior", 1.5) != 1.0:
            limit(TWO_INTERFACES)
        if mode == "RT":
            limit(RT_PDF)
        if category == "oren_nayar_diffuse_bsdf":
            call = (f"oren_nayar_diffuse_bsdf(N, {osl_color(v['color'])}, {osl_number(v['roughness'])}, "
                    f'"energy_compensation", {int(v["energy_compensation"])})')
        elif category == "burley_diffuse_bsdf":
            if v["roughness"] > 0.0:
                limit(BURLEY)
            call = f"burley_diffuse_bsdf(N, {osl_color(v['color'])}, {osl_number(v['roughness'])})"
        elif category == "translucent_bsdf":
            call = f"translucent_bsdf(N, {osl_color(v['color'])})"
        elif category == "subsurface_bsdf":
            limit(BSSRDF)
            call = f"subsurface_bssrdf(N, {osl_color(v['color'])}, 1.0, {osl_color(v['radius'])}, {osl_number(v['anisotropy'])})"
        elif category == "sheen_bsdf":
            if v["mode"] != "conty_kulla":
                raise Untranslatable(f"sheen_bsdf mode {v['mode']}: OSL 1.13 has one sheen model")
            call = f"sheen_bsdf(N, {osl_color(v['color'])}, {osl_number(v['roughness'])})"
        elif category == "dielectric_bsdf":
            call = (f"dielectric_bsdf(N, normalize(dPdu), {reflect}, {transmit}, {rough}, {osl_number(v['ior'])}, "
                    f"\"ggx\"{film})")
        elif category == "conductor_bsdf":
            call = (f"conductor_bsdf(N, normalize(dPdu), {rough}, {osl_color(v['ior'])}, {osl_color(v['extinction'])}, "
                    f"\"ggx\"{film})")
        elif category == "generalized_schlick_bsdf":
            if tuple(v["color82"]) != (1.0, 1.0, 1.0):
                raise Untranslatable("generalized_schlick_bsdf color82 != 1: OSL 1.13 has no F82 tint")
            call = (f"generalized_schlick_bsdf(N, normalize(dPdu), {reflect}, {transmit}, {rough}, "
                    f"{osl_color(v['color0'])}, {osl_color(v['color90'])}, {osl_number(v['exponent'])}, \"ggx\"{film})")
        else:
            raise Untranslatable(f"{category}: no OSL 1.13 closure")
        return call if v.get("weight", 1.0) == 1.0 else f"{osl_number(v['weight'])} * {call}"

    closure = expression("bsdf")
    if transmits and SINGLE_SCATTERING in limits:
        limit(BELOW_HORIZON)
    return Translation(closure, limits, transmits)


def surface_source(name: str, closure: str) -> str:
    return f"surface {name}()\n{{\n    Ci = {closure};\n}}\n"


def sphere_cosines(side: int) -> np.ndarray:
    """N.V at each pixel centre's hit on the unit sphere."""
    return np.clip(-(gts.sphere_normals(side) * gts.camera_rays(side)).sum(-1), 0.0, 1.0)


def ggx_single_scattering_albedo(mu: np.ndarray, alpha: float, n: int = 128) -> np.ndarray:
    """GGX's directional albedo with F = 1 and no multiple scattering, E(mu) = E_m~VNDF[G2 / G1],
    by a stratified n x n quadrature of the visible normals (Heitz 2018, "Sampling the GGX
    Distribution of Visible Normals") and Smith's height-correlated G2: independent of testrender."""
    alpha = max(alpha, 1e-4)
    u1, u2 = np.meshgrid((np.arange(n) + 0.5) / n, (np.arange(n) + 0.5) / n)
    u1, u2 = u1.ravel(), u2.ravel()

    def lam(cos):
        cos = np.clip(cos, 1e-6, 1.0)
        t2 = (1.0 - cos * cos) / (cos * cos)
        return (np.sqrt(1.0 + alpha * alpha * t2) - 1.0) / 2.0

    out = []
    for m in np.atleast_1d(mu):
        m = max(float(m), 1e-4)
        v = np.array([math.sqrt(1.0 - m * m), 0.0, m])
        vh = np.array([alpha * v[0], alpha * v[1], v[2]])
        vh /= np.linalg.norm(vh)
        t1 = np.array([0.0, 1.0, 0.0]) if vh[2] > 0.9999 else np.cross([0.0, 0.0, 1.0], vh) / np.linalg.norm(
            np.cross([0.0, 0.0, 1.0], vh))
        t2 = np.cross(vh, t1)
        r, phi = np.sqrt(u1), 2.0 * np.pi * u2
        p1, p2 = r * np.cos(phi), r * np.sin(phi)
        s = 0.5 * (1.0 + vh[2])
        p2 = (1.0 - s) * np.sqrt(1.0 - p1 * p1) + s * p2
        nh = p1[:, None] * t1 + p2[:, None] * t2 + np.sqrt(np.maximum(0.0, 1.0 - p1 * p1 - p2 * p2))[:, None] * vh
        h = np.stack([alpha * nh[:, 0], alpha * nh[:, 1], np.maximum(1e-6, nh[:, 2])], -1)
        h /= np.linalg.norm(h, axis=-1, keepdims=True)
        l_z = 2.0 * (h @ v) * h[:, 2] - v[2]
        g2_over_g1 = np.where(l_z > 0, (1.0 + lam(m)) / (1.0 + lam(m) + lam(l_z)), 0.0)
        out.append(g2_over_g1.mean())
    return np.asarray(out)


WHITE_CONDUCTOR = re.compile(r'^conductor_bsdf\(N, normalize\(dPdu\), ([^,]+), \1, color\(0\.0, 0\.0, 0\.0\), '
                             r'color\(0\.0, 0\.0, 0\.0\), "ggx"\)$')


def single_scattering_expected(closure: str, side: int, mask: np.ndarray) -> float | None:
    """For an isotropic white conductor (ior and extinction 0: F = 1, no film), the sphere's mean
    furnace value of single-scattering GGX at its roughness; None for any other closure."""
    match = WHITE_CONDUCTOR.match(closure)
    if not match:
        return None
    mu = sphere_cosines(side)[mask]
    grid = np.linspace(0.0, 1.0, 65)
    return float(np.interp(mu, grid, ggx_single_scattering_albedo(grid, float(match.group(1)))).mean())


# CIE 1931 2-degree colour matching functions, Wyman, Sloan & Shirley's multi-lobe fit (JCGT 2013):
# (weight, mean nm, sigma below, sigma above) per lobe, for x, y and z.
CMF_LOBES = (((1.056, 599.8, 37.9, 31.0), (0.362, 442.0, 16.0, 26.7), (-0.065, 501.1, 20.4, 26.2)),
             ((0.821, 568.8, 46.9, 40.5), (0.286, 530.9, 16.3, 31.1)),
             ((1.217, 437.0, 11.8, 36.0), (0.681, 459.0, 26.0, 13.8)))
# CIE XYZ to RGB with an equal-energy white (the CIE 1931 primaries), rows: a flat spectrum is white
XYZ_TO_RGB_E = np.array([[2.3706743, -0.9000405, -0.4706338], [-0.5138850, 1.4253036, 0.0885814],
                         [0.0052982, -0.0146949, 1.0093968]])
WAVELENGTHS = np.arange(360.0, 831.0, 1.0)


def colour_matching() -> np.ndarray:
    """x, y, z at WAVELENGTHS (columns)."""
    lam = WAVELENGTHS[:, None]
    return np.stack([sum(w * np.exp(-0.5 * ((lam[:, 0] - mu) / np.where(lam[:, 0] < mu, s1, s2)) ** 2)
                         for w, mu, s1, s2 in lobes) for lobes in CMF_LOBES], -1)


def spectrum_rgb(spectrum: np.ndarray) -> np.ndarray:
    """A reflectance spectrum (..., WAVELENGTHS) as RGB with an equal-energy white, normalised so
    that reflectance 1 everywhere is (1, 1, 1)."""
    cmf = colour_matching()
    white = XYZ_TO_RGB_E @ cmf.sum(0)
    return (spectrum @ cmf) @ XYZ_TO_RGB_E.T / white


def thin_film_reflectance(cosine: np.ndarray, film_ior: float, film_nm: float, ior: float) -> np.ndarray:
    """Exact reflectance spectrum (..., WAVELENGTHS) of a film of index film_ior and thickness
    film_nm on a dielectric of index `ior`, seen from air at `cosine`: the Airy sum of the film's
    coherent reflections, r = (r12 + r23 e^(i delta)) / (1 + r12 r23 e^(i delta)) with
    delta = 4 pi n2 d cos(theta2) / lambda, |r|^2 averaged over the two polarisations (Born & Wolf,
    Principles of Optics, sect. 7.6)."""
    sin2 = 1.0 - cosine ** 2
    c1 = cosine.astype(complex)
    c2 = np.sqrt(1.0 - sin2 / film_ior ** 2 + 0j)
    c3 = np.sqrt(1.0 - sin2 / ior ** 2 + 0j)
    phase = np.exp(1j * 4.0 * np.pi * film_ior * film_nm * c2[..., None] / WAVELENGTHS)
    out = 0.0
    for a1, a2, a3 in ((1.0, film_ior, ior), (1.0, 1.0 / film_ior, 1.0 / ior)):  # s; p is s with the indices inverted
        r12 = ((a1 * c1 - a2 * c2) / (a1 * c1 + a2 * c2))[..., None]
        r23 = ((a2 * c2 - a3 * c3) / (a2 * c2 + a3 * c3))[..., None]
        out = out + 0.5 * np.abs((r12 + r23 * phase) / (1.0 + r12 * r23 * phase)) ** 2
    return out


def compare(ours: np.ndarray, truth: np.ndarray, side: int) -> dict:
    """Furnace values (per-channel means over the sphere) and the largest difference of the
    per-band means, with the band where it is."""
    mask = gts.sphere_mask(side, INSET)
    mu = sphere_cosines(side)
    ours, truth = np.nan_to_num(ours[..., :3]), np.nan_to_num(truth[..., :3])
    result = {"ours": ours[mask].mean(0), "truth": truth[mask].mean(0)}
    worst, band = 0.0, ""
    for lo, hi in zip(BANDS, BANDS[1:]):
        sel = mask & (mu >= lo) & (mu < hi if hi < 1.0 else mu <= hi)
        if sel.sum() < 4:
            continue
        d = float(np.abs(ours[sel].mean(0) - truth[sel].mean(0)).max())
        if d > worst:
            worst, band = d, f"{lo:g}-{hi:g}"
    result.update(delta=float(np.abs(result["ours"] - result["truth"]).max()), band_delta=worst, band=band)
    return result


FILMS_NM = (300.0, 500.0, 800.0)


def film_check(renderer, side: int, samples: int, film_nm: float) -> dict:
    """Our smooth dielectric_bsdf (R, ior 1.5) under a film (index 1.3) in the white furnace
    against the exact Airy reflectance at each pixel's N.V, taken to RGB as ours is (equal-energy
    white): an independent judge of the film, which testrender ignores."""
    case = stress.bsdf_case("dielectric", "film_check", "dielectric_bsdf", {
        "roughness": (0.0, 0.0), "ior": 1.5, "scatter_mode": "R", "thinfilm_thickness": film_nm, "thinfilm_ior": 1.3})
    ours = render_ours(renderer, stress.our_records([case])["film_check"], side, samples)
    exact = spectrum_rgb(thin_film_reflectance(sphere_cosines(side), 1.3, film_nm, 1.5))
    return compare(ours, exact, side)


def render_truth(world: gts.Scene, closure: Translation, side: int, spp: int) -> np.ndarray:
    """testrender's furnace image. A closure that only reflects gets one bounce: on a convex sphere
    no reflected path meets the sphere again, and more bounces only add testrender's leak (its
    microfacet sample() keeps directions below the horizon, which its eval() refuses)."""
    name = f"furnace_{gts.digest(closure.expression)}"
    if (message := world.add_surface(surface_source(name, closure.expression), name)) is not None:
        raise RuntimeError(f"oslc: {message}")
    return world.render(name, side, spp, constant=1.0, max_bounces=16 if closure.transmits else 1)


def render_ours(renderer, record: dict, side: int, samples: int) -> np.ndarray:
    return renderer.render(stress.without_initialisers(record), size=side, env=stress.white_furnace(),
                           env_samples=samples).rgba


def judged_cases(family: str | None = None) -> tuple[list, list]:
    """(case, Translation) for each plausible stress case OSL can express; (case, why) for the others."""
    defaults = nodedef_defaults()
    judged, left_out = [], []
    for case in stress.cases():
        if not case.plausible or (family and case.family != family):
            continue
        try:
            judged.append((case, osl_closure(case, defaults)))
        except Untranslatable as exc:
            left_out.append((case, str(exc)))
    return judged, left_out


def fmt_rgb(v) -> str:
    return f"{v[0]:.3f}" if np.ptp(v) < 5e-4 else "/".join(f"{c:.3f}" for c in v)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--samples", type=int, default=64, help="our environment samples (FIS), as bench/stress.py")
    parser.add_argument("--spp", type=int, default=64,
                        help="testrender's samples per pixel (the figure is a mean over the sphere: few are enough)")
    parser.add_argument("--family", help="only this stress family")
    parser.add_argument("--table", default=os.path.join(ROOT, "docs", "furnace_truth.md"))
    args = parser.parse_args()
    if gts.testrender() is None:
        raise SystemExit("testrender is not installed (scripts/osl.sh builds it)")
    from shadergen.render import Renderer

    judged, left_out = judged_cases(args.family)
    records = stress.our_records([c for c, _ in judged])
    renderer = Renderer()
    rows = []
    mask = gts.sphere_mask(args.size, INSET)
    started = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="furnace-truth-") as folder:
        world = gts.Scene(folder)
        for case, closure in judged:
            row = {"case": case, "closure": closure.expression, "cause": "; ".join(closure.limitations),
                   "single": single_scattering_expected(closure.expression, args.size, mask)}
            record = records[case.name]
            if "error" in record:
                row["error"] = f"ours refused: {record['error'].get('code')}"
            else:
                try:
                    row.update(compare(render_ours(renderer, record, args.size, args.samples),
                                       render_truth(world, closure, args.size, args.spp), args.size))
                except Exception as exc:  # a case that fails is a row, not the end of the run
                    row["error"] = f"{type(exc).__name__}: {str(exc).splitlines()[0][:120] if str(exc) else ''}"
            rows.append(row)
            if "error" in row:
                print(f"{case.name}: {row['error']}", flush=True)
            else:
                print(f"{case.name}: ours {fmt_rgb(row['ours'])} testrender {fmt_rgb(row['truth'])} "
                      f"delta {row['delta']:.3f} band {row['band_delta']:.3f}", flush=True)
    films = {nm: film_check(renderer, args.size, args.samples, nm) for nm in FILMS_NM}
    for nm, f in films.items():
        print(f"thin film {nm:g} nm against Airy: ours {fmt_rgb(f['ours'])} exact {fmt_rgb(f['truth'])} "
              f"band {f['band_delta']:.4f}", flush=True)
    measured = [r for r in rows if "error" not in r]
    agree = [r for r in measured if r["delta"] <= AGREE]
    explained = [r for r in measured if r["delta"] > AGREE and r["cause"]]
    unexplained = sorted((r for r in measured if r["delta"] > AGREE and not r["cause"]), key=lambda r: -r["delta"])
    worst = max(measured, key=lambda r: r["delta"], default=None)
    worst_unexplained = unexplained[0] if unexplained else None
    last = (f"furnace truth: {len(measured)} cases | within {AGREE:g} of testrender: {len(agree)} | "
            f"apart with a testrender limitation: {len(explained)} | apart unexplained: {len(unexplained)}"
            + (f" (worst {worst_unexplained['case'].name} {worst_unexplained['delta']:.3f})" if worst_unexplained else "")
            + (f" | worst {worst['case'].name} ours {fmt_rgb(worst['ours'])} testrender {fmt_rgb(worst['truth'])}"
               f" ({worst['cause'] or 'unexplained'})" if worst else "")
            + f" | left out {len(left_out)}"
            + f" | thin film against Airy: worst band {max(f['band_delta'] for f in films.values()):.4f}"
            + f" | {time.perf_counter() - started:.0f} s")
    write_table(args, rows, left_out, films, last)
    print(last)
    return 0


def write_table(args, rows: list, left_out: list, films: dict, last: str) -> None:
    lines = ["# The white furnace judged by testrender", "",
             f"Written by `bench/furnace_truth.py` ({args.size}x{args.size}; ours: GL, fis {args.samples}; testrender "
             f"{args.spp} spp). Each plausible case of the stress set (bench/stress.py) that OSL 1.13's MaterialX closures "
             "can express: the sphere's mean in a white furnace (per channel when they differ), ours and "
             "testrender's; delta the largest channel difference of the means; band the largest difference of the "
             "means over one N.V band of the sphere (and which band); single: a white conductor's expected value under "
             "single-scattering GGX, by quadrature (what testrender should give; a lossless closure's exact answer is "
             "1); cause: the testrender limitation the case meets (bench/furnace_truth.py's docstring).", "",
             "| case | family | ours | testrender | delta | band delta (N.V) | single | cause |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        single = f"{r['single']:.3f}" if r["single"] is not None else ""
        if "error" in r:
            lines.append(f"| {r['case'].name} | {r['case'].family} | - | - | - | - | {single} | {r['error']} |")
            continue
        lines.append(f"| {r['case'].name} | {r['case'].family} | {fmt_rgb(r['ours'])} | {fmt_rgb(r['truth'])} | "
                     f"{r['delta']:.3f} | {r['band_delta']:.3f} ({r['band']}) | {single} | {r['cause']} |")
    by_family = {}
    for r in rows:
        if "error" not in r:
            f = by_family.setdefault(r["case"].family, [])
            f.append(r)
    lines += ["", "## Per family", "", "| family | cases | within 0.02 | worst case | ours | testrender | delta | cause |",
              "|---|---|---|---|---|---|---|---|"]
    for family, rs in by_family.items():
        w = max(rs, key=lambda r: r["delta"])
        lines.append(f"| {family} | {len(rs)} | {sum(r['delta'] <= AGREE for r in rs)} | {w['case'].name} | "
                     f"{fmt_rgb(w['ours'])} | {fmt_rgb(w['truth'])} | {w['delta']:.3f} | "
                     f"{'agrees' if w['delta'] <= AGREE else w['cause'] or 'unexplained'} |")
    if left_out:
        reasons = {}
        for case, why in left_out:
            reasons.setdefault(why, []).append(case.name)
        lines += ["", "## Left out", ""] + [f"- {why}: {len(names)} ({', '.join(names[:4])}{', ...' if len(names) > 4 else ''})"
                                            for why, names in reasons.items()]
    lines += ["", "## Thin film against the exact Airy reflectance", "",
              "testrender ignores films, so the film's judge is the exact reflectance of a film (index 1.3) on a "
              "smooth dielectric (ior 1.5), the Airy sum over the spectrum (Born & Wolf 7.6), to RGB with CIE 1931 "
              "(Wyman et al.'s fit) and an equal-energy white, at each pixel's N.V; ours: dielectric_bsdf R, roughness 0.",
              "", "| film nm | ours | exact | worst band delta (N.V) |", "|---|---|---|---|"]
    lines += [f"| {nm:g} | {fmt_rgb(f['ours'])} | {fmt_rgb(f['truth'])} | {f['band_delta']:.4f} ({f['band']}) |"
              for nm, f in films.items()]
    lines += ["", "```", last, "```", ""]
    with open(args.table, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
