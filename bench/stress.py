#!/usr/bin/env python3
"""Numerical stress of the PBR library in a white furnace (issue 10).

Every BSDF node and the standard_surface / open_pbr_surface shading models at the edges of their
parameters (roughness 0, 1e-6, 0.5, 1 and anisotropic; ior 0, 1, 1.0001, 1.5, 3, 10; thin film 0,
500, 3000 nm; conductor index and extinction zero, gold, 100; reflection, transmission and both;
weights 0, 1, 10, negative and NaN), each a material of its own, drawn by our renderer on a sphere
lit by a white environment (radiance 1 in every direction). A material that conserves energy
never returns more than 1 there. Printed per node family: documents, documents refused (a NaN
input is `invalid_value`), NaN/Inf pixels, negative pixels, the largest p99.9 over the sphere, and
the physically plausible cases (weights in [0, 1], ior >= 1) whose p99.9 exceeds 1.01; the same for
the reference's shaders (../shared/oracle) drawn by the same renderer when the oracle venv exists.

    .venv/bin/python bench/stress.py [--size 64] [--samples 64] [--family dielectric] [--no-reference] [--worst 10]
"""
import argparse
import itertools
import json
import math
import os
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, ROOT)
SHARED = os.path.join(os.path.dirname(ROOT), "shared")
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
ORACLE = os.path.join(SHARED, "oracle", "mx_oracle.py")
LIMIT = 1.01

ROUGHNESS = {"r0": 0.0, "r1e-6": 1e-6, "r0.5": 0.5, "r1": 1.0}
ANISOTROPIC = (0.1, 0.9)
IORS = (0.0, 1.0, 1.0001, 1.5, 3.0, 10.0)
THIN_FILMS = (0.0, 500.0, 3000.0)
SCATTER_MODES = ("R", "T", "RT")
WEIGHTS = {"w0": 0.0, "w1": 1.0, "w10": 10.0, "w-1": -1.0, "wnan": float("nan")}
CONDUCTORS = {"zero": ((0.0,) * 3, (0.0,) * 3), "gold": ((0.18, 0.42, 1.37), (3.42, 2.35, 1.77)),
              "n100": ((100.0,) * 3, (0.0,) * 3), "k100": ((0.0,) * 3, (100.0,) * 3), "nk100": ((100.0,) * 3, (100.0,) * 3)}


@dataclass(frozen=True)
class Case:
    family: str
    name: str
    xml: str               # the nodes of one material, its shader node named "shader"
    plausible: bool        # physically meaningful parameters: the furnace must stay <= LIMIT


@dataclass
class Tally:
    documents: int = 0
    refused: int = 0
    failed: int = 0
    nan_pixels: int = 0
    negative_pixels: int = 0
    worst: float = 0.0
    over: list = field(default_factory=list)  # names of plausible cases over LIMIT


def value_xml(value) -> tuple[str, str]:
    if isinstance(value, bool):
        return "boolean", "true" if value else "false"
    if isinstance(value, str):
        return "string", value
    if isinstance(value, tuple):
        return {2: "vector2", 3: "color3"}[len(value)], ", ".join(f"{v:g}" for v in value)
    return "float", f"{value:g}"


def node_xml(category: str, name: str, type_name: str, inputs: dict) -> str:
    body = "".join(f'<input name="{k}" type="{value_xml(v)[0]}" value="{value_xml(v)[1]}"/>' for k, v in inputs.items())
    return f'<{category} name="{name}" type="{type_name}">{body}</{category}>'


# Every document names its nodes alike, so that the generated source depends on the topology only
# and the renderer compiles one program per family shape, not one per case.
SURFACE = '<surface name="shader" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="bsdf"/></surface>'


def bsdf_case(family: str, name: str, node: str, inputs: dict, plausible: bool = True) -> Case:
    return Case(family, name, node_xml(node, "bsdf", "BSDF", inputs) + SURFACE, plausible)


