#!/usr/bin/env python3
"""Colour management by OpenColorIO (issue 28): our generated transforms against OCIO itself.

For every scene colour space of OCIO's built-in ACES CG and studio configs that converts to the
working space (ACEScg): a GL render of a plane sampling a ramp of test colours (shadergen/cms/
check.py) through our generated shader, against OCIO's CPU processor on the colours each pixel
sampled: max absolute error, and that error over max(1, |expected|) (float32 holds about 7
digits: a log space's 1.0 is a linear 200 whose last bit is 1.5e-5), against the goals 1e-4
(analytic) and 2e-3 (LUT). Values `specialized` folds: their difference from the CPU
processor's, goal 1e-6. Then a colour-managed material (textures and values in three spaces)
against the same material without colour spaces: generation and steady-frame time, interleaved
runs, medians. Then which of OCIO's GPU shaders need LUTs: every space to the working space and
every display's view from it, per built-in config (1D LUTs we draw as textures; 3D LUTs we
refuse, so none may be needed); and what a thumbnail's display encoding costs (a 256x256 PNG
through sRGB, and through the CG config's default view and 'Un-tone-mapped', interleaved, medians).

  .venv/bin/python bench/color.py [--runs 5] [--size 64] [--table docs/color-bench.md]
"""
import argparse
import os
import statistics
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

import numpy as np  # noqa: E402
import PyOpenColorIO as OCIO  # noqa: E402

from shadergen.api import DocumentFile, Generator  # noqa: E402
from shadergen.cms import display_encoder  # noqa: E402
from shadergen.cms.check import RampCheck  # noqa: E402
from shadergen.render import Renderer  # noqa: E402
from shadergen.render.imageio import encode_png, write_image  # noqa: E402

CONFIGS = ("ocio://cg-config-v2.1.0_aces-v1.3_ocio-v2.3", "ocio://studio-config-v2.1.0_aces-v1.3_ocio-v2.3")
WORKING = "ACEScg"
GOALS = {False: 1e-4, True: 2e-3}  # analytic, LUT
FOLD_GOAL = 1e-6
MATERIAL = """<?xml version="1.0"?>
<materialx version="1.39"{working}>
  <image name="base" type="color3">
    <input name="file" type="filename" value="ramp.exr"{srgb} />
  </image>
  <standard_surface name="ss" type="surfaceshader">
    <input name="base_color" type="color3" nodename="base" />
    <input name="specular_color" type="color3" value="0.9, 0.8, 0.7"{log} />
    <input name="emission_color" type="color3" value="0.1, 0.2, 0.3"{lut} />
    <input name="emission" type="float" value="0.1" />
  </standard_surface>
  <surfacematerial name="mat" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="ss" />
  </surfacematerial>
</materialx>
"""


def scene_spaces(config: str) -> list[str]:
    cfg = OCIO.Config.CreateFromFile(config)
    return [cs.getName() for cs in cfg.getColorSpaces(OCIO.SEARCH_REFERENCE_SPACE_SCENE, OCIO.COLORSPACE_ALL)
            if not cs.isData() and cs.getName() != WORKING]


def accuracy(size: int) -> list[dict]:
    rows = []
    for config in CONFIGS:
        check = RampCheck(config, WORKING, size=size)
        for space in scene_spaces(config):
            error, scaled, lut = check.error(space)
            rows.append({"config": config.removeprefix("ocio://").split("_")[0], "space": space, "lut": lut,
                         "error": error, "scaled": scaled, "folded": check.folded(space),
                         "ok": scaled <= GOALS[lut]})
    return rows


def timing(runs: int, size: int) -> dict:
    """Medians of generation (ms, in process, warm) and steady frame (ms) of the material with and
    without colour spaces, the two interleaved."""
    folder = tempfile.mkdtemp(prefix="shadergen-colour-bench-")
    ramp = np.concatenate([np.random.default_rng(1).random((16, 16, 3), dtype="f4"), np.ones((16, 16, 1), "f4")], 2)
    write_image(os.path.join(folder, "ramp.exr"), ramp)
    paths = {}
    for name, managed in (("managed", True), ("plain", False)):
        attrs = {"working": f' colorspace="{WORKING}"' if managed else "",
                 "srgb": ' colorspace="sRGB - Texture"' if managed else "",
                 "log": ' colorspace="ACEScct"' if managed else "", "lut": ' colorspace="ACEScc"' if managed else ""}
        paths[name] = os.path.join(folder, f"{name}.mtlx")
        with open(paths[name], "w") as f:
            f.write(MATERIAL.format(**attrs))
    generator, renderer = Generator(), Renderer()
    samples = {name: {"generate": [], "frame": []} for name in paths}
    for run in range(runs):
        for name in (("managed", "plain") if run % 2 == 0 else ("plain", "managed")):
            t0 = time.perf_counter()
            record = next(iter(generator.records(DocumentFile(paths[name]), target="glsl", interface="complete",
                                                 cms="ocio", ocio_config=CONFIGS[0])))
            samples[name]["generate"].append((time.perf_counter() - t0) * 1e3)
            result = renderer.render(record, size=size, frames=9, document_dir=folder)
            samples[name]["frame"].append(result.timings_ms["frame"])
    return {name: {k: statistics.median(v) for k, v in s.items()} for name, s in samples.items()}


