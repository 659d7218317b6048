#!/usr/bin/env python3
"""Render accuracy, image against image (issue 4). Two measurements:

  renderer   Same shader, two renderers: the oracle's record drawn by `shadergen render --record`
             against ../shared/oracle/mx_refrender.py drawing the same document, both lit by the
             environment mx_refrender saved (--save-env), per Examples/StandardSurface material.
             Prints PSNR, max difference, NaN/Inf pixels and timings (compile+link, first frame,
             steady frame at --size) of both renderers, measured in this run, Mesa's shader
             cache off.
  generator  Our shader against the reference shader, one renderer: every renderable element of
             TestSuite/stdlib (or the documents --documents names), our record (shadergen.api) and the oracle's drawn by our Renderer
             the same way. Prints the PSNR distribution, the share >= 40 dB and the worst ten.

  interfaces Our `specialized` shader against our `complete` one (same values, same renderer, same
             environment), every renderable element of the documents given: specialized must not change
             the image (>= 60 dB). Prints the minimum, the worst five, the count under 60 dB.

PSNR is over the linear RGBA framebuffers (peak 1.0); identical images print "inf".

  .venv/bin/python bench/accuracy.py renderer  [--corpus ../shared/corpus] [--out DIR] [--size 256]
  .venv/bin/python bench/accuracy.py generator [--corpus ../shared/corpus] [--filter math] [--json out.json]
  .venv/bin/python bench/accuracy.py generator --documents 'resources/Materials/Examples/**/*.mtlx' \
      'resources/Materials/TestSuite/pbrlib/surfaceshader/chiang_hair*.mtlx'
  .venv/bin/python bench/accuracy.py interfaces --documents 'resources/Materials/**/*.mtlx'

The oracle runs only as a subprocess of its own venv ($ORACLE_VENV, default ~/.cache/mx-oracle/venv).
"""
import argparse
import glob
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# ../shared beside the checkout; $SHADERGEN_SHARED where the checkout is elsewhere (a git worktree)
SHARED = os.environ.get("SHADERGEN_SHARED", os.path.join(os.path.dirname(ROOT), "shared"))
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
ORACLE = os.path.join(SHARED, "oracle", "mx_oracle.py")
REFRENDER = os.path.join(SHARED, "oracle", "mx_refrender.py")
PASS_DB = {"renderer": 50.0, "generator": 40.0}
# Timings compare compilers, not caches: Mesa would otherwise reuse a program the other renderer built.
NO_SHADER_CACHE = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true")


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    """Non-finite pixels read as 0 in both images, so a NaN both shaders produce at the same pixel
    is a match (it is still counted, separately) and a NaN only one produces is a difference."""
    a, b = (np.nan_to_num(x.astype("f8"), nan=0.0, posinf=0.0, neginf=0.0) for x in (a, b))
    mse = float(np.mean((a - b) ** 2))
    return float("inf") if mse == 0 else 10.0 * math.log10(1.0 / mse)


def bad_pixels(rgba: np.ndarray) -> int:
    return int((~np.isfinite(rgba)).any(axis=2).sum())


def oracle_records(document: str, cwd: str) -> list[dict]:
    """The reference generator's records for every renderable element (one document per process:
    the oracle stops at the first document it cannot list)."""
    run = subprocess.run([ORACLE_PY, ORACLE, document, "--all"], capture_output=True, text=True, cwd=cwd)
    records = [json.loads(line) for line in run.stdout.splitlines() if line.strip()]
    if run.returncode != 0 and not records:
        tail = run.stderr.strip().splitlines()[-1:] or ["no output"]
        return [{"document": document, "element": None, "error": {"code": "oracle_crashed", "message": tail[0]}}]
    return records


def fmt_db(value: float) -> str:
    return "inf" if value == float("inf") else "nan" if math.isnan(value) else f"{value:.1f}"


# -- measurement 1: one shader, two renderers ----------------------------------------------------------

