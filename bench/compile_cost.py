#!/usr/bin/env python3
"""Where a complete shader's compile time goes: hand-edited variants of one generated fragment.

Drivers inline every call, so what a fragment costs to compile is the code they see after inlining:
the BSDF tree written out per context, the sample loops, the thin film at every Fresnel call. This
generates one material's `complete` record (environment by fis; unlit, as a thumbnail's program
is, or with --lights), removes one part at a time from its pixel stage (each edit finds its text or
fails), and compiles each variant in a fresh process with Mesa's shader cache off, interleaved over
--runs. It reports the CPU time of the thread that compiles (less disturbed by a loaded machine
than wall time) for compile+link and for the first render, which includes llvmpipe's code
generation; images are compared to the unedited one only to show what an edit removed.

  .venv/bin/python bench/compile_cost.py [DOC.mtlx] [--runs 3] [--lights]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_DOCUMENT = os.path.join(os.path.dirname(ROOT), "shared", "corpus", "resources", "Materials", "Examples",
                                "StandardSurface", "standard_surface_carpaint.mtlx")
FIRST_RENDER = """
import json, sys, time
import numpy as np
from shadergen.render import program
from shadergen.render import renderer
cpu = {}
class Timed(program.Program):
    def __init__(self, *args, **kwargs):
        t0 = time.thread_time()
        super().__init__(*args, **kwargs)
        cpu["compile_link_ms"] = (time.thread_time() - t0) * 1e3
renderer.Program = Timed
record = json.load(open(sys.argv[1]))
t0 = time.thread_time()
rgba = renderer.Renderer().render(record, size=64).rgba
cpu["first_render_ms"] = (time.thread_time() - t0) * 1e3
np.save(sys.argv[2], rgba)
print(json.dumps(cpu))
"""


def block_removed(source: str, marker: str) -> str:
    """`source` without the statement or block that starts on the line holding `marker`."""
    start = source.index(marker)
    line_start = source.rfind("\n", 0, start) + 1
    depth, k = 0, source.index("{", start)
    while True:
        depth += {"{": 1, "}": -1}.get(source[k], 0)
        if depth == 0:
            break
        k += 1
    return source[:line_start] + source[source.index("\n", k) + 1:]


def replaced(source: str, old: str, new: str) -> str:
    if old not in source:
        raise SystemExit(f"the generated source no longer has {old.strip()[:60]!r}: update this bench")
    return source.replace(old, new)


LIGHT_LOOP = "for (int activeLightIndex"
LIGHT_LOOP_VARIANT = "light loop"  # in the names of the variants that need it
TRANSMISSION = "// transmission, seen along the view direction"
VARIANTS = {
    "as generated": lambda s: s,
    "no light loop": lambda s: block_removed(s, LIGHT_LOOP),
    "no transmission context": lambda s: block_removed(s, TRANSMISSION),
    "no light loop, no transmission": lambda s: block_removed(block_removed(s, LIGHT_LOOP), TRANSMISSION),
    "no sample loop in the lobes' preparation": lambda s: replaced(
        s, "    if (lobe.weight > 0.0)\n        lobe.environment = mx_environment_reflected(",
        "    if (false)\n        lobe.environment = mx_environment_reflected("),
    "no thin film in the Fresnel dispatch": lambda s: replaced(
        s, "    if (withFilm && mx_fresnel_has_thinfilm(fd))\n        return mx_fresnel_airy(cosTheta, fd);\n", ""),
}


def psnr(a, b) -> float:
    import numpy as np
    mse = float(np.mean((a[..., :3].astype(float) - b[..., :3].astype(float)) ** 2))
    return float("inf") if mse == 0 else 10 * np.log10(max(1.0, float(np.nanmax(a[..., :3]))) ** 2 / mse)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("document", nargs="?", default=DEFAULT_DOCUMENT)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--lights", action="store_true",
                    help="with the light loop (a lit preview's program; a thumbnail's has none)")
    args = ap.parse_args()
    import numpy as np
    sys.path.insert(0, ROOT)
    from shadergen.api import generate_file
    record = next(r for r in generate_file(args.document, environment="fis", lights=args.lights) if "stages" in r)
    env = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true", PYTHONPATH=ROOT)
    names = [name for name in VARIANTS if args.lights or LIGHT_LOOP_VARIANT not in name]
    timings = {name: [] for name in names}
    start = time.strftime("%H:%M:%S")
    with tempfile.TemporaryDirectory() as tmp:
        paths = {name: os.path.join(tmp, str(k)) for k, name in enumerate(names)}
        for name in names:
            with open(paths[name] + ".json", "w") as f:
                json.dump(dict(record, stages=dict(record["stages"], pixel=VARIANTS[name](record["stages"]["pixel"]))), f)
        for r in range(args.runs):
            for name in names[r % len(names):] + names[:r % len(names)]:  # rotated: load drifts over all alike
                run = subprocess.run([sys.executable, "-c", FIRST_RENDER, paths[name] + ".json", paths[name] + ".npy"],
                                     capture_output=True, text=True, env=env)
                if run.returncode != 0:
                    raise SystemExit(f"{name}: {(run.stdout + run.stderr).strip()[-500:]}")
                timings[name].append(json.loads(run.stdout.strip().splitlines()[-1]))
        pixels = {name: np.load(paths[name] + ".npy") for name in names}
    medians = {name: {key: statistics.median(t[key] for t in timings[name]) for key in timings[name][0]}
               for name in names}
    base = medians["as generated"]
    print(f"\n{os.path.basename(args.document)} complete ({'lit' if args.lights else 'unlit'}, fis), "
          f"{args.runs} interleaved run(s) from {start}, load average {os.getloadavg()[0]:.1f}; thread CPU ms, medians\n")
    print("| variant | fragment lines | compile+link | ratio | first render (with code generation) | ratio "
          "| PSNR vs as generated |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name in names:
        m = medians[name]
        lines = VARIANTS[name](record["stages"]["pixel"]).count("\n")
        print(f"| {name} | {lines} | {m['compile_link_ms']:.0f} | {m['compile_link_ms'] / base['compile_link_ms']:.2f} "
              f"| {m['first_render_ms']:.0f} | {m['first_render_ms'] / base['first_render_ms']:.2f} "
              f"| {psnr(pixels['as generated'], pixels[name]):.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
