"""Every input that changes generated code moves the output key: library definitions, their GLSL
sources, the folder they are loaded from and the generator's own code (fingerprint.py); the key a
cold process remembers from those files' stamps follows every edit."""
import functools
import hashlib
import os
import shutil
import time
from pathlib import Path

import pytest

from shadergen import digest, library
from shadergen.api import Generator
from shadergen.fingerprint import PACKAGE, output_key
from shadergen.library import DEFAULT_LIBRARY_ROOT, Library, remembered_output_key

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
    for cached in (tmp_path / "cache").glob("library-*.jsonl"):  # sources are named inside their library
        assert str(DEFAULT_LIBRARY_ROOT) not in cached.read_text() and str(library_copy) not in cached.read_text()


def aged(folder: Path) -> Path:
    """Every file under `folder` last modified an hour ago: old enough for its stamp to be trusted."""
    then = time.time() - 3600
    for path in folder.rglob("*"):
        os.utime(path, (then, then))
    return folder


@pytest.fixture
def remembered(library_copy, tmp_path, monkeypatch):
    """(library, package, cache folder): aged copies, and the cache folder the key is kept in."""
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path / "cache"))
    package = aged(Path(shutil.copytree(PACKAGE, tmp_path / "shadergen")))
    return aged(library_copy), package, tmp_path / "cache"


def test_a_later_process_reads_the_remembered_key_without_hashing(remembered, monkeypatch):
    root, package, cache = remembered
    key = remembered_output_key(root, package)
    assert key == output_key(root, package) and len(list(cache.glob("output-key-*.txt"))) == 1

    def hashing(*_):
        raise AssertionError("the files were hashed again")
    monkeypatch.setattr(library, "output_key", hashing)
    assert remembered_output_key(root, package) == key


def test_an_edited_file_moves_the_remembered_key(remembered):
    root, package, _ = remembered
    before = remembered_output_key(root, package)
    for edit in (root / FRACTAL_SOURCE, package / "graph.py"):
        edited(edit, MARKER if edit.suffix == ".glsl" else "# a change in the generator")
        after = remembered_output_key(root, package)
        assert after != before and after == output_key(root, package)
        before = after


def test_a_damaged_remembered_key_is_computed_again_and_rewritten(remembered):
    root, package, cache = remembered
    key = remembered_output_key(root, package)
    [kept] = cache.glob("output-key-*.txt")
    for damage in ("0" * 64 + " " + "0" * 64, key[:40], "", "\xff not ascii"):
        kept.write_bytes(damage.encode("latin-1"))
        assert remembered_output_key(root, package) == key
        assert kept.read_text().split()[0] == key


def test_a_key_of_files_modified_just_now_is_not_kept(remembered):
    root, package, cache = remembered
    edited(root / FRACTAL_SOURCE, MARKER)  # a rewrite within its clock step could keep this stamp
    assert remembered_output_key(root, package) == output_key(root, package)
    assert not list(cache.glob("output-key-*.txt"))


def test_the_generators_digests_are_sha256_and_blake2b():
    """shadergen/digest.py: CPython's own SHA-256 and BLAKE2b-256, not hashlib's; the same digests."""
    blake2b = functools.partial(hashlib.blake2b, digest_size=32)
    for ours, theirs in ((digest.sha256, hashlib.sha256), (digest.graph_digest, blake2b)):
        for data in (b"", b"abc", bytes(range(256)) * 1000):
            assert ours(data).hexdigest() == theirs(data).hexdigest()
        h = ours(b"ab")
        copy = h.copy()
        h.update(b"c")
        assert h.digest() == theirs(b"abc").digest() and copy.digest() == theirs(b"ab").digest()