def shader_case(family: str, name: str, node: str, inputs: dict, plausible: bool = True) -> Case:
    return Case(family, name, node_xml(node, "shader", "surfaceshader", inputs), plausible)


def weight_cases(family: str, make, base: dict) -> list[Case]:
    """The family's node at each edge weight; only weights in [0, 1] are plausible."""
    return [make(family, f"{family}_{label}", dict(base, weight=w), 0.0 <= w <= 1.0) for label, w in WEIGHTS.items()]


def roughness_values(vector: bool):
    for label, r in ROUGHNESS.items():
        yield label, ((r, r) if vector else r)
    if vector:
        yield "aniso", ANISOTROPIC


def cases() -> list[Case]:
    out: list[Case] = []

    def bsdf(family, name, node, inputs, plausible=True):
        out.append(bsdf_case(family, name, node, inputs, plausible))

    for (rl, r), ior, mode in itertools.product(roughness_values(True), IORS, SCATTER_MODES):
        bsdf("dielectric", f"diel_{rl}_ior{ior:g}_{mode}", "dielectric_bsdf",
             {"roughness": r, "ior": ior, "scatter_mode": mode}, ior >= 1.0)
    for (rl, r), film, ior in itertools.product(roughness_values(True), THIN_FILMS[1:], (1.5, 3.0)):
        bsdf("dielectric", f"diel_{rl}_film{film:g}_ior{ior:g}", "dielectric_bsdf",
             {"roughness": r, "ior": ior, "scatter_mode": "RT", "thinfilm_thickness": film, "thinfilm_ior": 1.3})
    out += weight_cases("dielectric", lambda f, n, i, p: bsdf_case(f, n, "dielectric_bsdf", i, p),
                        {"roughness": (0.5, 0.5), "ior": 1.5, "scatter_mode": "RT"})

    for (rl, r), (cl, (n, k)), film in itertools.product(roughness_values(True), CONDUCTORS.items(), THIN_FILMS):
        bsdf("conductor", f"cond_{rl}_{cl}_film{film:g}", "conductor_bsdf",
             {"roughness": r, "ior": n, "extinction": k, "thinfilm_thickness": film, "thinfilm_ior": 1.5})
    out += weight_cases("conductor", lambda f, n, i, p: bsdf_case(f, n, "conductor_bsdf", i, p), {"roughness": (0.5, 0.5)})

    schlick_colours = {"white": ((1.0,) * 3, (1.0,) * 3, (1.0,) * 3), "plastic": ((0.04,) * 3, (1.0,) * 3, (1.0,) * 3),
                       "tinted": ((0.9, 0.6, 0.2), (0.8, 0.8, 0.9), (1.0,) * 3)}
    for (rl, r), (cl, (c0, c82, c90)), mode in itertools.product(roughness_values(True), schlick_colours.items(), SCATTER_MODES):
        bsdf("generalized_schlick", f"gs_{rl}_{cl}_{mode}", "generalized_schlick_bsdf",
             {"roughness": r, "color0": c0, "color82": c82, "color90": c90, "scatter_mode": mode})
    for (rl, r), film, exponent in itertools.product(roughness_values(True), THIN_FILMS[1:], (0.0, 5.0, 100.0)):
        bsdf("generalized_schlick", f"gs_{rl}_film{film:g}_exp{exponent:g}", "generalized_schlick_bsdf",
             {"roughness": r, "color0": (0.04,) * 3, "exponent": exponent, "thinfilm_thickness": film, "thinfilm_ior": 1.5})
    out += weight_cases("generalized_schlick", lambda f, n, i, p: bsdf_case(f, n, "generalized_schlick_bsdf", i, p),
                        {"roughness": (0.5, 0.5), "color0": (1.0,) * 3})

    for (rl, r), compensated, colour in itertools.product(roughness_values(False), (False, True), (1.0, 0.5)):
        bsdf("oren_nayar_diffuse", f"on_{rl}_{'eon' if compensated else 'qon'}_c{colour:g}", "oren_nayar_diffuse_bsdf",
             {"roughness": r, "energy_compensation": compensated, "color": (colour,) * 3})
    out += weight_cases("oren_nayar_diffuse", lambda f, n, i, p: bsdf_case(f, n, "oren_nayar_diffuse_bsdf", i, p),
                        {"color": (1.0,) * 3})
    for (rl, r), colour in itertools.product(roughness_values(False), (1.0, 0.5)):
        bsdf("burley_diffuse", f"burley_{rl}_c{colour:g}", "burley_diffuse_bsdf", {"roughness": r, "color": (colour,) * 3})
    out += weight_cases("burley_diffuse", lambda f, n, i, p: bsdf_case(f, n, "burley_diffuse_bsdf", i, p),
                        {"color": (1.0,) * 3, "roughness": 1.0})
    for (rl, r), mode in itertools.product(roughness_values(False), ("conty_kulla", "zeltner")):
        bsdf("sheen", f"sheen_{rl}_{mode}", "sheen_bsdf", {"roughness": r, "mode": mode, "color": (1.0,) * 3})
    out += weight_cases("sheen", lambda f, n, i, p: bsdf_case(f, n, "sheen_bsdf", i, p), {"color": (1.0,) * 3})
    for radius in (0.0, 1.0, 100.0):
        bsdf("subsurface", f"sss_radius{radius:g}", "subsurface_bsdf", {"radius": (radius,) * 3, "color": (1.0,) * 3})
    out += weight_cases("subsurface", lambda f, n, i, p: bsdf_case(f, n, "subsurface_bsdf", i, p), {"color": (1.0,) * 3})
    out += weight_cases("translucent", lambda f, n, i, p: bsdf_case(f, n, "translucent_bsdf", i, p), {"color": (1.0,) * 3})
    for rl, r in roughness_values(False):
        bsdf("chiang_hair", f"hair_{rl}", "chiang_hair_bsdf",
             {"roughness_R": (r, r), "roughness_TT": (r, r), "roughness_TRT": (r, r)})
    out += layer_cases()
    out += shading_model_cases()
    out += graph_value_cases()
    return out


