"""OSL conformance: per corpus (TestSuite/stdlib, TestSuite/pbrlib, Examples), the renderable
elements, how many we generate as OSL and how many of those oslc compiles (scripts/osl.sh builds
it). The reference's OSL beside it and the testshade-vs-GL agreement table are not written yet.

    .venv/bin/python bench/osl.py [--corpus ../shared/corpus]
"""
import argparse
import collections
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from shadergen.api import DocumentFile, default_generator  # noqa: E402
from shadergen.targets.osl.check import errors  # noqa: E402

CORPORA = {"stdlib": "resources/Materials/TestSuite/stdlib", "pbrlib": "resources/Materials/TestSuite/pbrlib",
           "Examples": "resources/Materials/Examples"}


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--corpus", default="../shared/corpus")
    a = p.parse_args()
    gen = default_generator()
    figures = []
    print("| corpus | elements | generated | compiled by oslc | first reasons |\n|---|---:|---:|---:|---|")
    for name, folder in CORPORA.items():
        elements, shaders, reasons = 0, {}, collections.Counter()
        for doc in sorted(glob.glob(os.path.join(a.corpus, folder, "**", "*.mtlx"), recursive=True)):
            for rec in gen.records(DocumentFile(doc), target="osl", all=True):
                elements += 1
                if "error" in rec:
                    reasons[rec["error"]["message"][:60]] += 1
                else:
                    shaders[f"{doc}:{rec['element']}"] = ("pixel", rec["stages"]["pixel"])
        compiled = len(shaders) - len(errors(shaders))
        generated_pct = 100 * len(shaders) / max(elements, 1)
        compiled_pct = 100 * compiled / max(len(shaders), 1)
        top = "; ".join(f"{n}x {m}" for m, n in reasons.most_common(2))
        print(f"| {name} | {elements} | {len(shaders)} ({generated_pct:.1f} %) | {compiled} ({compiled_pct:.1f} %) | {top} |")
        figures.append(f"{name} generated {generated_pct:.1f} % compiled {compiled_pct:.1f} %")
    print("osl: " + " | ".join(figures))


if __name__ == "__main__":
    main()
