import subprocess
import tempfile
import os

import pytest

from shadergen.api import Generator
from shadergen.targets.deadcode import used_functions


@pytest.fixture(scope="session")
def gen() -> Generator:
    return Generator()


def doc(body: str, version: str = "1.39", colorspace: str | None = None) -> str:
    cs = f' colorspace="{colorspace}"' if colorspace else ""
    return f'<?xml version="1.0"?>\n<materialx version="{version}"{cs}>\n{body}\n</materialx>\n'


def glslang(source: str, stage: str) -> tuple[bool, str]:
    """Compile with the real reference compiler; stage is 'vertex' or 'pixel'."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "s." + ("vert" if stage == "vertex" else "frag"))
        with open(path, "w") as f:
            f.write(source)
        p = subprocess.run(["glslangValidator", path], capture_output=True, text=True)
    return p.returncode == 0, p.stdout


needs_glslang = pytest.mark.usefixtures("glslang_validator")  # skipped without it, failed under CI=true


def kept_code(library: str, roots: str) -> str:
    """What a stage keeps of the library's function lines when `roots` (its main) use them."""
    lines, _ = used_functions(library.split("\n"), roots)
    return "\n".join(lines)
