#!/usr/bin/env python3
"""Time to thumbnail (issue 9): ours `complete`, ours `specialized` and the reference, interleaved.

For every Examples material under the corpus folder given, in one run, each of the three is a
whole process that generates, compiles and links, and draws the thumbnail at --size with Mesa's
shader cache off: `shadergen render DOC --interface complete|specialized` and
../shared/oracle/mx_refrender.py DOC. The order of the three rotates from one material to the next,
so that the machine's load drifts over all of them alike. Per run: whole-process time, compile+link,
first frame, a steady frame (median of --frames), and the fragment shader's lines. Prints a table
per material (medians over --runs) and the median of each column with its ratio to the reference.

  .venv/bin/python bench/thumbnail.py ../shared/corpus/resources/Materials/Examples [--runs 3] [--size 256]
"""
import argparse
import glob
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(os.path.dirname(ROOT), "shared")
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
REFRENDER = os.path.join(SHARED, "oracle", "mx_refrender.py")
SHADERGEN = os.path.join(os.path.dirname(sys.executable), "shadergen")
NO_SHADER_CACHE = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true")
COLUMNS = ("total_ms", "compile_link_ms", "first_frame_ms", "frame_ms", "frag_lines")
REFERENCE_TIMING = re.compile(r"compile\+link ([\d.]+)s\s+frame\(.*?\) median ([\d.]+) ms over \d+\s+first ([\d.]+) ms")
REFERENCE_LINES = re.compile(r"frag=(\d+)")


def ours(document: str, interface: str, args, out_dir: str) -> dict:
    png = os.path.join(out_dir, f"{interface}.png")
    cmd = [SHADERGEN, "render", document, "-o", png, "--size", str(args.size), "--interface", interface,
           "--repeat", str(args.frames), "--json", "--search-path", args.corpus_root]
    t0 = time.perf_counter()
    run = subprocess.run(cmd, capture_output=True, text=True, env=NO_SHADER_CACHE)
    total = (time.perf_counter() - t0) * 1e3
    if run.returncode != 0:
        return {"error": (run.stdout + run.stderr).strip().splitlines()[-1:]}
    t = json.loads(run.stdout.strip().splitlines()[-1])["timings_ms"]
    return {"total_ms": total, "compile_link_ms": t["compile_link"], "first_frame_ms": t["first_frame"],
            "frame_ms": t["frame"]}


def reference(document: str, args, out_dir: str) -> dict:
    cmd = [ORACLE_PY, REFRENDER, document, "-o", os.path.join(out_dir, "reference.png"), "--size", str(args.size),
           "--repeat", str(args.frames)]
    t0 = time.perf_counter()
    run = subprocess.run(cmd, capture_output=True, text=True, env=NO_SHADER_CACHE, cwd=args.corpus_root)
    total = (time.perf_counter() - t0) * 1e3
    timing, lines = REFERENCE_TIMING.search(run.stderr), REFERENCE_LINES.search(run.stderr)
    if run.returncode != 0 or timing is None:
        return {"error": run.stderr.strip().splitlines()[-1:]}
    return {"total_ms": total, "compile_link_ms": float(timing.group(1)) * 1e3, "frame_ms": float(timing.group(2)),
            "first_frame_ms": float(timing.group(3)), "frag_lines": int(lines.group(1)) if lines else None}


