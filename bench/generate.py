#!/usr/bin/env python3
"""Generation time, ours against the MaterialX reference generator, measured in one run.

Warm: per element, in-process (ours: Generator.prepare + emit with the libraries loaded; the
reference: a fresh GenContext per element, libraries loaded, via the oracle venv).
Cold: a whole process from start to the shader written, for one document.
Prints a table of medians and ratios (ours / reference).

  .venv/bin/python bench/generate.py ../shared/corpus --filter TestSuite/stdlib [--cold-docs 10]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
HERE = os.path.dirname(os.path.abspath(__file__))
REF_WARM = r"""
import json, sys, time, os
import MaterialX as mx, MaterialX.PyMaterialXGenShader as gs, MaterialX.PyMaterialXGenGlsl as gg
lib = mx.createDocument(); search = mx.getDefaultDataSearchPath()
mx.loadLibraries(mx.getDefaultDataLibraryFolders(), search, lib)
gen = gg.GlslShaderGenerator.create()
out, skipped = [], []
for path in sys.argv[1:]:
    doc = mx.createDocument()
    try:
        mx.readFromXmlFile(doc, path)
    except Exception as exc:  # e.g. an include the corpus does not ship
        skipped.append([path, str(exc).splitlines()[0]])
        continue
    doc.setDataLibrary(lib)
    for e in gs.findRenderableElements(doc):
        ctx = gs.GenContext(gen); ctx.registerSourceCodeSearchPath(search)
        t0 = time.perf_counter()
        try:
            gen.generate(e.getName(), e, ctx)
        except Exception:
            continue
        out.append([path, e.getNamePath(), (time.perf_counter() - t0) * 1e3])
print(json.dumps({"times": out, "skipped": skipped}))
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


def ours_warm(docs):
    sys.path.insert(0, os.path.dirname(HERE))
    from shadergen.api import Generator
    from shadergen.errors import ShaderGenError

    gen = Generator()
    out = []
    for path in docs:
        doc = gen.load(Path(path))  # parsed once, as the reference's document is
        for p in gen.prepare_all(doc):
            if isinstance(p, Exception):
                continue
            t0 = time.perf_counter()
            try:
                gen.prepare(doc, element=p.element).emit()
            except ShaderGenError:
                continue
            out.append([path, p.element, (time.perf_counter() - t0) * 1e3])
    return out


def cold(cmd, repeat=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, capture_output=True, check=False)
        times.append((time.perf_counter() - t0) * 1e3)
    return min(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("corpus")
    ap.add_argument("--filter", default="TestSuite/stdlib")
    ap.add_argument("--cold-docs", type=int, default=10)
    a = ap.parse_args()
    docs = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.corpus) for f in fs
                  if f.endswith(".mtlx") and a.filter in os.path.join(d, f))
    reference = json.loads(subprocess.run([ORACLE_PY, "-c", REF_WARM, *docs], capture_output=True, text=True).stdout)
    ref, skipped = reference["times"], {path for path, _ in reference["skipped"]}
    for path, why in reference["skipped"]:
        print(f"skipped (the reference cannot load it): {os.path.relpath(path, a.corpus)}: {why}")
    docs = [d for d in docs if d not in skipped]
    ours = ours_warm(docs)
    ref_by = {(p, e): ms for p, e, ms in ref}
    pairs = [(ms, ref_by[(p, e)]) for p, e, ms in ours if (p, e) in ref_by]
    warm_ratio = statistics.median(o / r for o, r in pairs)
    # Cold means a fresh process of the installed product: bytecode written once, as an install does
    # (this machine sets PYTHONDONTWRITEBYTECODE, which would otherwise recompile every module per run).
    subprocess.run([sys.executable, "-m", "compileall", "-q", os.path.join(os.path.dirname(HERE), "shadergen")],
                   capture_output=True, check=False)
    colds = []
    shadergen = [sys.executable, "-m", "shadergen.cli", "generate"]
    for path in docs[:: max(1, len(docs) // a.cold_docs)][: a.cold_docs]:
        with tempfile.TemporaryDirectory() as d:
            o = cold(shadergen + [path, "--out", d])
            r = cold([ORACLE_PY, "-c", REF_COLD, path, d])
        colds.append((o, r))
    print(f"{'measure':<34}{'ours ms':>10}{'reference ms':>14}{'ratio':>8}")
    print(f"{'warm, median per element (n=%d)' % len(pairs):<34}{statistics.median(o for o, _ in pairs):>10.3f}"
          f"{statistics.median(r for _, r in pairs):>14.3f}{warm_ratio:>8.2f}")
    co, cr = statistics.median(o for o, _ in colds), statistics.median(r for _, r in colds)
    print(f"{'cold process, median (n=%d docs)' % len(colds):<34}{co:>10.1f}{cr:>14.1f}"
          f"{statistics.median(o / r for o, r in colds):>8.2f}")


if __name__ == "__main__":
    main()
