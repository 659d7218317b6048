#!/usr/bin/env python3
"""The library's code as typed IR (shadergen/code/library.py): what building it costs once per
library, and what reading it back costs a cold process.

Build: parse every source file and the prelude, check them, parse every inline expression, in
this process with the data library already loaded (best of --repeat). Load: a fresh process reads
the pickle (best of --repeat, the time of CodeLibrary.load alone, with the data library loaded).

  .venv/bin/python bench/code_library.py [--repeat 3]
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from shadergen.code.check import check_modules  # noqa: E402
from shadergen.code.library import PRELUDE, PRELUDE_PATH, CodeLibrary, inline_sources, source_files  # noqa: E402
from shadergen.code.parse import parse_expression, parse_module  # noqa: E402
from shadergen.code.types import ir_type  # noqa: E402
from shadergen.library import Library, read_source  # noqa: E402
from shadergen.nodes.surface import ENVIRONMENT_UNIFORMS  # noqa: E402

EXTERNALS = {name: ir_type(t) for name, t in ENVIRONMENT_UNIFORMS}
LOAD = r"""
import sys, time
from shadergen.code.library import CodeLibrary
from shadergen.code.types import ir_type
from shadergen.library import Library
from shadergen.nodes.surface import ENVIRONMENT_UNIFORMS
library = Library.load()
t = time.perf_counter()
CodeLibrary.load(library, {name: ir_type(t) for name, t in ENVIRONMENT_UNIFORMS})
print((time.perf_counter() - t) * 1e3)
"""


def build_phases(library: Library) -> tuple[float, float, float]:
    """(parse, check, templates) in ms."""
    t0 = time.perf_counter()
    modules = {PRELUDE: parse_module(PRELUDE, read_source(PRELUDE_PATH))}
    for relative in source_files(library.root):
        modules[relative] = parse_module(relative, read_source(os.path.join(library.root, relative)))
    t1 = time.perf_counter()
    check_modules(modules, EXTERNALS, (PRELUDE,))
    t2 = time.perf_counter()
    for text, where in inline_sources(library):
        parse_expression(text, where)
    t3 = time.perf_counter()
    return (t1 - t0) * 1e3, (t2 - t1) * 1e3, (t3 - t2) * 1e3


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    library = Library.load()
    phases = min((build_phases(library) for _ in range(args.repeat)), key=sum)
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "SHADERGEN_CACHE_DIR": cache, "PYTHONPATH": ROOT}
        os.environ["SHADERGEN_CACHE_DIR"] = cache
        CodeLibrary.load(library, EXTERNALS)  # writes the pickle
        size = sum(os.path.getsize(os.path.join(cache, f)) for f in os.listdir(cache) if f.startswith("code-"))
        loads = [float(subprocess.run([sys.executable, "-c", LOAD], env=env, capture_output=True, text=True,
                                      check=True, timeout=300).stdout) for _ in range(args.repeat)]
    print(f"parse {phases[0]:.0f} ms, check {phases[1]:.0f} ms, inline templates {phases[2]:.0f} ms; "
          f"pickle {size / 1e6:.2f} MB, cold load {min(loads):.1f} ms (best of {args.repeat})")
    print(f"code_library: build {sum(phases):.0f} ms | load {min(loads):.1f} ms | pickle {size / 1e6:.2f} MB")


if __name__ == "__main__":
    main()
