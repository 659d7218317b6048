#!/usr/bin/env python3
"""Run time against error of environment lighting (issue 10, item 4).

For each material, our shader and the reference's (the oracle's record), both drawn by our
Renderer on the sphere in the procedural sky, at environment sample counts 1, 4, 16, 64, 256
(filtered importance sampling) and, ours only, with the prefiltered environment
(--env-method prefilter: one lookup in the GGX-prefiltered map, our DFG table) and the hybrid
(--env-method hybrid at 2, 4, 8, 12, 16 samples: that lookup corrected by correlated samples of the
prefiltered map, a control variate); the reference's GLSL has neither. Ours is generated for each
method (generate --env-method), as render and thumbnails draw it. Each point is compared with
the same shader's converged image (--converged FIS samples, 4096 by default), as linear float
framebuffers: PSNR over the object's pixels, clipped to [0, 1] and sRGB-encoded, peak 1 (what a
viewer sees), and beside it unclipped linear HDR, peak 1 (where a highlight brighter than white,
the sun in a near-mirror, still counts); the shading models' own differences do not count, only
each one's sampling error. Frame times are the steady frame (median of frames after the first),
points measured round-robin over --rounds rounds (every configuration once per round,
interleaved), the median kept.

Goal: at the reference's 16-sample frame time, our best point that is no slower is at least 6 dB
closer to its converged image than the reference's 16 samples are to theirs (the sRGB PSNR).
Where both are closer than 8-bit quantization noise (EIGHT_BIT_DB) the table says so: no 8-bit
image can show a difference there.

    .venv/bin/python bench/accuracy_time.py [--size 64] [--rounds 3] [--plot out/accuracy_time.png]

Materials: Examples/StandardSurface carpaint, plastic, brass_tiled, gold, glass from the corpus
(../shared/corpus), and bench/documents/ (an OpenPBR and a glTF material written for this bench,
the corpus having none). The oracle runs only as a subprocess of its own venv.
"""
import argparse
import math
import os
import statistics
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))

from accuracy import SHARED, oracle_records  # noqa: E402

EXAMPLES = "resources/Materials/Examples/StandardSurface"
MATERIALS = [os.path.join("{corpus}", EXAMPLES, f"standard_surface_{name}.mtlx")
             for name in ("carpaint", "plastic", "brass_tiled", "gold", "glass")] + [
    os.path.join(HERE, "documents", "open_pbr_coated_metal.mtlx"),
    os.path.join(HERE, "documents", "gltf_pbr_painted.mtlx")]
SAMPLE_COUNTS = (1, 4, 16, 64, 256)
HYBRID_COUNTS = (2, 4, 8, 12, 16)
ENV_METHODS = ("fis", "prefilter", "hybrid")
SHADERS = ("ours", "reference")
GOAL_SAMPLES, GOAL_DB = 16, 6.0
# PSNR of uniform quantization noise at 8 bits (step 1/255, variance step^2 / 12): an error below
# it disappears when the image is stored as 8 bits per channel.
EIGHT_BIT_DB = 10.0 * math.log10(12.0 * 255.0 ** 2)


def psnr(image: np.ndarray, converged: np.ndarray, viewed: bool = True) -> float:
    """Over the object's pixels, peak 1: `viewed` clipped to [0, 1] and sRGB-encoded (what a viewer
    sees), else the linear HDR values as they are."""
    from shadergen.render.imageio import srgb_encode

    covered = converged[..., 3] > 0
    rgb = [np.nan_to_num(x[..., :3].astype("f8")) for x in (image, converged)]
    if viewed:
        rgb = [srgb_encode(np.clip(x, 0.0, 1.0)) for x in rgb]
    mse = float(((rgb[0] - rgb[1])[covered] ** 2).mean())
    return float("inf") if mse == 0 else 10.0 * math.log10(1.0 / mse)


def points(shader: str) -> list[tuple[str, int]]:
    """(env_method, samples) measured for a shader; prefilter ignores the sample count."""
    fis = [("fis", n) for n in SAMPLE_COUNTS]
    return fis + [("prefilter", 1)] + [("hybrid", n) for n in HYBRID_COUNTS] if shader == "ours" else fis


def label(method: str, samples: int) -> str:
    return "prefilter" if method == "prefilter" else f"{method} {samples}"


def records(document: str, interface: str) -> dict[tuple[str, str], dict]:
    """(shader, env_method) -> record: ours generated for each method in `interface`, the
    reference's (FIS only, every input a uniform: as `complete`)."""
    from shadergen.api import generate_file

    shaders = {}
    for method in ENV_METHODS:
        record = generate_file(document, environment=method, interface=interface)[0]
        if "error" in record:
            raise SystemExit(f"{document}: {record['error']}")
        shaders[("ours", method)] = record
    element = shaders[("ours", "fis")]["element"]
    reference = [r for r in oracle_records(document, os.path.dirname(document)) if "error" not in r]
    matching = [r for r in reference if r.get("element") == element] or reference
    if not matching:
        raise SystemExit(f"the oracle gave no record for {document}")
    shaders[("reference", "fis")] = matching[0]
    return shaders


