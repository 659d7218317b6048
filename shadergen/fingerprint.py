"""The key of everything besides the document that changes what the generator writes.

Generated code depends on the document, the options, and three things on disk: the data
libraries (their .mtlx definitions *and* the GLSL source files those name), the folder they were
loaded from (implementations name their sources relative to it), and the generator's own Python
code. `output_key` hashes all three; the library's on-disk cache, the graph hash and the
service's request digest all build on it, so editing any of those files moves every key.
"""
import os

from .digest import sha256

# Paths here are plain strings (any os.PathLike is accepted): a cold `generate` never imports
# pathlib, which with what it imports costs a few milliseconds of every process start.
PACKAGE = os.path.dirname(os.path.realpath(__file__))
KEY_FORMAT = 2  # bump when the layout of what is hashed changes


def generator_fingerprint(package: str = PACKAGE) -> str:
    """The generator's code: a new release must never be served records cached by the old one."""
    h = sha256()
    for relative in _code_files(package):
        h.update(relative.encode() + b"\0" + _read(package, relative) + b"\0")
    return h.hexdigest()


def _code_files(package: str) -> list[str]:
    """The generator's Python files; the renderer is not part of what a record depends on."""
    return [relative for relative in _files_under(package, ".py") if "render" not in relative.split(os.sep)]


def library_files(root: str) -> list[str]:
    """Every file of a library folder: definitions, implementations' sources, includes."""
    return [os.path.join(root, relative) for relative in _files_under(root)]


def _files_under(folder: str, suffix: str = "") -> list[str]:
    """The files under a folder whose names end with `suffix`, as sorted paths relative to it.
    (os.walk and plain strings: a cold process computes this key on every start, and pathlib's
    rglob costs several times as much.)"""
    found = []
    for parent, _, names in os.walk(folder, followlinks=True):
        below = os.path.relpath(parent, folder)
        found.extend(name if below == "." else os.path.join(below, name) for name in names if name.endswith(suffix))
    return sorted(found)


def _read(folder: str, relative: str) -> bytes:
    with open(os.path.join(folder, relative), "rb") as f:
        return f.read()


def file_stamps(root: str | os.PathLike, package: str | os.PathLike = PACKAGE) -> tuple[str, int]:
    """A digest of the name, size, modification time and inode of every file `output_key` reads,
    and the newest of those times (ns). Equal stamps mean the same files, unless a file was
    rewritten within the clock step of its last modification: a caller trusts stamps only of
    files that were older than that when it read them."""
    root, package = os.path.realpath(root), os.fspath(package)
    h = sha256(f"{root}\0{package}\0".encode())
    newest = 0
    for folder, names in ((package, _code_files(package)), (root, _files_under(root))):
        for relative in names:
            st = os.stat(os.path.join(folder, relative))
            h.update(f"{relative}\0{st.st_size}\0{st.st_mtime_ns}\0{st.st_ino}\0".encode())
            newest = max(newest, st.st_mtime_ns)
    return h.hexdigest(), newest


def output_key(root: str | os.PathLike, package: str | os.PathLike = PACKAGE) -> str:
    root, package = os.path.realpath(root), os.fspath(package)
    h = sha256(f"shadergen-output-key-{KEY_FORMAT}\0".encode())
    h.update(generator_fingerprint(package).encode() + b"\0")
    h.update(str(root).encode() + b"\0")
    for relative in _files_under(root):
        h.update(relative.encode() + b"\0" + _read(root, relative) + b"\0")
    return h.hexdigest()
