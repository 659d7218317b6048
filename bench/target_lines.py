#!/usr/bin/env python3
"""Shader size per target: the pixel stage's lines (non-blank) of every material of a folder, in
each target, against GLSL's, for one interface (specialized unless --interface says otherwise).
WGSL gets every reduction GLSL gets when the ratio is at most 1 (the same code passes run on the
same IR for every target; WGSL's own lines are its uniform buffer struct and entry point).

  .venv/bin/python bench/target_lines.py ../shared/corpus/resources/Materials/Examples [--interface specialized]
"""
import argparse
import glob
import os
import statistics
from pathlib import Path

from shadergen.api import Generator

TARGETS = ("glsl", "essl", "wgsl")


def lines(text: str) -> int:
    return sum(1 for line in text.splitlines() if line.strip())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folder")
    ap.add_argument("--interface", default="specialized", choices=["complete", "reduced", "specialized"])
    a = ap.parse_args()
    generator = Generator()
    rows = []
    for path in sorted(glob.glob(os.path.join(a.folder, "**", "*.mtlx"), recursive=True)):
        counts = {}
        for target in TARGETS:
            record = next(iter(generator.records(Path(path), target=target, interface=a.interface)))
            counts[target] = None if "error" in record else lines(record["stages"]["pixel"])
        if None not in counts.values():
            rows.append((os.path.relpath(path, a.folder), counts))
    print(f"| material | {' | '.join(TARGETS)} | wgsl / glsl |\n|---|{'---:|' * (len(TARGETS) + 1)}")
    for name, counts in rows:
        print(f"| {name} | {' | '.join(str(counts[t]) for t in TARGETS)} | {counts['wgsl'] / counts['glsl']:.2f} |")
    ratios = [c["wgsl"] / c["glsl"] for _, c in rows]
    essl = [c["essl"] / c["glsl"] for _, c in rows]
    print(f"target_lines: {len(rows)} materials, {a.interface} pixel stage | wgsl/glsl median {statistics.median(ratios):.2f}"
          f" (max {max(ratios):.2f}) | essl/glsl median {statistics.median(essl):.2f}")


if __name__ == "__main__":
    main()