def measure(renderer, document: str, args) -> list[dict]:
    shaders = records(document, args.interface)
    render_options = dict(size=args.size, document_dir=os.path.dirname(document))
    converged = {name: renderer.render(shaders[(name, "fis")], env_samples=args.converged, **render_options).rgba
                 for name in SHADERS}
    times: dict[tuple, list[float]] = {}
    images: dict[tuple, np.ndarray] = {}
    for _ in range(args.rounds):
        for name in SHADERS:
            for method, samples in points(name):
                result = renderer.render(shaders[(name, method)], env_method=method, env_samples=samples,
                                         frames=args.frames, **render_options)
                times.setdefault((name, method, samples), []).append(result.timings_ms["frame"])
                images[(name, method, samples)] = result.rgba
    element = shaders[("ours", "fis")]["element"]
    rows = [{"material": element, "shader": name, "method": method, "samples": samples,
             "frame_ms": statistics.median(times[(name, method, samples)]),
             "psnr": psnr(images[(name, method, samples)], converged[name]),
             "psnr_hdr": psnr(images[(name, method, samples)], converged[name], viewed=False)}
            for name in SHADERS for method, samples in points(name)]
    rows.append({"material": element, "shader": "ours vs reference", "method": "converged",
                 "samples": args.converged, "frame_ms": float("nan"),
                 "psnr": psnr(converged["ours"], converged["reference"]),
                 "psnr_hdr": psnr(converged["ours"], converged["reference"], viewed=False)})
    return rows


def goal(rows: list[dict]) -> dict:
    """Our best point no slower than the reference's GOAL_SAMPLES, against that point."""
    reference = next(r for r in rows if r["shader"] == "reference" and r["samples"] == GOAL_SAMPLES)
    ours = [r for r in rows if r["shader"] == "ours" and r["frame_ms"] <= reference["frame_ms"]]
    best = max(ours, key=lambda r: r["psnr"]) if ours else None
    gain = best["psnr"] - reference["psnr"] if best else float("nan")
    below_8bit = best is not None and min(best["psnr"], reference["psnr"]) >= EIGHT_BIT_DB
    return {"material": reference["material"], "budget_ms": reference["frame_ms"], "reference_db": reference["psnr"],
            "reference_hdr_db": reference["psnr_hdr"], "ours": best, "gain": gain, "met": gain >= GOAL_DB,
            "below_8bit": below_8bit}


def fmt(value: float, digits: int = 1) -> str:
    return "inf" if value == float("inf") else "-" if math.isnan(value) else f"{value:.{digits}f}"


def print_tables(all_rows: list[dict], goals: list[dict], args) -> None:
    print(f"# steady frame time and PSNR against each shader's {args.converged}-sample render "
          f"({args.size}x{args.size}, ours {args.interface}, median of {args.rounds} interleaved rounds of {args.frames} frames)")
    print(f"{'material':<28} {'shader':<18} {'point':<10} {'frame ms':>9} {'PSNR dB':>8} {'HDR dB':>7}")
    for r in all_rows:
        print(f"{r['material']:<28} {r['shader']:<18} {label(r['method'], r['samples']):<10} "
              f"{fmt(r['frame_ms'], 2):>9} {fmt(r['psnr']):>8} {fmt(r['psnr_hdr']):>7}")
    print()
    print(f"# goal: at the reference's {GOAL_SAMPLES}-sample frame time, ours >= {GOAL_DB:.0f} dB closer to converged "
          f"(sRGB PSNR; HDR: the linear PSNR of the same points); 8-bit: both closer than 8-bit quantization noise "
          f"({EIGHT_BIT_DB:.1f} dB)")
    print(f"{'material':<28} {'ref 16 ms':>9} {'ref 16 dB':>9} {'ours point':<10} {'ours ms':>8} {'ours dB':>8} "
          f"{'gain dB':>8} {'met':>4} {'8-bit':>5} {'HDR gain':>8}")
    for g in goals:
        best = g["ours"] or {"method": "-", "samples": 0, "frame_ms": float("nan"), "psnr": float("nan"),
                             "psnr_hdr": float("nan")}
        print(f"{g['material']:<28} {fmt(g['budget_ms'], 2):>9} {fmt(g['reference_db']):>9} "
              f"{label(best['method'], best['samples']) if g['ours'] else '-':<10} {fmt(best['frame_ms'], 2):>8} "
              f"{fmt(best['psnr']):>8} {fmt(g['gain']):>8} {'yes' if g['met'] else 'no':>4} "
              f"{'yes' if g['below_8bit'] else '':>5} {fmt(best['psnr_hdr'] - g['reference_hdr_db']):>8}")
    met = sum(g["met"] for g in goals)
    invisible = sum(g["below_8bit"] and not g["met"] for g in goals)
    print(f"goal met for {met} of {len(goals)} materials; of the others, {invisible} where the reference's "
          f"{GOAL_SAMPLES} samples and ours are both below 8-bit quantization noise")


