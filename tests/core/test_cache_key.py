"""Every input that changes generated code moves the output key: library definitions, their GLSL
sources, the folder they are loaded from and the generator's own code (fingerprint.py)."""
import shutil
from pathlib import Path

import pytest

from shadergen.api import Generator
from shadergen.fingerprint import PACKAGE, output_key
from shadergen.library import DEFAULT_LIBRARY_ROOT, Library

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "marble_checker.mtlx"
FRACTAL_SOURCE = Path("stdlib/genglsl/mx_noise_fractal.glsl")
MARKER = "// edited in a copy of the library"


@pytest.fixture
def library_copy(tmp_path) -> Path:
    return Path(shutil.copytree(DEFAULT_LIBRARY_ROOT, tmp_path / "libraries"))


def edited(path: Path, line: str) -> None:
    path.write_text(path.read_text() + f"\n{line}\n")


@pytest.mark.parametrize("relative", [FRACTAL_SOURCE, Path("stdlib/stdlib_defs.mtlx")])
def test_editing_a_library_file_moves_the_key(library_copy, relative):
    before = output_key(library_copy)
    edited(library_copy / relative, "<!-- x -->" if relative.suffix == ".mtlx" else MARKER)
    assert output_key(library_copy) != before


def test_the_library_folder_is_part_of_the_key(library_copy, tmp_path):
    twin = shutil.copytree(library_copy, tmp_path / "twin")
    assert output_key(library_copy) != output_key(twin)


def test_the_generators_code_is_part_of_the_key(library_copy, tmp_path):
    package = Path(shutil.copytree(PACKAGE, tmp_path / "shadergen"))
    before = output_key(library_copy, package)
    edited(package / "graph.py", "# a change in the generator")
    after_graph_edit = output_key(library_copy, package)
    assert after_graph_edit != before
    edited(package / "render" / "scene.py", "# the renderer does not shape records")
    assert output_key(library_copy, package) == after_graph_edit


def test_the_generator_reports_the_key_the_service_digests():
    assert Generator().library_hash == output_key(DEFAULT_LIBRARY_ROOT)


def test_a_copied_library_emits_its_own_sources(library_copy, tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path / "cache"))
    original = Generator(Library.load(DEFAULT_LIBRARY_ROOT)).prepare(EXAMPLE)  # fills the on-disk cache first
    source = library_copy / FRACTAL_SOURCE
    # in every body: only the functions the shader calls are written
    source.write_text(source.read_text().replace("{", "{\n    " + MARKER))
    for attempt in ("parsed", "from the on-disk cache"):
        copy = Generator(Library.load(library_copy)).prepare(EXAMPLE)
        assert MARKER in copy.emit()["stages"]["pixel"], attempt
        assert copy.hash != original.hash
    assert MARKER not in original.emit()["stages"]["pixel"]
    for cached in (tmp_path / "cache").glob("library-*.json"):  # sources are named inside their library
        assert str(DEFAULT_LIBRARY_ROOT) not in cached.read_text() and str(library_copy) not in cached.read_text()
