#!/usr/bin/env python3
"""Names out of the source (issue 23, item 1): how many distinct sources and topology hashes the
corpus's materials give with document names (before) and structural names (after), in `complete`
and `reduced`, over the Examples and the TestSuite, and for the 11 untextured StandardSurface
Examples the issue names (which should give 1 of each with structural names).

  .venv/bin/python bench/names.py ../shared/corpus/resources/Materials

Its last line: `names: Examples complete D -> S | ... | untextured StandardSurface D -> S`, each
figure the distinct fragment sources with document names -> with structural names.
"""
import argparse
import glob
import os

from shadergen.api import DocumentFile, Generator

UNTEXTURED = ("default", "gold", "chrome", "copper", "plastic", "glass", "jade", "metal_brushed", "carpaint",
              "thin_film", "velvet")


def distinct(gen: Generator, paths: list[str], interface: str, names: str) -> tuple[int, int, int]:
    """(materials, distinct fragment sources, distinct topology hashes) over `paths`."""
    sources, topologies, materials = set(), set(), 0
    for path in paths:
        for record in gen.records(DocumentFile(path), all=True, interface=interface, names=names):
            if "error" in record:
                continue
            materials += 1
            sources.add(record["stages"]["pixel"])
            topologies.add(record["topology_hash"])
    return materials, len(sources), len(topologies)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("materials", help="the corpus's Materials folder (with Examples and TestSuite)")
    args = parser.parse_args()
    gen = Generator()
    sets = {folder: sorted(glob.glob(os.path.join(args.materials, folder, "**", "*.mtlx"), recursive=True))
            for folder in ("Examples", "TestSuite")}
    sets["untextured StandardSurface"] = [
        os.path.join(args.materials, "Examples", "StandardSurface", f"standard_surface_{m}.mtlx") for m in UNTEXTURED]
    summary = []
    for label, paths in sets.items():
        for interface in ("complete", "reduced"):
            counts = {names: distinct(gen, paths, interface, names) for names in ("document", "structural")}
            (materials, before, topo_before), (_, after, topo_after) = counts["document"], counts["structural"]
            print(f"{label}, {interface}: {len(paths)} documents, {materials} materials: distinct sources "
                  f"{before} -> {after}, distinct topology hashes {topo_before} -> {topo_after}", flush=True)
            summary.append(f"{label} {interface} {before} -> {after}")
    print("names: " + " | ".join(summary))


if __name__ == "__main__":
    main()