# Values a graph computes at run time, which no document check can see: in1 / in2 of a divide node.
GRAPH_VALUES = {"nan": (0.0, 0.0), "inf": (1.0, 0.0), "-inf": (-1.0, 0.0), "zero": (0.0, 1.0), "neg": (-1.0, 1.0)}
# node -> its inputs that a graph may feed (name: type), and its other inputs
GRAPH_FED = {
    "dielectric_bsdf": ({"ior": "float", "roughness": "vector2", "thinfilm_thickness": "float", "thinfilm_ior": "float"},
                        {"scatter_mode": "RT", "thinfilm_thickness": 500.0}),
    "conductor_bsdf": ({"ior": "color3", "extinction": "color3", "roughness": "vector2"}, {}),
    "generalized_schlick_bsdf": ({"roughness": "vector2", "exponent": "float"}, {"scatter_mode": "RT"}),
    "oren_nayar_diffuse_bsdf": ({"roughness": "float"}, {"energy_compensation": True}),
    "burley_diffuse_bsdf": ({"roughness": "float"}, {}),
    "sheen_bsdf": ({"roughness": "float"}, {}),
    "subsurface_bsdf": ({"radius": "color3", "anisotropy": "float"}, {}),
    "chiang_hair_bsdf": ({"ior": "float", "roughness_R": "vector2"}, {}),
    "standard_surface": ({"specular_roughness": "float", "specular_IOR": "float", "coat_IOR": "float",
                          "thin_film_IOR": "float"}, {"coat": 1.0, "transmission": 0.5, "thin_film_thickness": 500.0}),
    "open_pbr_surface": ({"specular_roughness": "float", "specular_ior": "float", "coat_ior": "float"},
                         {"coat_weight": 1.0, "transmission_weight": 0.5}),
}


