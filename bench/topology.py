#!/usr/bin/env python3
"""One shader per topology (issue 11).

1. Over every Examples document in `complete`: how many distinct fragment sources, and how many
   distinct topology hashes (they should be equal: the topology decides the source).
2. An editing session on one material: --requests edits, each changing one value of the
   document, generated and drawn as a thumbnail in this process (one Renderer, as a render worker
   keeps it). With sharing (values in the listing: one source, one program) and without
   (`values: "source"`: every edit is a new source and a new program), the two interleaved edit by
   edit. Prints p50/p99 of generate and of thumbnail (generate + draw) with the ratio.

  .venv/bin/python bench/topology.py ../shared/corpus/resources/Materials/Examples [--requests 200] [--size 64]
"""
import argparse
import glob
import os
import re
import statistics
import time
from pathlib import Path

from shadergen.api import Generator
from shadergen.render import Renderer

FLOAT = re.compile(r'(<input name="[^"]+" type="float" value=")([-\d.eE]+)(")')


def distinct_sources(gen: Generator, folder: str) -> None:
    sources, topologies, materials, failed = set(), set(), 0, []
    paths = sorted(glob.glob(os.path.join(folder, "**", "*.mtlx"), recursive=True))
    for path in paths:
        for record in gen.records(Path(path), all=True):
            if "error" in record:
                failed.append(f"{os.path.basename(path)} {record['element']}: {record['error']['code']}")
                continue
            materials += 1
            sources.add(record["stages"]["pixel"])
            topologies.add(record["topology_hash"])
    print(f"complete, {len(paths)} documents, {materials} materials: {len(sources)} distinct fragment sources, "
          f"{len(topologies)} distinct topology hashes")
    for line in failed:
        print(f"  not generated: {line}")


def edits(text: str, count: int):
    """`count` documents, each the previous one with one float input changed."""
    spots = list(FLOAT.finditer(text))
    for i in range(count):
        m = spots[i % len(spots)]
        value = (float(m.group(2)) + 0.01 * (i + 1)) % 1.0
        yield text[:m.start(2)] + f"{value:.4f}" + text[m.end(2):]


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def editing_session(gen: Generator, path: str, requests: int, size: int) -> None:
    text, base_dir = open(path).read(), os.path.dirname(path)
    renderer = Renderer(search_paths=[base_dir])
    times = {mode: {"generate": [], "thumbnail": []} for mode in ("listing", "source")}
    for document in edits(text, requests):
        for mode in ("listing", "source"):
            t0 = time.perf_counter()
            record = gen.prepare(document, base_dir=base_dir, values=mode).emit()
            t1 = time.perf_counter()
            renderer.render(record, size=size, document_dir=base_dir)
            t2 = time.perf_counter()
            times[mode]["generate"].append((t1 - t0) * 1e3)
            times[mode]["thumbnail"].append((t2 - t0) * 1e3)
    print(f"\nediting session: {requests} edits of {os.path.basename(path)} at {size}x{size} "
          f"(programs compiled/reused over both modes: {renderer.program_counts})")
    print("| ms | shared topology | no sharing (values in source) | ratio |\n| --- | --- | --- | --- |")
    for step in ("generate", "thumbnail"):
        for name, q in (("p50", 0.5), ("p99", 0.99)):
            shared, alone = (percentile(times[m][step], q) for m in ("listing", "source"))
            print(f"| {step} {name} | {shared:.1f} | {alone:.1f} | {shared / alone:.2f} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("examples", help="the Examples folder of the corpus")
    ap.add_argument("--material", default="StandardSurface/standard_surface_carpaint.mtlx")
    ap.add_argument("--requests", type=int, default=200)
    ap.add_argument("--size", type=int, default=256)
    args = ap.parse_args()
    os.environ["MESA_SHADER_CACHE_DISABLE"] = "true"  # a new source must compile, as on a fresh worker
    gen = Generator()
    distinct_sources(gen, args.examples)
    editing_session(gen, os.path.join(args.examples, args.material), args.requests, args.size)


if __name__ == "__main__":
    main()
