"""OSL conformance: per corpus (TestSuite/stdlib, TestSuite/pbrlib, Examples), the renderable
elements, how many we generate as OSL and how many of those oslc compiles (scripts/osl.sh builds
it), beside the reference's own OSL (../shared/oracle/mx_oracle.py --target osl) compiled by the
same oslc; then the generation time of OSL against GLSL on the Examples (warm, interleaved in the
same run); with --agreement, the testshade-vs-GL agreement table of TestSuite/stdlib instead
(bench/osl_agreement.py).

Ours is compiled with -Werror (a warning is a rejection: generated code is product); the
reference's without it (its warnings allowed), with its own include folder (mx_funcs.h, found
beside the oracle venv's MaterialX package, never read here) on oslc's include path.

    .venv/bin/python bench/osl.py [--corpus ../shared/corpus] [--repeats 5]
    .venv/bin/python bench/osl.py --agreement [--filter math/]
"""
import argparse
import collections
import glob
import json
import os
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
from shadergen.api import DocumentFile, default_generator  # noqa: E402
from shadergen.targets.osl.check import errors  # noqa: E402

CORPORA = {"stdlib": "resources/Materials/TestSuite/stdlib", "pbrlib": "resources/Materials/TestSuite/pbrlib",
           "Examples": "resources/Materials/Examples"}
# ../shared beside the checkout; $SHADERGEN_SHARED where the checkout is elsewhere (a git worktree)
SHARED = os.environ.get("SHADERGEN_SHARED", os.path.join(os.path.dirname(ROOT), "shared"))
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
ORACLE = os.path.join(SHARED, "oracle", "mx_oracle.py")


def documents(corpus: str, folder: str) -> list[str]:
    return sorted(glob.glob(os.path.join(corpus, folder, "**", "*.mtlx"), recursive=True))


def percent(part: int, whole: int) -> float:
    return 100 * part / max(whole, 1)


def ours(gen, docs: list[str]) -> tuple[int, int, int, collections.Counter]:
    """(elements, generated, compiled, refusal reasons) of our OSL."""
    elements, shaders, reasons = 0, {}, collections.Counter()
    for doc in docs:
        for rec in gen.records(DocumentFile(doc), target="osl", all=True):
            elements += 1
            if "error" in rec:
                reasons[rec["error"]["message"][:60]] += 1
            else:
                shaders[f"{doc}:{rec['element']}"] = ("pixel", rec["stages"]["pixel"])
    return elements, len(shaders), len(shaders) - len(errors(shaders)), reasons


def reference_include() -> str:
    """The reference's OSL include folder: beside its package, asked of the oracle's own Python."""
    done = subprocess.run([ORACLE_PY, "-c", "import MaterialX, os; print(os.path.dirname(MaterialX.__file__))"],
                          capture_output=True, text=True, check=True)
    return os.path.join(done.stdout.strip(), "libraries", "stdlib", "genosl", "include")


def reference(docs: list[str], corpus: str, include: str) -> tuple[int, int, int]:
    """(elements, generated, compiled) of the reference's OSL: one oracle process per document
    (it stops at the first document it cannot list)."""
    elements, shaders = 0, {}
    for doc in docs:
        run = subprocess.run([ORACLE_PY, ORACLE, doc, "--target", "osl", "--all"], capture_output=True, text=True,
                             cwd=corpus, timeout=600)
        records = [json.loads(line) for line in run.stdout.splitlines() if line.strip()]
        elements += max(len(records), 1)  # a document it cannot list: one element not generated
        for rec in records:
            if "error" not in rec and rec.get("stages", {}).get("pixel"):
                shaders[f"{doc}:{rec['element']}"] = ("pixel", rec["stages"]["pixel"])
    return elements, len(shaders), len(shaders) - len(errors(shaders, include, strict=False))


def generation_times(gen, docs: list[str], repeats: int) -> dict[str, float]:
    """Median milliseconds to generate every element of `docs`, per target, interleaved (warm:
    one untimed pass first)."""
    samples = {"glsl": [], "osl": []}
    for rep in range(repeats + 1):
        for target in samples:
            start = time.perf_counter()
            for doc in docs:
                for _ in gen.records(DocumentFile(doc), target=target, all=True):
                    pass
            if rep:
                samples[target].append(1000 * (time.perf_counter() - start))
    return {target: statistics.median(values) for target, values in samples.items()}


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--corpus", default=os.path.join(SHARED, "corpus"))
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--agreement", action="store_true", help="the testshade-vs-GL table of TestSuite/stdlib")
    p.add_argument("--filter", help="with --agreement: only documents whose path contains this")
    p.add_argument("--mipmapped", action="store_true", help="with --agreement: file images filtered as the product "
                   "does (OIIO's footprint, GL's mip chain), not like for like (bench/osl_agreement.py)")
    a = p.parse_args()
    corpus = os.path.abspath(a.corpus)
    gen = default_generator()
    if a.agreement:
        from bench.osl_agreement import differences, report
        print("osl: " + report(differences(gen, corpus, a.filter, not a.mipmapped)))
        return
    include = reference_include()
    figures = []
    print("| corpus | elements (ours / ref) | generated: ours | ref | compiled by oslc: ours | ref "
          "| our refusals |\n|---|---:|---:|---:|---:|---:|---|")
    for name, folder in CORPORA.items():
        docs = documents(corpus, folder)
        elements, generated, compiled, reasons = ours(gen, docs)
        ref_elements, ref_generated, ref_compiled = reference(docs, corpus, include)
        top = "; ".join(f"{n}x {m}" for m, n in reasons.most_common(3))
        print(f"| {name} | {elements} / {ref_elements} | {generated} ({percent(generated, elements):.1f} %) "
              f"| {ref_generated} ({percent(ref_generated, ref_elements):.1f} %) "
              f"| {compiled} ({percent(compiled, generated):.1f} %) "
              f"| {ref_compiled} ({percent(ref_compiled, ref_generated):.1f} %) | {top} |")
        figures.append(f"{name} generated {percent(generated, elements):.1f} % compiled "
                       f"{percent(compiled, generated):.1f} % (ref {percent(ref_generated, ref_elements):.1f} % / "
                       f"{percent(ref_compiled, ref_generated):.1f} %)")
    times = generation_times(gen, documents(corpus, CORPORA["Examples"]), a.repeats)
    print(f"\nExamples, every element, median of {a.repeats} warm passes: GLSL {times['glsl']:.0f} ms, "
          f"OSL {times['osl']:.0f} ms ({times['osl'] / times['glsl']:.2f}x)")
    figures.append(f"Examples generation OSL/GLSL {times['osl'] / times['glsl']:.2f}x")
    print("osl: " + " | ".join(figures))


if __name__ == "__main__":
    main()