def graph_value_cases() -> list[Case]:
    """Every input of GRAPH_FED read from a divide node that gives NaN, +-Inf, 0 or -1 at run time.
    Not plausible (the furnace bound does not apply); no pixel may be NaN, Inf or negative."""
    out = []
    for (node, (fed, others)), label in itertools.product(GRAPH_FED.items(), GRAPH_VALUES):
        numerator, denominator = GRAPH_VALUES[label]
        shader = node in SHADING_MODELS
        for name, type_name in fed.items():
            divide = (f'<divide name="value" type="{type_name}"><input name="in1" type="{type_name}" '
                      f'value="{", ".join([f"{numerator:g}"] * {"float": 1, "vector2": 2, "color3": 3}[type_name])}"/>'
                      f'<input name="in2" type="float" value="{denominator:g}"/></divide>')
            inputs = "".join(f'<input name="{k}" type="{value_xml(v)[0]}" value="{value_xml(v)[1]}"/>'
                             for k, v in others.items() if k != name)
            fed_input = f'<input name="{name}" type="{type_name}" nodename="value"/>'
            element = (f'<{node} name="{"shader" if shader else "bsdf"}" type="{"surfaceshader" if shader else "BSDF"}">'
                       f'{inputs}{fed_input}</{node}>')
            out.append(Case("graph_values", f"graph_{node}_{name}_{label}", divide + element + ("" if shader else SURFACE),
                            False))
    return out


def layer_cases() -> list[Case]:
    """A top lobe over a white diffuse base: what the top reflects must not also reach the base."""
    out = []
    tops = {"coat": ("dielectric_bsdf", {"ior": 1.5, "scatter_mode": "R"}, "roughness", True),
            "coat3": ("dielectric_bsdf", {"ior": 3.0, "scatter_mode": "R"}, "roughness", True),
            "schlick": ("generalized_schlick_bsdf", {"color0": (0.5,) * 3}, "roughness", True),
            "sheen": ("sheen_bsdf", {"color": (1.0,) * 3}, "roughness", False)}
    for (label, (node, inputs, rough_input, vector)), (rl, r) in itertools.product(tops.items(), ROUGHNESS.items()):
        top = node_xml(node, "top", "BSDF", dict(inputs, **{rough_input: (r, r) if vector else r}))
        base = node_xml("oren_nayar_diffuse_bsdf", "base", "BSDF", {"color": (1.0,) * 3})
        layer = ('<layer name="bsdf" type="BSDF"><input name="top" type="BSDF" nodename="top"/>'
                 '<input name="base" type="BSDF" nodename="base"/></layer>')
        out.append(Case("layer", f"layer_{label}_{rl}", top + base + layer + SURFACE, True))
    return out


# Each shading model's names for the same physical parameters.
SHADING_MODELS = {
    "standard_surface": ("ss", {"base": "base", "colour": "base_color", "metal": "metalness", "rough": "specular_roughness",
                                "transmission": "transmission", "coat": "coat", "ior": "specular_IOR"}),
    "open_pbr_surface": ("opbr", {"base": "base_weight", "colour": "base_color", "metal": "base_metalness",
                                  "rough": "specular_roughness", "transmission": "transmission_weight",
                                  "coat": "coat_weight", "ior": "specular_ior"}),
}


