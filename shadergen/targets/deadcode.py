"""Dead code of a C-like stage (GLSL, ESSL): only the definitions the stage's main reaches.

Library files bring whole families of functions (a file per closure operator defines its BSDF,
EDF and VDF forms); the stage needs only what `main` calls, directly or through what it calls.
Top-level items are split by brace depth: a function, a struct, a `#define`, a global, each with
the comment lines just above it. Items whose name cannot be read are kept.
"""
import re
from functools import lru_cache

IDENTIFIER = re.compile(r"\b[A-Za-z_]\w*\b")
NAMES = (re.compile(r"^\s*#\s*define\s+(\w+)"), re.compile(r"^\s*struct\s+(\w+)"),
         re.compile(r"^\s*(?:const\s+)?\w+\s+(\w+)\s*(?:\(|=|;|\[)"))


def split_items(lines: list[str]) -> list[tuple[str | None, list[str]]]:
    """(defined name or None, lines) for each top-level item, comments attached to what follows."""
    items, current, pending, depth = [], [], [], 0
    for line in lines:
        stripped = line.strip()
        if depth == 0 and not current:
            if not stripped or stripped.startswith("//"):
                pending.append(line)
                continue
            if stripped.startswith("#") and not stripped.endswith("\\"):
                items.append((_name(stripped), pending + [line]))
                pending = []
                continue
        current.append(line)
        depth += _braces(line)
        if depth == 0 and (stripped.endswith("}") or stripped.endswith(";")):
            items.append((_name(current[0].strip()), pending + current))
            current, pending = [], []
    if current or pending:
        items.append((None, pending + current))
    return items


def _braces(line: str) -> int:
    code = line.split("//", 1)[0]
    return code.count("{") - code.count("}")


def _name(first_line: str) -> str | None:
    for pattern in NAMES:
        m = pattern.match(first_line)
        if m:
            return m.group(1)
    return None


def reachable(items: tuple[tuple[str | None, tuple[str, ...]], ...], roots: str) -> tuple[list[int], set[str]]:
    """The indices of the items the roots use, transitively, in their original order, and every
    identifier the roots and those items use."""
    by_name: dict[str, list[int]] = {}
    for k, (name, _) in enumerate(items):
        if name is not None:
            by_name.setdefault(name, []).append(k)
    keep = {k for k, (name, _) in enumerate(items) if name is None}
    todo = set(IDENTIFIER.findall(roots)) | {w for k in keep for w in _words(items[k][1])}
    seen: set[str] = set()
    while todo:
        word = todo.pop()
        if word in seen:
            continue
        seen.add(word)
        for k in by_name.get(word, ()):
            if k not in keep:
                keep.add(k)
                todo.update(_words(items[k][1]))
    return sorted(keep), seen


@lru_cache(maxsize=8192)
def _words(item: tuple[str, ...]) -> frozenset[str]:
    """The identifiers of an item: library functions recur in every request, so this is memoised."""
    return frozenset(IDENTIFIER.findall("\n".join(item)))


@lru_cache(maxsize=64)
def _split(function_lines: tuple[str, ...]) -> tuple[tuple[str | None, tuple[str, ...]], ...]:
    """split_items, memoised: shaders of one topology have the same function section, request after request."""
    return tuple((name, tuple(lines)) for name, lines in split_items(list(function_lines)))


def used_functions(function_lines: list[str], roots: str) -> tuple[list[str], set[str]]:
    """The function section's lines, reduced to what `roots` (main and declarations) use, and the
    identifiers used by the roots and those lines."""
    items = _split(tuple(function_lines))
    keep, used = reachable(items, roots)
    out: list[str] = []
    for k in keep:
        lines = items[k][1]
        out.extend(lines)
        if lines and lines[-1].strip():
            out.append("")
    return out, used


def identifiers(text: str) -> set[str]:
    return set(IDENTIFIER.findall(text))
