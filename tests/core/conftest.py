import subprocess
import tempfile
import os

import pytest

from shadergen.api import Generator
from shadergen.code import ir
from shadergen.code.check import check_modules
from shadergen.code.parse import parse_module
from shadergen.code.passes import stage
from shadergen.library import default_library
from shadergen.nodes.base import implementation_for
from shadergen.targets.glsl.printer import GlslPrinter


@pytest.fixture(scope="session")
def gen() -> Generator:
    return Generator()


def doc(body: str, version: str = "1.39", colorspace: str | None = None) -> str:
    cs = f' colorspace="{colorspace}"' if colorspace else ""
    return f'<?xml version="1.0"?>\n<materialx version="{version}"{cs}>\n{body}\n</materialx>\n'


def material(bsdf: str) -> str:
    """A document of one material whose surface takes the BSDF node named "b" that `bsdf` declares."""
    return doc(f'{bsdf}<surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="b"/></surface>'
               '<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" '
               'nodename="surf"/></surfacematerial>')


def glslang(source: str, stage: str) -> tuple[bool, str]:
    """Compile with the real reference compiler; stage is 'vertex' or 'pixel'."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "s." + ("vert" if stage == "vertex" else "frag"))
        with open(path, "w") as f:
            f.write(source)
        p = subprocess.run(["glslangValidator", path], capture_output=True, text=True)
    return p.returncode == 0, p.stdout


needs_glslang = pytest.mark.usefixtures("glslang_validator")  # skipped without it, failed under CI=true


def library_implementation(nodedef: str):
    """The implementation (nodes.base) the default library gives a nodedef for GLSL."""
    library = default_library()
    element = next(e for e in library.implementations[nodedef] if e.category == "implementation")
    return implementation_for(element, library)


def checked_code(library: str, roots: str) -> tuple[list, ir.Block]:
    """`library` (GLSL-subset source) parsed and checked as the library's files are, with `roots`
    the statements of a main after it: (the library's items, main's body)."""
    path = "library.glsl"
    module = parse_module(path, library + "\nvoid main()\n{\n" + roots + "\n}\n")
    check_modules({path: module}, {})
    *items, main = module.items
    return items, main.body


def kept_code(library: str, roots: str, features: frozenset | None = None) -> str:
    """What a pixel stage keeps of `library` when `roots` (the statements of its main) use it:
    the stage's code passes (shadergen/code/passes/stage.py), the kept items printed as GLSL."""
    items, main = checked_code(library, roots)
    reached, _ = stage.run(items, features, frozenset(), [main])
    printer = GlslPrinter()
    return "\n".join(line for item in reached.items for line in printer.item(item))


@pytest.fixture(scope="module")
def code():
    """The library's code (code/library.py): every source and the prelude parsed and checked, built
    in a cache folder of its own, as a cold process first builds it."""
    from shadergen.code.externals import EXTERNALS
    from shadergen.code.library import CodeLibrary
    from shadergen.library import Library
    with tempfile.TemporaryDirectory() as folder:
        saved = os.environ.get("SHADERGEN_CACHE_DIR")
        os.environ["SHADERGEN_CACHE_DIR"] = folder
        try:
            yield CodeLibrary.load(Library.load(), EXTERNALS)
        finally:
            if saved is None:
                del os.environ["SHADERGEN_CACHE_DIR"]
            else:
                os.environ["SHADERGEN_CACHE_DIR"] = saved