def shading_model_cases() -> list[Case]:
    out = []
    for model, (prefix, names) in SHADING_MODELS.items():
        for metal, rough, transmission, coat, ior in itertools.product((0.0, 1.0), (0.0, 0.5, 1.0), (0.0, 1.0),
                                                                      (0.0, 1.0), (1.0, 1.5, 3.0)):
            values = {"base": 1.0, "colour": (1.0,) * 3, "metal": metal, "rough": rough, "transmission": transmission,
                      "coat": coat, "ior": ior}
            name = f"{prefix}_m{metal:g}_r{rough:g}_t{transmission:g}_c{coat:g}_ior{ior:g}"
            out.append(shader_case(model, name, model, {names[k]: v for k, v in values.items()}))
    for film, aniso, sheen in itertools.product((0.0, 500.0), (0.0, 0.8), (0.0, 1.0)):
        out.append(shader_case("standard_surface", f"ss_film{film:g}_aniso{aniso:g}_sheen{sheen:g}", "standard_surface", {
            "base": 1.0, "base_color": (1.0,) * 3, "specular_roughness": 0.3, "thin_film_thickness": film,
            "specular_anisotropy": aniso, "sheen": sheen}))
    out += weight_cases("standard_surface", lambda f, n, i, p: shader_case(f, n, "standard_surface",
                        {("base" if k == "weight" else k): v for k, v in i.items()}, p), {"base_color": (1.0,) * 3})
    for film, fuzz in itertools.product((0.0, 500.0), (0.0, 1.0)):
        out.append(shader_case("open_pbr_surface", f"opbr_film{film:g}_fuzz{fuzz:g}", "open_pbr_surface", {
            "base_weight": 1.0, "base_color": (1.0,) * 3, "thin_film_weight": 1.0 if film else 0.0,
            "thin_film_thickness": film / 1000.0, "fuzz_weight": fuzz}))
    return out


def document(case: Case) -> str:
    return ('<?xml version="1.0"?>\n<materialx version="1.39">\n' + case.xml + '\n<surfacematerial name="material" '
            'type="material"><input name="surfaceshader" type="surfaceshader" nodename="shader"/></surfacematerial>\n'
            '</materialx>\n')


def white_furnace():
    from shadergen.render import Environment
    ones = np.ones((32, 64, 3), "f4")
    return Environment(ones, ones, "white-furnace")


def furnace_stats(rgba: np.ndarray) -> dict:
    """NaN/Inf pixels, negative pixels and the p99.9 of the largest channel over the sphere."""
    finite = np.isfinite(rgba).all(axis=2)
    rgb = np.where(finite[..., None], rgba[..., :3], 0.0)
    covered = finite & (rgba[..., 3] > 0.0)
    peak = rgb.max(axis=2)[covered]
    return {"nan": int((~finite).sum()), "negative": int((rgb < 0.0).any(axis=2).sum()),
            "p999": float(np.percentile(peak, 99.9)) if peak.size else 0.0}


UNIFORM_INITIALISER = re.compile(r"^(uniform [^=;]+?) = [^;]+;", re.M)


def without_initialisers(record: dict) -> dict:
    """The record with `uniform T name = value;` declared as `uniform T name;`: the renderer binds
    every value from the listings anyway, and cases differing only in values then share one
    compiled program (ours and the reference's alike)."""
    stages = {stage: UNIFORM_INITIALISER.sub(r"\1;", source) for stage, source in record["stages"].items()}
    return dict(record, stages=stages)


def render_records(renderer, records: dict, size: int, samples: int, env) -> dict:
    """name -> stats, or why there are none: refused (an error record) or failed (the render)."""
    from shadergen.render import RenderError
    out = {}
    for name, record in records.items():
        if "error" in record:
            out[name] = {"refused": record["error"].get("code")}
            continue
        try:
            rgba = renderer.render(without_initialisers(record), size=size, env=env, env_samples=samples).rgba
            out[name] = furnace_stats(rgba)
        except RenderError as exc:
            out[name] = {"failed": f"{exc.code}: {exc.message.splitlines()[0][:100]}"}
    return out


def our_records(family_cases: list[Case]) -> dict:
    from shadergen.api import default_generator
    return {case.name: next(default_generator().records(document(case))) for case in family_cases}


def reference_records(family_cases: list[Case]) -> dict:
    """The oracle's records, one process for the whole family (its documents in one call)."""
    with tempfile.TemporaryDirectory() as tmp:
        paths = {}
        for case in family_cases:
            paths[case.name] = os.path.join(tmp, f"{case.name}.mtlx")
            with open(paths[case.name], "w") as f:
                f.write(document(case))
        run = subprocess.run([ORACLE_PY, ORACLE, *paths.values()], capture_output=True, text=True)
    by_path = {r["document"]: r for r in map(json.loads, filter(str.strip, run.stdout.splitlines()))}
    return {name: by_path.get(path, {"error": {"code": "oracle_failed"}}) for name, path in paths.items()}