def fragment_lines(document: str, interface: str) -> int | None:
    """Lines of the fragment shader `shadergen render` compiled: generated for the lighting it draws
    with (fis, no light rig). Newlines are counted, as the reference's count is, comments and blank
    lines included."""
    sys.path.insert(0, ROOT)
    from shadergen.api import generate_file
    records = [r for r in generate_file(document, interface=interface, environment="fis", lights=False)
               if "stages" in r]
    return records[0]["stages"]["pixel"].count("\n") if records else None


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("examples", help="folder of Examples materials (searched recursively for .mtlx)")
    ap.add_argument("--runs", type=int, default=1, help="interleaved runs per material (median reported)")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--frames", type=int, default=5, help="frames drawn per run: the first, then a steady median")
    ap.add_argument("--filter", default="", help="only documents whose path contains this")
    ap.add_argument("--json", help="write every measurement here")
    args = ap.parse_args()
    documents = sorted(d for d in glob.glob(os.path.join(os.path.abspath(args.examples), "**", "*.mtlx"), recursive=True)
                       if args.filter in d)
    if not documents:
        ap.error(f"no .mtlx documents under {args.examples!r}" + (f" matching {args.filter!r}" if args.filter else ""))
    # the corpus root: documents name textures relative to it (resources/Images/...)
    args.corpus_root = os.path.abspath(os.path.join(args.examples, *([".."] * 3))) \
        if "resources" in os.path.abspath(args.examples) else os.path.dirname(os.path.abspath(args.examples))
    kinds = ("complete", "specialized", "reference")
    rows = []
    with tempfile.TemporaryDirectory() as out_dir:
        for k, document in enumerate(documents):
            runs = {kind: [] for kind in kinds}
            for r in range(args.runs):
                order = kinds[(k + r) % 3:] + kinds[:(k + r) % 3]
                for kind in order:
                    runs[kind].append(reference(document, args, out_dir) if kind == "reference"
                                      else ours(document, kind, args, out_dir))
            row = {"document": os.path.relpath(document, args.examples)}
            for kind in kinds:
                ok = [m for m in runs[kind] if "error" not in m]
                if not ok:
                    row[kind] = {"error": runs[kind][0]["error"]}
                    continue
                row[kind] = {c: statistics.median(m[c] for m in ok) for c in COLUMNS if c != "frag_lines"}
                row[kind]["frag_lines"] = ok[0].get("frag_lines") if kind == "reference" \
                    else fragment_lines(document, kind)
            rows.append(row)
            print(f"  {row['document']}: " + ", ".join(
                f"{kind} {row[kind].get('total_ms', float('nan')):.0f} ms" for kind in kinds), file=sys.stderr)
    report(rows, args)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


def report(rows: list[dict], args) -> None:
    kinds = ("complete", "specialized", "reference")
    print(f"\nTime to thumbnail, {len(rows)} materials, {args.size}x{args.size}, MESA_SHADER_CACHE_DISABLE=true, "
          f"{args.runs} interleaved run(s) each (median per material)\n")
    print("| material | " + " | ".join(f"{k} total ms | {k} compile+link ms | {k} frag lines" for k in kinds) + " |")
    print("|---|" + "---:|" * 9)
    for row in rows:
        cells = []
        for kind in kinds:
            m = row[kind]
            cells += ["error"] * 3 if "error" in m else \
                [f"{m['total_ms']:.0f}", f"{m['compile_link_ms']:.0f}", str(m['frag_lines'])]
        print(f"| {row['document']} | " + " | ".join(cells) + " |")
    complete_rows = [r for r in rows if all("error" not in r[k] for k in kinds)]
    print(f"\nMedians over the {len(complete_rows)} materials all three drew; ratio = median of per-material "
          "ratios to the reference\n")
    print("| median | ours complete | ours specialized | reference | complete / ref | specialized / ref |")
    print("|---|---:|---:|---:|---:|---:|")
    labels = {"total_ms": "time to thumbnail, whole process (ms)", "compile_link_ms": "compile + link (ms)",
              "first_frame_ms": "first frame (ms)", "frame_ms": "steady frame (ms)", "frag_lines": "fragment lines"}
    for column in COLUMNS:
        values = {k: [r[k][column] for r in complete_rows if r[k].get(column) is not None] for k in kinds}
        ratios = {k: [r[k][column] / r["reference"][column] for r in complete_rows
                      if r[k].get(column) is not None and r["reference"].get(column)] for k in kinds[:2]}
        med = {k: statistics.median(v) if v else float("nan") for k, v in values.items()}
        rat = {k: statistics.median(v) if v else float("nan") for k, v in ratios.items()}
        print(f"| {labels[column]} | {med['complete']:.0f} | {med['specialized']:.0f} | {med['reference']:.0f} | "
              f"{rat['complete']:.2f} | {rat['specialized']:.2f} |")


if __name__ == "__main__":
    sys.exit(main())
