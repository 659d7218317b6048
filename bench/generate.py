#!/usr/bin/env python3
"""Generation time, ours against the MaterialX reference generator, measured in one run, interleaved.

Warm: per element, in a long-lived process of each (ours: Generator.prepare + emit, libraries
loaded and earlier requests served; the reference: a fresh GenContext per element, libraries
loaded, via the oracle venv). The two processes are sent the same documents one at a time,
alternating which goes first, --repeat rounds over the whole set; an element's time is its best
round (the first round warms both). Documents the reference cannot load (an include the corpus
does not ship) are skipped for both, and named.
Cold: a whole process from start to the shader written, for one document, ours and the
reference alternating, best of three.
Prints a table of medians and ratios (ours / reference).
With `--baseline TREE` the other side is not the reference but our own generator from another
source tree (a checkout of main before a change): the same documents, the same interleaving.
With `--targets glsl,essl,...` (issue 24) the other side is our GLSL: in this one process, per
element, each target's prepare + emit (the whole record: vulkan's includes its SPIR-V, compiled by
glslangValidator) in an order that turns each round; an element's time per target is its best
round; medians per target and the median per-element ratio to GLSL.

  .venv/bin/python bench/generate.py ../shared/corpus --filter TestSuite/stdlib [--cold-docs 10] [--repeat 3]
  .venv/bin/python bench/generate.py ../shared/corpus --filter Examples
  .venv/bin/python bench/generate.py ../shared/corpus --filter Examples --baseline /tmp/main-checkout
  .venv/bin/python bench/generate.py ../shared/corpus --filter Examples --targets glsl,essl,wgsl,vulkan,hlsl,slang,msl
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Each warm worker reads a document path per line and answers one JSON line:
# {"times": [[element name path, ms], ...]} or {"skipped": why}.
REF_WARM = r"""
import json, sys, time
import MaterialX as mx, MaterialX.PyMaterialXGenShader as gs, MaterialX.PyMaterialXGenGlsl as gg
lib = mx.createDocument(); search = mx.getDefaultDataSearchPath()
mx.loadLibraries(mx.getDefaultDataLibraryFolders(), search, lib)
gen = gg.GlslShaderGenerator.create()
for line in sys.stdin:
    doc = mx.createDocument()
    try:
        mx.readFromXmlFile(doc, line.strip())
    except Exception as exc:  # e.g. an include the corpus does not ship
        print(json.dumps({"skipped": str(exc).splitlines()[0]}), flush=True)
        continue
    doc.setDataLibrary(lib)
    times = []
    for e in gs.findRenderableElements(doc):
        ctx = gs.GenContext(gen); ctx.registerSourceCodeSearchPath(search)
        t0 = time.perf_counter()
        try:
            gen.generate(e.getName(), e, ctx)
        except Exception:
            continue
        times.append([e.getNamePath(), (time.perf_counter() - t0) * 1e3])
    print(json.dumps({"times": times}), flush=True)
"""
OURS_WARM = r"""
import json, sys, time
from pathlib import Path
from shadergen.api import Generator
from shadergen.errors import ShaderGenError
gen = Generator()
for line in sys.stdin:
    try:
        doc = gen.load(Path(line.strip()))  # parsed once, untimed, as the reference's document is
    except ShaderGenError as exc:  # e.g. an include the corpus does not ship
        print(json.dumps({"skipped": exc.message}), flush=True)
        continue
    times = []
    for p in gen.prepare_all(doc):
        if isinstance(p, Exception):
            continue
        t0 = time.perf_counter()
        try:
            gen.prepare(doc, element=p.element).emit()
        except ShaderGenError:
            continue
        times.append([p.element, (time.perf_counter() - t0) * 1e3])
    print(json.dumps({"times": times}), flush=True)
