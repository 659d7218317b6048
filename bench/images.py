#!/usr/bin/env python3
"""Images unchanged by a change to the generator or the libraries: render, then compare.

`render` draws every material under a folder of documents (the Examples by default) with our
shader of one interface (`complete` unless --interface says otherwise), once under the environment alone and once with a light rig as well, into a
folder of linear .npy images; `compare` prints the PSNR of each image of one such folder against
the same image of another and fails when any is below --min-psnr. Render the baseline from the
tree before the change (a checkout of main: `--tree`), then the change, then compare.

  .venv/bin/python bench/images.py render /tmp/before --tree /tmp/main-checkout
  .venv/bin/python bench/images.py render /tmp/after
  .venv/bin/python bench/images.py compare /tmp/before /tmp/after [--min-psnr 60]
"""
import argparse
import glob
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CORPUS = os.path.join(os.path.dirname(ROOT), "shared", "corpus")
EXAMPLES = os.path.join(CORPUS, "resources", "Materials", "Examples")
LIGHTS = os.path.join(CORPUS, "resources", "Lights", "san_giuseppe_bridge_split.mtlx")
SCENES = {"env": [], "lights": ["--lights", LIGHTS]}


def documents(folder: str) -> list[str]:
    return sorted(glob.glob(os.path.join(os.path.abspath(folder), "**", "*.mtlx"), recursive=True))


def render(args) -> int:
    """Each image from a process of its own, running the shadergen of --tree (default: this one)."""
    env = dict(os.environ, PYTHONPATH=os.path.abspath(args.tree))
    failed = 0
    for document in documents(args.examples):
        for scene, extra in SCENES.items():
            out = os.path.join(args.out, scene, os.path.relpath(document, args.examples) + ".npy")
            os.makedirs(os.path.dirname(out), exist_ok=True)
            cmd = [sys.executable, "-m", "shadergen.cli", "render", document, "--interface", args.interface,
                   "--npy", out, "--size", str(args.size), "--search-path", CORPUS, *extra]
            run = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=args.tree)
            status = "ok" if run.returncode == 0 else "FAILED " + (run.stdout + run.stderr).strip()[-300:]
            failed += run.returncode != 0
            print(f"{scene} {os.path.relpath(document, args.examples)}: {status}", flush=True)
    return 1 if failed else 0


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    """Over the RGB channels, with the peak of the first image (at least 1) as the signal."""
    a, b = a[..., :3].astype(np.float64), b[..., :3].astype(np.float64)
    mse = float(np.mean((a - b) ** 2))
    peak = max(1.0, float(np.nanmax(a)))
    return math.inf if mse == 0 else 10 * math.log10(peak * peak / mse)


def compare(args) -> int:
    rows = []
    for path in sorted(glob.glob(os.path.join(args.before, "**", "*.npy"), recursive=True)):
        rel = os.path.relpath(path, args.before)
        other = os.path.join(args.after, rel)
        value = psnr(np.load(path), np.load(other)) if os.path.exists(other) else float("nan")
        rows.append((rel, value))
    print("| image | PSNR dB |\n|---|---:|")
    for rel, value in rows:
        print(f"| {rel} | {value:.1f} |")
    low = [r for r, v in rows if not v >= args.min_psnr]
    finite = [v for _, v in rows if math.isfinite(v)]
    missing = sum(math.isnan(v) for _, v in rows)
    print(f"\n{len(rows)} images, {len(low)} below {args.min_psnr} dB ({missing} missing, counted as below), "
          f"{sum(v == math.inf for _, v in rows)} identical; lowest of the others "
          f"{min(finite) if finite else float('nan'):.1f} dB")
    return 1 if low or not rows else 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("render", help="draw every material into a folder of .npy images")
    r.add_argument("out", help="folder for the images (env/ and lights/ below it)")
    r.add_argument("--examples", default=EXAMPLES, help="folder of documents, searched recursively")
    r.add_argument("--tree", default=ROOT, help="the source tree whose shadergen draws them")
    r.add_argument("--size", type=int, default=128)
    r.add_argument("--interface", default="complete", choices=["complete", "reduced", "specialized"])
    c = sub.add_parser("compare", help="PSNR of every image of one folder against another")
    c.add_argument("before")
    c.add_argument("after")
    c.add_argument("--min-psnr", type=float, default=60.0)
    args = ap.parse_args()
    return render(args) if args.command == "render" else compare(args)


if __name__ == "__main__":
    sys.exit(main())