def tally(family_cases: list[Case], results: dict) -> Tally:
    t = Tally(documents=len(family_cases))
    for case in family_cases:
        stats = results.get(case.name, {"failed": "missing"})
        if "refused" in stats:
            t.refused += 1
        elif "failed" in stats:
            t.failed += 1
        else:
            t.nan_pixels += stats["nan"]
            t.negative_pixels += stats["negative"]
            t.worst = max(t.worst, stats["p999"])
            if case.plausible and stats["p999"] > LIMIT:
                t.over.append((case.name, stats["p999"]))
    return t


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--samples", type=int, default=64, help="environment samples (FIS)")
    parser.add_argument("--family", help="only this node family")
    parser.add_argument("--no-reference", action="store_true", help="skip the reference's shaders")
    parser.add_argument("--worst", type=int, default=10, help="list this many plausible cases over the limit")
    args = parser.parse_args()

    from shadergen.render import Renderer
    renderer = Renderer()
    env = white_furnace()
    with_reference = not args.no_reference and os.path.exists(ORACLE_PY)
    by_family: dict[str, list[Case]] = {}
    for case in cases():
        if not args.family or case.family == args.family:
            by_family.setdefault(case.family, []).append(case)

    rows = []
    for family, family_cases in by_family.items():
        ours = tally(family_cases, render_records(renderer, our_records(family_cases), args.size, args.samples, env))
        ref = tally(family_cases, render_records(renderer, reference_records(family_cases), args.size, args.samples,
                                                 env)) if with_reference else None
        rows.append((family, family_cases, ours, ref))
        print(f"  {family}: {len(family_cases)} documents", file=sys.stderr)

    print(f"\nWhite furnace (radiance 1), {args.size}x{args.size} sphere, {args.samples} environment samples; "
          f"a plausible case fails above {LIMIT}\n")
    print("| family | documents | plausible | refused ours / ref | failed ours / ref | NaN/Inf px ours / ref | "
          "negative px ours / ref | p99.9 max ours / ref | plausible over 1.01 ours / ref |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    total = {"docs": 0, "plausible": 0, "ours_over": 0, "ref_over": 0, "ours_nan": 0, "ref_nan": 0}
    for family, family_cases, ours, ref in rows:
        plausible = sum(c.plausible for c in family_cases)
        pair = lambda a, b: f"{a} / {b if ref else '-'}"
        print(f"| {family} | {ours.documents} | {plausible} | {pair(ours.refused, ref and ref.refused)} | "
              f"{pair(ours.failed, ref and ref.failed)} | {pair(ours.nan_pixels, ref and ref.nan_pixels)} | "
              f"{pair(ours.negative_pixels, ref and ref.negative_pixels)} | "
              f"{ours.worst:.3f} / {f'{ref.worst:.3f}' if ref else '-'} | {pair(len(ours.over), ref and len(ref.over))} |")
        total["docs"] += ours.documents
        total["plausible"] += plausible
        total["ours_over"] += len(ours.over)
        total["ours_nan"] += ours.nan_pixels
        if ref:
            total["ref_over"] += len(ref.over)
            total["ref_nan"] += ref.nan_pixels
    print(f"\n{total['docs']} documents, {total['plausible']} plausible; over {LIMIT}: ours {total['ours_over']}"
          + (f", reference {total['ref_over']}" if with_reference else "") + f"; NaN/Inf pixels: ours {total['ours_nan']}"
          + (f", reference {total['ref_nan']}" if with_reference else ""))
    worst = sorted(((v, n) for _, _, ours, _ in rows for n, v in ours.over), reverse=True)[:args.worst]
    if worst:
        print("\nOurs, worst plausible cases: " + "; ".join(f"{n} {v:.3f}" for v, n in worst))
    return 0 if total["ours_over"] == 0 and total["ours_nan"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