def plot(all_rows: list[dict], path: str, args) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    materials = list(dict.fromkeys(r["material"] for r in all_rows))
    columns = 4
    rows_n = math.ceil(len(materials) / columns)
    fig, axes = plt.subplots(rows_n, columns, figsize=(4.2 * columns, 3.4 * rows_n), squeeze=False)
    for ax, material in zip(axes.flat, materials):
        for shader, colour in (("ours", "tab:blue"), ("reference", "tab:orange")):
            fis = [r for r in all_rows if r["material"] == material and r["shader"] == shader and r["method"] == "fis"]
            ax.plot([r["frame_ms"] for r in fis], [r["psnr"] for r in fis], "o-", color=colour, label=f"{shader} FIS")
            for r in fis:
                ax.annotate(str(r["samples"]), (r["frame_ms"], r["psnr"]), fontsize=7, xytext=(3, -9),
                            textcoords="offset points", color=colour)
        hybrid = [r for r in all_rows if r["material"] == material and r["method"] == "hybrid"]
        ax.plot([r["frame_ms"] for r in hybrid], [r["psnr"] for r in hybrid], "s-", color="tab:purple",
                label="ours hybrid")
        for r in hybrid:
            ax.annotate(str(r["samples"]), (r["frame_ms"], r["psnr"]), fontsize=7, xytext=(3, 4),
                        textcoords="offset points", color="tab:purple")
        for r in all_rows:
            if r["material"] == material and r["method"] == "prefilter":
                ax.plot([r["frame_ms"]], [r["psnr"]], "*", markersize=14, color="tab:green", label="ours prefilter")
        reference16 = next(r for r in all_rows if r["material"] == material and r["shader"] == "reference"
                            and r["samples"] == GOAL_SAMPLES)
        ax.axvline(reference16["frame_ms"], color="grey", linestyle="--", linewidth=0.8)
        ax.axhline(reference16["psnr"] + GOAL_DB, color="grey", linestyle=":", linewidth=0.8)
        ax.set_xscale("log")
        ax.set_title(material, fontsize=9)
        ax.set_xlabel("steady frame, ms (log)", fontsize=8)
        ax.set_ylabel("PSNR vs converged, dB", fontsize=8)
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(materials):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7, loc="lower right")
    fig.suptitle(f"Environment lighting: error against time ({args.size}x{args.size}, ours {args.interface}; dashed: reference's "
                 f"{GOAL_SAMPLES}-sample time, dotted: its PSNR + {GOAL_DB:.0f} dB)", fontsize=10)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--corpus", default=os.path.join(SHARED, "corpus"))
    parser.add_argument("--size", type=int, default=64, help="image side in pixels")
    parser.add_argument("--converged", type=int, default=4096, help="samples of the converged render")
    parser.add_argument("--rounds", type=int, default=3, help="interleaved rounds of every configuration")
    parser.add_argument("--frames", type=int, default=3, help="frames drawn per render (the first is not timed)")
    parser.add_argument("--plot", default=os.path.join(os.path.dirname(HERE), "out", "accuracy_time.png"))
    parser.add_argument("--filter", default="", help="only materials whose file name contains this")
    parser.add_argument("--interface", default="complete", choices=["complete", "specialized"],
                        help="our shaders' interface: complete keeps every input a uniform, as the reference's "
                             "shader does; specialized is what `shadergen render` and thumbnails draw")
    args = parser.parse_args()

    from shadergen.render import Renderer

    documents = [m.format(corpus=os.path.abspath(args.corpus)) for m in MATERIALS]
    documents = [d for d in documents if args.filter in os.path.basename(d)]
    missing = [d for d in documents if not os.path.exists(d)]
    if missing:
        raise SystemExit(f"missing documents (is ../shared/corpus there?): {', '.join(missing)}")
    renderer = Renderer(confined=False)
    all_rows, goals = [], []
    for document in documents:
        rows = measure(renderer, document, args)
        all_rows += rows
        goals.append(goal(rows))
        print(f"measured {rows[0]['material']}", file=sys.stderr)
    print_tables(all_rows, goals, args)
    plot(all_rows, args.plot, args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
