"""Our WGSL (or, with --target vulkan, our Vulkan GLSL's SPIR-V; with --target slang, the SPIR-V
slangpy's Slang compiler writes from our Slang, bench/slang_spirv.py; with --target essl, our ESSL
on GL) drawn by WebGPU against our GLSL drawn by GL, same scene (issues 12, 24): every renderable element
of the documents given (default: the Examples materials of the corpus), generated for the target
and for glsl with the same interface, drawn by WgpuRenderer (wgpu on Vulkan: lavapipe without a
GPU) and by Renderer (moderngl on EGL: llvmpipe) on the same sphere, procedural sky, textures and
optional light rig. PSNR over the linear RGBA framebuffers (peak 1.0), as bench/accuracy.py.
Prints a row per element, then the minimum, the median and the worst five, and the share >= 40 dB.
bench/targets.py calls compare_images for its image column.

    .venv/bin/python bench/wgsl_images.py [DOC.mtlx ...] [--target wgsl|vulkan|slang|essl] [--corpus ../shared/corpus]
        [--size 128] [--interface specialized] [--lights rig.mtlx] [--save DIR]
"""
import argparse
import glob
import math
import os
import statistics
import sys

import numpy as np

# Both renderers' JIT (Mesa's gallivm, under llvmpipe for GL and lavapipe for Vulkan) without
# LLVM's optimisation passes. Those passes were most of a lavapipe pipeline's first frame: our
# lit standard_surface_default's SPIR-V 46.8 s with them, 2.8 s without (GL's 0.6 s), its image
# the same to the printed digit against GL (95.6 dB; brick_procedural 88.1 dB both ways); the
# constant tables' initialisers were not it (the module without them took 46.8 s too). The draw
# is the same shaders through the same driver, so the check stays an image check; set
# GALLIVM_PERF to something else (or empty) to draw with the passes. Read when Mesa starts, so
# before any renderer exists.
os.environ.setdefault("GALLIVM_PERF", "nopt")

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from accuracy import fmt_db, psnr  # noqa: E402 - the same PSNR as the other accuracy measurements

from shadergen.api import generate_file  # noqa: E402
from shadergen.render import Renderer, RenderError  # noqa: E402
from shadergen.render.wgpu_renderer import WGPU_TARGETS, WgpuRenderer  # noqa: E402
from slang_spirv import drawable  # noqa: E402

PASS_DB = 40.0
EXAMPLES = "resources/Materials/Examples/StandardSurface/*.mtlx"


DRAWN = (*WGPU_TARGETS, "slang", "essl")


def renderer_for(target: str, roots: list[str]):
    """GL draws GLSL and ESSL; WebGPU draws WGSL and SPIR-V (Vulkan's, Slang's)."""
    if target in WGPU_TARGETS or target == "slang":
        return WgpuRenderer(search_paths=roots, confined=False)
    return Renderer(search_paths=roots, confined=False)


def compare_images(documents, target: str, roots: list[str], size: int = 128, interface: str = "specialized",
                   lights: str | None = None, save: str | None = None, show=print) -> list[dict]:
    """A row per renderable element: {"document", "element", "psnr"} (NaN and "error" where either
    record failed), `target` drawn by its renderer against glsl drawn by GL; `show` prints each."""
    renderers = {"glsl": renderer_for("glsl", roots)}
    renderers[target] = renderers["glsl"] if target == "essl" else renderer_for(target, roots)
    show(f"{'document':<44} {'element':<28} {'PSNR dB':>8} {'max diff':>9} {'compile s ours/gl':>18} "
         f"{'first frame s ours/gl':>22}")
    rows = []
    for document in documents:
        records = {t: {r.get("element"): r for r in generate_file(document, target=t, all=True, interface=interface)}
                   for t in (target, "glsl", *(["vulkan"] if target == "slang" else []))}
        for element, theirs in records[target].items():
            name = os.path.basename(document)
            glsl = records["glsl"].get(element)
            failed = next((r["error"]["message"] for r in (theirs, glsl) if r is None or "error" in r), None) \
                if glsl is not None else "no glsl record"
            if failed:
                rows.append({"document": name, "element": element, "psnr": float("nan"), "error": failed})
                show(f"{name:<44} {str(element):<28} {'error':>8}  {failed[:80]}")
                continue
            if target == "slang":  # drawn as our Vulkan record of the element with Slang's SPIR-V
                try:
                    theirs = drawable(theirs, records["vulkan"][element])
                except ValueError as exc:
                    rows.append({"document": name, "element": element, "psnr": float("nan"), "error": str(exc)})
                    show(f"{name:<44} {str(element):<28} {'error':>8}  {str(exc)[:200]}")
                    continue
            images, compile_s, first_s = {}, {}, {}
            for drawn, record in (("ours", theirs), ("glsl", glsl)):
                try:
                    result = renderers[target if drawn == "ours" else "glsl"].render(record, size=size, lights=lights)
                except RenderError as exc:
                    images = None
                    rows.append({"document": name, "element": element, "psnr": float("nan"), "error": exc.message})
                    show(f"{name:<44} {str(element):<28} {'error':>8}  {drawn}: {exc.message[:200]}")
                    break
                images[drawn] = result.rgba
                compile_s[drawn] = result.timings_ms["compile_link"] / 1e3
                first_s[drawn] = result.timings_ms["first_frame"] / 1e3
            if images is None:
                continue
            if save:
                os.makedirs(save, exist_ok=True)
                for drawn, image in images.items():
                    np.save(os.path.join(save, f"{os.path.splitext(name)[0]}.{target if drawn == 'ours' else drawn}.npy"),
                            image)
            score = psnr(images["ours"], images["glsl"])
            diff = float(np.nanmax(np.abs(images["ours"] - images["glsl"])))
            rows.append({"document": name, "element": element, "psnr": score})
            show(f"{name:<44} {str(element):<28} {fmt_db(score):>8} {diff:>9.4f} "
                 f"{compile_s['ours']:>9.1f}/{compile_s['glsl']:<8.1f} {first_s['ours']:>11.1f}/{first_s['glsl']:<10.1f}")
    return rows


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("documents", nargs="*")
    p.add_argument("--corpus", default=os.path.join(os.path.dirname(os.path.dirname(HERE)), "shared", "corpus"))
    p.add_argument("--target", choices=DRAWN, default="wgsl",
                   help="the target drawn against glsl (wgsl, vulkan and slang by WebGPU, essl by GL)")
    p.add_argument("--size", type=int, default=128)
    p.add_argument("--interface", default="specialized")
    p.add_argument("--lights", help="a light rig both renderers use")
    p.add_argument("--save", metavar="DIR", help="write both images of each element as .npy")
    a = p.parse_args()
    documents = a.documents or sorted(glob.glob(os.path.join(a.corpus, EXAMPLES)))
    rows = compare_images(documents, a.target, [a.corpus], a.size, a.interface, a.lights, a.save,
                          show=lambda line: print(line, flush=True))
    scored = sorted((r for r in rows if not math.isnan(r["psnr"])), key=lambda r: r["psnr"])
    values = [r["psnr"] for r in scored]
    print()
    print(f"elements {len(rows)}, drawn by both {len(scored)}; PSNR min {fmt_db(values[0]) if values else '-'} dB, "
          f"median {fmt_db(statistics.median(values)) if values else '-'} dB; >= {PASS_DB:.0f} dB: "
          f"{sum(v >= PASS_DB for v in values)}/{len(rows)}")
    print("worst five: " + ", ".join(f"{r['document']} {fmt_db(r['psnr'])}" for r in scored[:5]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
