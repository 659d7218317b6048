"""The key of everything besides the document that changes what the generator writes.

Generated code depends on the document, the options, and three things on disk: the data
libraries (their .mtlx definitions *and* the GLSL source files those name), the folder they were
loaded from (implementations name their sources relative to it), and the generator's own Python
code. `output_key` hashes all three; the library's on-disk cache, the graph hash and the
service's request digest all build on it, so editing any of those files moves every key.
"""
import hashlib
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
KEY_FORMAT = 2  # bump when the layout of what is hashed changes


def generator_fingerprint(package: Path = PACKAGE) -> str:
    """The generator's code: a new release must never be served records cached by the old one.
    The renderer is not part of what a record depends on."""
    h = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        relative = path.relative_to(package)
        if "render" not in relative.parts:
            h.update(str(relative).encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def library_files(root: Path) -> list[Path]:
    """Every file of a library folder: definitions, implementations' sources, includes."""
    return sorted(p for p in root.rglob("*") if p.is_file())


def output_key(root: Path, package: Path = PACKAGE) -> str:
    root = Path(root).resolve()
    h = hashlib.sha256(f"shadergen-output-key-{KEY_FORMAT}\0".encode())
    h.update(generator_fingerprint(package).encode() + b"\0")
    h.update(str(root).encode() + b"\0")
    for path in library_files(root):
        h.update(str(path.relative_to(root)).encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()