def measure_renderer(args) -> int:
    corpus = os.path.abspath(args.corpus)
    documents = sorted(glob.glob(os.path.join(corpus, "resources/Materials/Examples/StandardSurface/*.mtlx")))
    out = args.out or tempfile.mkdtemp(prefix="accuracy-renderer-")
    env_dir = os.path.join(out, "env")
    os.makedirs(env_dir, exist_ok=True)
    # mx_refrender's procedural sky, saved once; both renderers then read the same two files.
    subprocess.run([ORACLE_PY, REFRENDER, documents[0], "-o", os.path.join(out, "envprobe.png"), "--size", "8",
                    "--repeat", "1", "--save-env", env_dir], check=True, capture_output=True, cwd=corpus)
    env = ["--env", os.path.join(env_dir, "radiance.hdr"), "--irr", os.path.join(env_dir, "irradiance.hdr")]
    rows = []
    for document in documents:
        name = os.path.splitext(os.path.basename(document))[0]
        record = oracle_records(document, corpus)[0]
        record_path = os.path.join(out, f"{name}.oracle.json")
        with open(record_path, "w") as f:
            json.dump(record, f)
        ref_npy, our_npy = os.path.join(out, f"{name}.ref.npy"), os.path.join(out, f"{name}.ours.npy")
        ref = subprocess.run([ORACLE_PY, REFRENDER, document, "-o", os.path.join(out, f"{name}.ref.png"), "--npy", ref_npy,
                              "--size", str(args.size), "--repeat", str(args.repeat), *env],
                             capture_output=True, text=True, cwd=corpus, env=NO_SHADER_CACHE)
        ours = subprocess.run([sys.executable, "-m", "shadergen.cli", "render", "--record", record_path,
                               "-o", os.path.join(out, f"{name}.ours.png"), "--npy", our_npy, "--size", str(args.size),
                               "--repeat", str(args.repeat), "--search-path", corpus, "--json", *env],
                              capture_output=True, text=True, cwd=corpus, env=NO_SHADER_CACHE)
        row = {"material": name, "element": record.get("element")}
        if "error" in record or ref.returncode != 0:  # nothing to measure against
            row["skipped"] = (record.get("error") or {}).get("message") or ref.stderr.strip().splitlines()[-1:]
            rows.append(row)
            continue
        if ours.returncode != 0:
            row["error"] = ours.stderr.strip().splitlines()[-1:]
            rows.append(row)
            continue
        a, b = np.load(our_npy), np.load(ref_npy)
        timing = re.search(r"compile\+link ([\d.]+)s.*median ([\d.]+) ms.*first ([\d.]+) ms", ref.stderr)
        ours_t = json.loads(ours.stdout)["timings_ms"]
        row.update(psnr=psnr(a, b), max_diff=float(np.nanmax(np.abs(a - b))), nan_ours=bad_pixels(a), nan_ref=bad_pixels(b),
                   ours_ms=(ours_t["compile_link"], ours_t["first_frame"], ours_t["frame"]),
                   ref_ms=(float(timing[1]) * 1e3, float(timing[3]), float(timing[2])))
        rows.append(row)
        print(f"  {name}: {fmt_db(row['psnr'])} dB", file=sys.stderr)
    print(f"\nSame shader (oracle record), two renderers; {args.size}x{args.size}, environment {env_dir}; images in {out}\n")
    print("| material | PSNR dB | max abs diff | NaN/Inf ours | NaN/Inf ref | compile+link ms ours / ref | "
          "first frame ms ours / ref | frame ms ours / ref |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        if "skipped" in r or "error" in r:
            label = f"not measured, the reference cannot render it: {r['skipped']}" if "skipped" in r else f"ours failed: {r['error']}"
            print(f"| {r['material']} | {label} |||||||")
            continue
        o, f = r["ours_ms"], r["ref_ms"]
        print(f"| {r['material']} | {fmt_db(r['psnr'])} | {r['max_diff']:.2e} | {r['nan_ours']} | {r['nan_ref']} | "
              f"{o[0]:.0f} / {f[0]:.0f} | {o[1]:.0f} / {f[1]:.0f} | {o[2]:.0f} / {f[2]:.0f} |")
    measured = [r for r in rows if "skipped" not in r]
    good = [r for r in measured if "error" not in r]
    passed = sum(r["psnr"] >= PASS_DB["renderer"] for r in good)
    if good:
        ratio = lambda k: statistics.median(r["ours_ms"][k] / r["ref_ms"][k] for r in good)
        print(f"\n{passed}/{len(measured)} measured materials >= {PASS_DB['renderer']:.0f} dB "
              f"({len(rows) - len(measured)} not measurable); NaN/Inf pixels: "
              f"{sum(r['nan_ours'] + r['nan_ref'] for r in good)}; median time ratio ours/ref: "
              f"compile+link {ratio(0):.2f}, first frame {ratio(1):.2f}, frame {ratio(2):.2f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0 if measured and passed == len(measured) else 1


# -- measurement 2: two shaders, one renderer ----------------------------------------------------------

def corpus_documents(args):
    """(corpus, the documents --documents and --filter select, a Renderer finding their textures)."""
    sys.path.insert(0, ROOT)
    from shadergen.render import Renderer

    corpus = os.path.abspath(args.corpus)
    documents = sorted({d for pattern in args.documents for d in glob.glob(os.path.join(corpus, pattern), recursive=True)})
    return corpus, [d for d in documents if not args.filter or args.filter in d], Renderer(search_paths=[corpus])


def measure_generator(args) -> int:
    corpus, documents, renderer = corpus_documents(args)
    from shadergen.api import generate_file
    from shadergen.render import RenderError

    rows = []

    def draw(record, document):
        """(rgba, problem): a render of the record, or why there is none."""
        if "error" in record:
            return None, f"{record['error'].get('code')}: {record['error'].get('message', '')[:120]}"
        try:
            return renderer.render(record, size=args.size, document_dir=os.path.dirname(document)).rgba, None
        except RenderError as exc:
            return None, f"{exc.code}: {exc.message.splitlines()[0][:120]}"

    for document in documents:
        relative = os.path.relpath(document, corpus)
        reference = {r.get("element"): r for r in oracle_records(document, corpus)}
        try:
            ours = {r.get("element"): r for r in generate_file(document, target="glsl", all=True)}
        except Exception as exc:  # the generator's bug is a result here, not the end of the run
            ours = {}
            print(f"  {relative}: generator raised {type(exc).__name__}: {exc}", file=sys.stderr)
        unlisted = reference.pop(None, None)  # the oracle failed on the whole document
        for element in sorted(set(reference) | set(ours), key=str):
            row = {"document": relative, "element": element}
            if unlisted and element not in reference:
                row["skipped"] = f"reference: {unlisted['error'].get('message', '')[:120]}"
                rows.append(row)
                continue
            if element not in reference or element not in ours:
                row["problem"] = "only the " + ("reference" if element in reference else "generator") + " lists this element"
                rows.append(row)
                continue
            ref_rgba, ref_problem = draw(reference[element], document)
            if ref_problem:  # the reference cannot be drawn: nothing to measure against
                row["skipped"] = f"reference: {ref_problem}"
                rows.append(row)
                continue
            our_rgba, our_problem = draw(ours[element], document)
            row["nan_ref"] = bad_pixels(ref_rgba)
            if our_problem:
                row["problem"] = f"ours: {our_problem}"
            else:
                row.update(psnr=psnr(our_rgba, ref_rgba), nan_ours=bad_pixels(our_rgba))
            rows.append(row)
        done = [r for r in rows if r["document"] == relative]
        print(f"  {relative}: {len(done)} elements", file=sys.stderr)
    return report_generator(rows, args)


def measure_interfaces(args) -> int:
    corpus, documents, renderer = corpus_documents(args)
    from shadergen.api import generate_file
    from shadergen.render import RenderError

    rows, undrawable = [], 0
    for document in documents:
        relative = os.path.relpath(document, corpus)
        records = {i: {r.get("element"): r for r in generate_file(document, all=True, interface=i)}
                   for i in ("complete", "specialized")}
        for element, complete in records["complete"].items():
            specialized = records["specialized"].get(element, {"error": {"code": "missing"}})
            if "error" in complete:
                continue  # not renderable by us at all: nothing to compare
            try:
                a = renderer.render(complete, size=args.size, document_dir=os.path.dirname(document)).rgba
            except RenderError:
                undrawable += 1
                continue
            row = {"document": relative, "element": element,
                   "lines": (complete["stages"]["pixel"].count("\n"),
                             specialized.get("stages", {}).get("pixel", "").count("\n"))}
            try:
                row["psnr"] = psnr(renderer.render(specialized, size=args.size,
                                                   document_dir=os.path.dirname(document)).rgba, a) \
                    if "error" not in specialized else float("-inf")
            except RenderError as exc:
                row["psnr"], row["problem"] = float("-inf"), exc.code
            rows.append(row)
        print(f"  {relative}", file=sys.stderr)
    scores = sorted(rows, key=lambda r: r["psnr"])
    under = [r for r in rows if r["psnr"] < 60.0]
    print(f"\nspecialized vs complete, same renderer and values, {args.size}x{args.size}: {len(rows)} elements "
          f"drawn ({undrawable} that complete itself cannot draw left out)")
    print(f"minimum PSNR {fmt_db(scores[0]['psnr']) if scores else '-'} dB; under 60 dB: {len(under)}; identical: "
          f"{sum(r['psnr'] == float('inf') for r in rows)}; fragment lines total complete "
          f"{sum(r['lines'][0] for r in rows)}, specialized {sum(r['lines'][1] for r in rows)}")
    print("\nWorst five:\n\n| document | element | PSNR dB |\n|---|---|---:|")
    for r in scores[:5]:
        print(f"| {r['document']} | {r['element']} | {fmt_db(r['psnr'])} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0 if rows and not under else 1


def report_generator(rows: list[dict], args) -> int:
    measured = [r for r in rows if "skipped" not in r]
    scores = [r.get("psnr", float("-inf")) for r in measured]  # no image of ours counts as the worst
    passing = sum(s >= PASS_DB["generator"] for s in scores)
    print(f"\nOur shader vs the reference shader, one renderer, {args.size}x{args.size}: "
          f"{len(measured)} elements measured ({len(rows) - len(measured)} skipped: the reference itself cannot be drawn)\n")
    bins = [("inf (identical)", lambda s: s == float("inf")), (">= 60", lambda s: 60 <= s < float("inf")),
            ("50-60", lambda s: 50 <= s < 60), ("40-50", lambda s: 40 <= s < 50), ("30-40", lambda s: 30 <= s < 40),
            ("20-30", lambda s: 20 <= s < 30), ("< 20", lambda s: float("-inf") < s < 20),
            ("no image of ours / element missing", lambda s: s == float("-inf"))]
    print("| PSNR dB | elements |\n|---|---:|")
    for label, test in bins:
        print(f"| {label} | {sum(map(test, scores))} |")
    finite = [s for s in scores if math.isfinite(s)]
    share = 100.0 * passing / len(measured) if measured else 0.0
    print(f"\n>= {PASS_DB['generator']:.0f} dB: {passing}/{len(measured)} = {share:.1f} % (target 95 %); "
          f"median of finite PSNRs {statistics.median(finite) if finite else float('nan'):.1f} dB; "
          f"NaN/Inf pixels ours {sum(r.get('nan_ours', 0) for r in measured)}, reference {sum(r.get('nan_ref', 0) for r in measured)}")
    failures = {}
    for r in measured:
        if "problem" in r:
            failures.setdefault(r["problem"][:100], []).append(r["element"])
    if failures:
        print("\nNo image of ours, by cause:\n\n| elements | cause | e.g. |\n|---:|---|---|")
        for cause, elements in sorted(failures.items(), key=lambda kv: -len(kv[1])):
            print(f"| {len(elements)} | {cause} | {elements[0]} |")
    print("\nWorst ten drawn by both:\n\n| document | element | PSNR dB |\n|---|---|---:|")
    for r in sorted((r for r in measured if "psnr" in r), key=lambda r: r["psnr"])[:10]:
        print(f"| {r['document']} | {r['element']} | {fmt_db(r['psnr'])} |")
    broken = [r for r in measured if r.get("nan_ours") or r.get("nan_ref")]
    if broken:
        print("\nNaN/Inf pixels: " + "; ".join(f"{r['document']}:{r['element']} (ours {r.get('nan_ours', '-')}, "
                                                f"reference {r.get('nan_ref', '-')})" for r in broken))
    skipped = [r for r in rows if "skipped" in r]
    if skipped:
        print(f"\nSkipped ({len(skipped)}): " + "; ".join(f"{r['document']}:{r['element']} ({r['skipped']})" for r in skipped[:10])
              + (" ..." if len(skipped) > 10 else ""))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0 if measured and share >= 95.0 else 1


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("measurement", choices=["renderer", "generator", "interfaces"])
    parser.add_argument("--corpus", default=os.path.join(SHARED, "corpus"))
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--repeat", type=int, default=5, help="frames timed per render (renderer measurement)")
    parser.add_argument("--documents", nargs="+", default=["resources/Materials/TestSuite/stdlib/**/*.mtlx"],
                        help="globs of the documents below the corpus (generator and interfaces)")
    parser.add_argument("--filter", help="only documents whose path contains this (generator measurement)")
    parser.add_argument("--out", help="keep records and images here (renderer measurement)")
    parser.add_argument("--json", help="also write the per-element results here")
    args = parser.parse_args()
    return {"renderer": measure_renderer, "generator": measure_generator,
            "interfaces": measure_interfaces}[args.measurement](args)


if __name__ == "__main__":
    sys.exit(main())
