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
    files that were older than that when it read them. (Every cold process stamps its 270 files:
    each is read from its directory entry and the stamps hashed at once, which costs half of
    stat-ing the listed paths one by one.)"""
    root, package = os.path.realpath(root), os.fspath(package)
    code, library = [], []
    newest = max(_stamp_files(package, ".py", "render", code), _stamp_files(root, "", None, library))
    code.sort()  # (the files in name order, as _files_under lists them: a stamp starts with the name and a NUL)
    library.sort()
    return sha256(f"{root}\0{package}\0{''.join(code)}{''.join(library)}".encode()).hexdigest(), newest


def _stamp_files(folder: str, suffix: str, skipped: str | None, out: list[str], prefix: str = "") -> int:
    """The stamps of the files under `folder` whose names end with `suffix`, outside folders named
    `skipped`, appended to `out` (their names relative to it, after `prefix`); the newest time."""
    newest = 0
    with os.scandir(folder) as entries:
        for entry in entries:
            if entry.is_dir():
                if entry.name != skipped:
                    newest = max(newest, _stamp_files(entry.path, suffix, skipped, out, prefix + entry.name + os.sep))
            elif entry.name.endswith(suffix):
                st = entry.stat()
                out.append(f"{prefix}{entry.name}\0{st.st_size}\0{st.st_mtime_ns}\0{st.st_ino}\0")
                newest = max(newest, st.st_mtime_ns)
    return newest


def output_key(root: str | os.PathLike, package: str | os.PathLike = PACKAGE) -> str:
    root, package = os.path.realpath(root), os.fspath(package)
    h = sha256(f"shadergen-output-key-{KEY_FORMAT}\0".encode())
    h.update(generator_fingerprint(package).encode() + b"\0")
    h.update(str(root).encode() + b"\0")
    for relative in _files_under(root):
        h.update(relative.encode() + b"\0" + _read(root, relative) + b"\0")
    return h.hexdigest()