"""
REF_COLD = r"""
import sys, os
import MaterialX as mx, MaterialX.PyMaterialXGenShader as gs, MaterialX.PyMaterialXGenGlsl as gg
lib = mx.createDocument(); search = mx.getDefaultDataSearchPath()
mx.loadLibraries(mx.getDefaultDataLibraryFolders(), search, lib)
gen = gg.GlslShaderGenerator.create()
doc = mx.createDocument(); mx.readFromXmlFile(doc, sys.argv[1]); doc.setDataLibrary(lib)
e = gs.findRenderableElements(doc)[0]
ctx = gs.GenContext(gen); ctx.registerSourceCodeSearchPath(search)
sh = gen.generate(e.getName(), e, ctx)
open(os.path.join(sys.argv[2], "ref.frag"), "w").write(sh.getSourceCode("pixel"))
"""


class WarmWorker:
    """A long-lived generator process answering one document at a time."""

    def __init__(self, python: str, code: str, tree: str = ROOT):
        self.proc = subprocess.Popen([python, "-c", code], cwd=tree, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     text=True, env=dict(os.environ, PYTHONPATH=tree))

    def times(self, path: str) -> dict:
        self.proc.stdin.write(path + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if not line:
            raise SystemExit(f"a warm worker ({self.proc.args[0]}) exited on {path}")
        return json.loads(line)

    def close(self) -> None:
        self.proc.stdin.close()
        self.proc.wait(60)


def warm(docs: list[str], repeat: int, baseline: str | None) -> tuple[list[tuple[float, float]], dict[str, str]]:
    """(ours ms, other ms) per element both generated, each its best round; and the documents
    the other could not load, with why. The other is the reference, or our `baseline` tree."""
    other = WarmWorker(sys.executable, OURS_WARM, baseline) if baseline else WarmWorker(ORACLE_PY, REF_WARM)
    workers = {"ours": WarmWorker(sys.executable, OURS_WARM), "reference": other}
    best: dict[str, dict[tuple[str, str], float]] = {name: {} for name in workers}
    skipped: dict[str, str] = {}
    try:
        for round_ in range(repeat):
            for i, path in enumerate(d for d in docs if d not in skipped):
                order = list(workers) if (i + round_) % 2 == 0 else list(reversed(workers))
                for name in order:
                    if path in skipped:
                        continue
                    answer = workers[name].times(path)
                    if "skipped" in answer:
                        skipped[path] = answer["skipped"]
                        continue
                    for element, ms in answer["times"]:
                        key = (path, element)
                        best[name][key] = min(ms, best[name].get(key, ms))
    finally:
        for worker in workers.values():
            worker.close()
    ours, reference = best["ours"], best["reference"]
    return [(ms, reference[key]) for key, ms in ours.items() if key in reference and key[0] not in skipped], skipped


def cold(docs: list[str], count: int, baseline: str | None) -> list[tuple[float, float]]:
    """(ours ms, other ms) per document: a whole process each, alternating, best of three."""
    # Cold means a fresh process of the installed product: bytecode written once, as an install does
    # (this machine sets PYTHONDONTWRITEBYTECODE, which would otherwise recompile every module per run).
    trees = (ROOT, baseline or ROOT)
    for tree in set(trees):
        subprocess.run([sys.executable, "-m", "compileall", "-q", os.path.join(tree, "shadergen")],
                       capture_output=True, check=False)
    out = []
    for path in docs[:: max(1, len(docs) // count)][:count]:
        with tempfile.TemporaryDirectory() as d:
            ours = [sys.executable, "-m", "shadergen.cli", "generate", path, "--out", d]
            commands = (ours, ours if baseline else [ORACLE_PY, "-c", REF_COLD, path, d])
            best = [float("inf"), float("inf")]
            for round_ in range(3):
                for k in ((0, 1) if round_ % 2 == 0 else (1, 0)):
                    t0 = time.perf_counter()
                    subprocess.run(commands[k], cwd=trees[k], capture_output=True, check=False,
                                   env=dict(os.environ, PYTHONPATH=trees[k]))
                    best[k] = min(best[k], (time.perf_counter() - t0) * 1e3)
        out.append((best[0], best[1]))
    return out


def per_target(docs: list[str], targets: list[str], repeat: int) -> dict[str, dict[tuple[str, str], float]]:
    """target -> (document, element) -> best ms of prepare + emit, every target of an element
    measured in the same round, each round in another order."""
    from pathlib import Path

    from shadergen.api import Generator
    from shadergen.errors import ShaderGenError

    gen = Generator()
    best: dict[str, dict[tuple[str, str], float]] = {t: {} for t in targets}
    for path in docs:
        try:
            doc = gen.load(Path(path))  # parsed once, untimed, as in the warm measurement
        except ShaderGenError:
            continue
        elements = [p.element for p in gen.prepare_all(doc) if not isinstance(p, Exception)]
        for round_ in range(repeat):
            for i, element in enumerate(elements):
                shift = (round_ + i) % len(targets)
                for target in targets[shift:] + targets[:shift]:
                    t0 = time.perf_counter()
                    try:
                        gen.prepare(doc, element=element, target=target).emit()
                    except ShaderGenError:
                        continue
                    ms = (time.perf_counter() - t0) * 1e3
                    key = (path, element)
                    best[target][key] = min(ms, best[target].get(key, ms))
    return best


def report_targets(filter_: str, best: dict[str, dict[tuple[str, str], float]]) -> None:
    glsl = best["glsl"]
    print(f"{'target':<8}{'elements':>10}{'median ms':>11}{'/ glsl (median per element)':>29}")
    groups = []
    for target, times in best.items():
        ratios = [ms / glsl[key] for key, ms in times.items() if key in glsl]
        ratio = statistics.median(ratios) if ratios else float("nan")
        print(f"{target:<8}{len(times):>10}{statistics.median(times.values()) if times else float('nan'):>11.2f}"
              f"{ratio:>29.2f}")
        if target != "glsl":
            groups.append(f"{target} {ratio:.2f}x")
    print(f"generate targets: {filter_} against glsl (n={len(glsl)}) | " + " | ".join(groups))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("corpus")
    ap.add_argument("--filter", default="TestSuite/stdlib")
    ap.add_argument("--cold-docs", type=int, default=10)
    ap.add_argument("--repeat", type=int, default=3, help="warm rounds over the documents")
    ap.add_argument("--baseline", help="a source tree of ours to measure against instead of the reference")
    ap.add_argument("--targets", help="our targets against our glsl instead (comma-separated, glsl among them)")
    a = ap.parse_args()
    other = "baseline" if a.baseline else "reference"
    docs = sorted(os.path.abspath(os.path.join(d, f)) for d, _, fs in os.walk(a.corpus) for f in fs
                  if f.endswith(".mtlx") and a.filter in os.path.join(d, f))
    if a.targets:
        targets = a.targets.split(",")
        report_targets(a.filter, per_target(docs, targets if "glsl" in targets else ["glsl", *targets], a.repeat))
        return
    pairs, skipped = warm(docs, a.repeat, a.baseline)
    for path, why in skipped.items():
        print(f"skipped (the {other} cannot load it): {os.path.relpath(path, a.corpus)}: {why}")
    colds = cold([d for d in docs if d not in skipped], a.cold_docs, a.baseline)
    print(f"{'measure':<34}{'ours ms':>10}{other + ' ms':>14}{'ratio':>8}")
    print(f"{'warm, median per element (n=%d)' % len(pairs):<34}{statistics.median(o for o, _ in pairs):>10.3f}"
          f"{statistics.median(r for _, r in pairs):>14.3f}{statistics.median(o / r for o, r in pairs):>8.2f}")
    co, cr = statistics.median(o for o, _ in colds), statistics.median(r for _, r in colds)
    print(f"{'cold process, median (n=%d docs)' % len(colds):<34}{co:>10.1f}{cr:>14.1f}"
          f"{statistics.median(o / r for o, r in colds):>8.2f}")
    print(f"generate: {a.filter} against the {other} | warm {statistics.median(o / r for o, r in pairs):.2f}x "
          f"(n={len(pairs)}) | cold {statistics.median(o / r for o, r in colds):.2f}x (n={len(colds)})")


if __name__ == "__main__":
    main()
