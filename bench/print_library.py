#!/usr/bin/env python3
"""The IR printers over the whole library: every item of every source file and the prelude, typed
(shadergen/code/library.py), printed as GLSL 4.00, ESSL 3.00 and WGSL (sections still in the IR:
GLSL writes them all out, WGSL takes one side of each). CPU time, best of --repeat; the line
counts against the library sources'.

  .venv/bin/python bench/print_library.py [--repeat 5]
"""
import argparse
import os
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from shadergen.code import ir  # noqa: E402
from shadergen.code.library import PRELUDE, CodeLibrary  # noqa: E402
from shadergen.code.types import ir_type  # noqa: E402
from shadergen.library import Library, read_source  # noqa: E402
from shadergen.nodes.surface import ENVIRONMENT_UNIFORMS  # noqa: E402
from shadergen.targets.glsl.printer import GlslPrinter  # noqa: E402
from shadergen.targets.wgsl.printer import WgslPrinter, function_names  # noqa: E402

EXTERNALS = {**{name: ir_type(t) for name, t in ENVIRONMENT_UNIFORMS}, "u_numActiveLightSources": "int",
             "u_lightData": "LightData[MAX_LIGHT_SOURCES]"}


def best(printer, items, repeat: int) -> tuple[float, int]:
    """(ms of CPU, lines) of printing every item."""
    times = []
    for _ in range(repeat):
        start = time.process_time()
        lines = sum(len(printer.item(item)) for item in items)
        times.append(time.process_time() - start)
    return min(times) * 1e3, lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    library = Library.load()
    with tempfile.TemporaryDirectory() as cache:
        os.environ["SHADERGEN_CACHE_DIR"] = cache
        code = CodeLibrary.load(library, EXTERNALS)
    items = [item for path in sorted(code.modules) for item in code.modules[path].items]
    functions = [n for item in items for n in ir.walk(item) if type(n) is ir.Function]
    sources = [os.path.join(library.root, p) for p in code.modules if p != PRELUDE]
    source_lines = sum(len(read_source(p).splitlines()) for p in sources)
    figures = {}
    for name, printer in (("glsl", GlslPrinter("glsl")), ("essl", GlslPrinter("essl")),
                          ("wgsl", WgslPrinter(function_names(functions)))):
        figures[name] = best(printer, items, args.repeat)
        print(f"{name}: {figures[name][0]:.1f} ms, {figures[name][1]} lines")
    print(f"library sources: {source_lines} lines, {len(functions)} functions")
    print("print_library: " + " | ".join(f"{name} {ms:.1f} ms {lines} lines" for name, (ms, lines) in figures.items())
          + f" | sources {source_lines} lines")


if __name__ == "__main__":
    main()
