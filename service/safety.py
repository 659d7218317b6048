"""Checks on what clients upload, done before any parser sees it.

MaterialX documents never need a DOCTYPE, and every XML bomb (entity expansion) and external
entity needs one, so a document with a DOCTYPE is refused outright rather than parsed carefully.
(The generator's own parser refuses DTDs, entity declarations and external entities, and xi:include
as well: this is the first wall.)"""
import os
import re
from pathlib import Path

from shadergen.paths import inside

from .errors import ServiceError

# what may come before the root element besides a DOCTYPE: space, comments, processing instructions
_PROLOG_ITEM = re.compile(rb"\s+|<!--.*?-->|<\?.*?\?>", re.DOTALL)


def _has_doctype(raw: bytes) -> bool:
    """Whether the prolog holds a DOCTYPE. A DTD (and so any entity declaration) can only stand
    there; the same text inside a comment or CDATA is text, and after the root a parse error."""
    position = 3 if raw.startswith(b"\xef\xbb\xbf") else 0
    while (item := _PROLOG_ITEM.match(raw, position)) is not None:
        position = item.end()
    return raw.startswith(b"<!DOCTYPE", position)


def check_document(raw: bytes) -> str:
    """The document as text, or a 400 for anything that is not plain UTF-8 XML without a DTD."""
    if _has_doctype(raw):
        raise ServiceError("unsafe_xml", "documents with a DOCTYPE (and so entity declarations) are refused")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ServiceError("invalid_document", f"the document is not UTF-8: {exc.reason}",
                           f"byte {exc.start}") from None
    if "\x00" in text:
        raise ServiceError("invalid_document", "the document contains a NUL character")
    return text


def check_texture_paths(record: dict, roots: list[str]) -> None:
    """Every filename a shader will read must resolve inside a configured texture root, so a
    document cannot make a render worker read the server's files (`/etc/passwd`, `../../key`)."""
    for stage in (record.get("blocks") or {}).values():
        for variables in stage.values():
            for var in variables:
                value = var.get("value")
                if var.get("type") != "filename" or not value:
                    continue
                if not isinstance(value, str) or texture_in_roots(value, roots) is None:
                    raise ServiceError("path_not_allowed",
                                       f"texture {value!r} is outside the configured texture roots",
                                       var.get("path"))


def texture_in_roots(value: str, roots: list[str]) -> Path | None:
    """The real path a filename names inside one of the configured roots, or None when it names a
    URL, holds a NUL or leaves them: what thumbnails may read, and what the editor may fetch.
    The name is made normal as written (`a/x/../b` is `a/b`) and must lie in a root, as configured
    or as it really is, before the file system is asked anything: resolved by the file system,
    `..` after a folder outside the roots goes wherever that folder really is, so what the server
    keeps outside them (a folder, a link and where it leads, nothing) would decide the answer. A
    root configured through a link is one folder under both names, so a texture named through the
    link is in it. Links inside a root are still followed, and what they lead to must be in a
    real root."""
    if "://" in value or "\x00" in value:
        return None
    real_roots = [Path(os.path.realpath(r)) for r in roots]
    candidate = Path(value)
    if candidate.is_absolute():
        written = Path(os.path.normpath(candidate))
        as_configured = [Path(os.path.normpath(os.path.abspath(r))) for r in roots]
        if not any(inside(written, root) for root in real_roots + as_configured):
            return None
        real = Path(os.path.realpath(written))
        return real if any(inside(real, root) for root in real_roots) else None
    # relative names are looked up under a root and must stay under that same root; the first
    # root that holds the file, else the first the name stays in (a missing file is no escape)
    staying = [real for root in real_roots if inside(written := Path(os.path.normpath(root / candidate)), root)
               and inside(real := Path(os.path.realpath(written)), root)]
    return next((real for real in staying if _is_file(real)), staying[0] if staying else None)


def _is_file(path: Path) -> bool:
    """Path.is_file, with a name the system refuses (too long: ENAMETOOLONG) no file either."""
    try:
        return path.is_file()
    except OSError:
        return False