def lut_census() -> list[dict]:
    """Per built-in config: OCIO's GPU shaders (GLSL 4.0) of every space to the working space and
    every display's view from it, and how many of them hold 1D and 3D LUTs."""
    rows = []
    for config in CONFIGS + ("ocio://default",):
        cfg = OCIO.Config.CreateFromFile(config)
        processors = [cfg.getProcessor(cs, WORKING) for cs in cfg.getColorSpaceNames()]
        processors += [cfg.getProcessor(OCIO.DisplayViewTransform(src=WORKING, display=d, view=v))
                       for d in cfg.getDisplays() for v in cfg.getViews(d)]
        one, three = 0, 0
        for processor in processors:
            desc = OCIO.GpuShaderDesc.CreateShaderDesc(language=OCIO.GPU_LANGUAGE_GLSL_4_0)
            desc.setAllowTexture1D(False)
            processor.getDefaultGPUProcessor().extractGpuShaderInfo(desc)
            one += bool(list(desc.getTextures()))
            three += bool(list(desc.get3DTextures()))
        rows.append({"config": config.removeprefix("ocio://").split("_")[0], "shaders": len(processors),
                     "lut1d": one, "lut3d": three})
    return rows


def display_timing(runs: int) -> dict:
    """Median ms to encode a 256x256 linear render as a PNG: sRGB (the built-in system's), and
    OCIO's default view and Un-tone-mapped view of the CG config from ACEScg."""
    rgba = np.concatenate([np.random.default_rng(2).random((256, 256, 3), dtype="f4") * 4,
                           np.ones((256, 256, 1), "f4")], 2)
    encoders = {"sRGB (builtin)": None,
                "OCIO default view": display_encoder({"ocio_config": CONFIGS[0], "working": WORKING, "view": None}),
                "OCIO Un-tone-mapped": display_encoder({"ocio_config": CONFIGS[0], "working": WORKING,
                                                        "view": "Un-tone-mapped"})}
    samples = {name: [] for name in encoders}
    for run in range(runs):
        for name in (list(encoders) if run % 2 == 0 else list(reversed(encoders))):
            t0 = time.perf_counter()
            encode_png(rgba, encode=encoders[name])
            samples[name].append((time.perf_counter() - t0) * 1e3)
    return {name: statistics.median(v) for name, v in samples.items()}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--size", type=int, default=64, help="ramp render side in pixels")
    parser.add_argument("--table", metavar="FILE.md", help="also write the table there")
    args = parser.parse_args()
    rows = accuracy(args.size)
    lines = ["| config | colour space | kind | max abs error | error / max(1, abs value) | goal | folded | ok |",
             "|---|---|---|---:|---:|---:|---:|---|"]
    for r in rows:
        lines.append(f"| {r['config']} | {r['space']} | {'LUT' if r['lut'] else 'analytic'} | {r['error']:.2e} | "
                     f"{r['scaled']:.2e} | {GOALS[r['lut']]:.0e} | {r['folded']:.1e} | {'yes' if r['ok'] else 'NO'} |")
    times = timing(args.runs, 128)
    lines += ["", "| material | generate ms | frame ms |", "|---|---:|---:|"]
    lines += [f"| {name} | {t['generate']:.1f} | {t['frame']:.1f} |" for name, t in times.items()]
    census = lut_census()
    lines += ["", "| config | GPU shaders (spaces to ACEScg, views from it) | with 1D LUTs | with 3D LUTs |",
              "|---|---:|---:|---:|"]
    lines += [f"| {r['config']} | {r['shaders']} | {r['lut1d']} | {r['lut3d']} |" for r in census]
    encoding = display_timing(max(args.runs, 9))
    lines += ["", "| thumbnail 256x256 PNG encoding | ms |", "|---|---:|"]
    lines += [f"| {name} | {ms:.2f} |" for name, ms in encoding.items()]
    text = "\n".join(lines)
    print(text)
    if args.table:
        with open(args.table, "w") as f:
            f.write(text + "\n")
    analytic = [r["scaled"] for r in rows if not r["lut"]]
    luts = [r["scaled"] for r in rows if r["lut"]]
    passed = sum(r["ok"] for r in rows)
    folded = max(r["folded"] for r in rows)
    print(f"color: {passed}/{len(rows)} spaces within goal | analytic max {max(analytic):.1e} (goal 1e-4) | "
          f"LUT max {max(luts):.1e} (goal 2e-3) | folded max {folded:.1e} (goal 1e-6) | "
          f"generate managed/plain {times['managed']['generate'] / times['plain']['generate']:.2f} | "
          f"frame managed/plain {times['managed']['frame'] / times['plain']['frame']:.2f} | "
          f"3D LUTs needed {sum(r['lut3d'] for r in census)}/{sum(r['shaders'] for r in census)} shaders | "
          f"PNG through the default view/sRGB "
          f"{encoding['OCIO default view'] / encoding['sRGB (builtin)']:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
