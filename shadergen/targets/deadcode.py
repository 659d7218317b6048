"""Dead code of a C-like stage (GLSL, ESSL): only the definitions the stage's main reaches.

Library files bring whole families of functions (a file per closure operator defines its BSDF,
EDF and VDF forms); the stage needs only what `main` calls, directly or through what it calls.
Top-level items are split by brace depth: a function, a struct, a `#define`, a global, each with
the comment lines just above it. Items whose name cannot be read are kept.

A comment block that a blank line separates from what follows documents the library *file* (its
header, a "--- Dielectric ---" divider): it describes functions the shader mostly does not have,
in an order the shader does not keep, so it is left out of every stage. Comments attached to a
function, struct or definition stay with it.
"""
import re
from functools import lru_cache

from .deadfields import code_of, without_dead_members
from .forwarding import without_forwarding

# GLSL identifiers are ASCII: matched as such, the scan runs about twice as fast as with Unicode
# word classes (every item of every library file a shader includes is scanned once per process).
IDENTIFIER = re.compile(r"\b[A-Za-z_]\w*", re.ASCII)
COMMENT = re.compile(r"//.*")
NAMES = (re.compile(r"^\s*#\s*define\s+(\w+)"), re.compile(r"^\s*struct\s+(\w+)"),
         re.compile(r"^\s*(?:const\s+)?\w+\s+(\w+)\s*(?:\(|=|;|\[)"))

GUARD = re.compile(r"^\s*#\s*ifndef\s+(\w+)\s*$")
ENDIF = re.compile(r"^\s*#\s*endif\b")


def split_items(lines: list[str]) -> list[tuple[str | None, list[str]]]:
    """(defined name or None, lines) for each top-level item, comments attached to what follows."""
    items, current, pending, depth = [], [], [], 0
    index = 0
    while index < len(lines):
        line = lines[index]
        index += 1
        if not current:  # between items (an item ends where its braces balance)
            stripped = line.strip()
            if not stripped or stripped.startswith("//"):
                pending.append(line)
                continue
            if stripped.startswith("#"):
                guarded = _default_definition(lines, index - 1)
                if guarded:
                    items.append((guarded, _attached(pending) + lines[index - 1:index + 2]))
                    pending = []
                    index += 2
                    continue
                if not stripped.endswith("\\"):
                    items.append((_name(stripped), _attached(pending) + [line]))
                    pending = []
                    continue
        current.append(line)
        if "{" in line or "}" in line:
            depth += _braces(line)
        if depth == 0 and line.rstrip().endswith(("}", ";")):
            items.append((_name(current[0].strip()), _attached(pending) + current))
            current, pending = [], []
    if current or pending:
        items.append((None, _attached(pending) + current))
    return items


def _default_definition(lines: list[str], index: int) -> str | None:
    """The name X when lines[index:] start with `#ifndef X`, `#define X ...`, `#endif`: a default a
    compiler option may override, one item that is kept only where X is used."""
    m = GUARD.match(lines[index])
    if m and index + 2 < len(lines) and _name(lines[index + 1].strip()) == m.group(1) \
            and ENDIF.match(lines[index + 2]):
        return m.group(1)
    return None


def _attached(pending: list[str]) -> list[str]:
    """The blank and comment lines before an item without its detached comment blocks: only the
    comments after the last blank line document the item (the blank lines stay: they space it)."""
    last_blank = max((i for i, line in enumerate(pending) if not line.strip()), default=-1)
    return [line for i, line in enumerate(pending) if i > last_blank or not line.strip()]


def _braces(line: str) -> int:
    code = code_of(line)
    return code.count("{") - code.count("}")


def _name(first_line: str) -> str | None:
    for pattern in NAMES:
        m = pattern.match(first_line)
        if m:
            return m.group(1)
    return None


class Section:
    """A function section split into items, with which items each item uses: computed once per
    section (shaders of one topology have the same one, request after request)."""

    def __init__(self, function_lines: tuple[str, ...]):
        split = split_items(list(function_lines))
        self.items = [tuple(lines) for _, lines in split]
        names = [name for name, _ in split]
        self.words = [_words(lines) for lines in self.items]
        self.by_name: dict[str, list[int]] = {}
        for k, name in enumerate(names):
            if name is not None:
                self.by_name.setdefault(name, []).append(k)
        self.always = [k for k, name in enumerate(names) if name is None]  # kept: their names cannot be read
        self.uses = [self.defining(words) for words in self.words]

    def defining(self, words) -> set[int]:
        return {k for w in self.by_name.keys() & words for k in self.by_name[w]}

    def reachable(self, root_words: set[str], edited: dict[int, tuple[str, ...]]) -> tuple[list[int], set[str]]:
        """The indices of the items the roots use, transitively, in their original order, and every
        identifier the roots and those items use; `edited` replaces some items' lines."""
        def words(k: int) -> frozenset[str]:
            return _words(edited[k]) if k in edited else self.words[k]

        keep = set(self.always) | self.defining(root_words)
        todo = list(keep)
        while todo:
            k = todo.pop()
            for used_item in self.defining(words(k)) if k in edited else self.uses[k]:
                if used_item not in keep:
                    keep.add(used_item)
                    todo.append(used_item)
        used = root_words.union(*(words(k) for k in keep))
        return sorted(keep), used


@lru_cache(maxsize=8192)
def _words(item: tuple[str, ...]) -> frozenset[str]:
    """The identifiers of an item: library functions recur in every request, so this is memoised."""
    return frozenset(identifiers("\n".join(item)))


@lru_cache(maxsize=64)
def _section(function_lines: tuple[str, ...]) -> Section:
    return Section(function_lines)


def used_functions(function_lines: list[str], roots: str) -> tuple[list[str], set[str]]:
    """The function section's lines, reduced to what `roots` (main and declarations) use, and the
    identifiers used by the roots and those lines. Items keep the spacing of their sources: one
    blank line where the source had one or where dropped items come between, none between
    neighbours that had none (a run of #defines). Struct members nothing reads go too
    (deadfields.py), callers of a forwarding function call its target (forwarding.py), and then
    whatever only those stores and calls used."""
    out, used = _reduced(_section(tuple(function_lines)), roots)
    return list(out), set(used)


@lru_cache(maxsize=1024)  # a service answers many topologies: a library of materials, a test suite
def _reduced(section: Section, roots: str) -> tuple[tuple[str, ...], frozenset[str]]:
    """A section reduced to what `roots` use: shaders of one topology have the same main, request
    after request, so the walk and the reassembly are done once for each."""
    root_words = identifiers(roots)
    edited: dict[int, tuple[str, ...]] = {}
    keep, used = section.reachable(root_words, edited)
    while True:  # a store or a call that goes may have been the last use of a function
        items = [edited.get(k, section.items[k]) for k in keep]
        changed = without_dead_members(items, roots, root_words)
        changed.update(without_forwarding([changed.get(i, item) for i, item in enumerate(items)], root_words))
        if not changed:
            return _joined(section, keep, edited), frozenset(used)
        edited.update((keep[i], item) for i, item in changed.items())
        keep, used = section.reachable(root_words, edited)


def _joined(section: Section, keep: list[int], edited: dict[int, tuple[str, ...]]) -> tuple[str, ...]:
    """The kept items' lines (`edited` replacing some), spaced as the module's doc says."""
    out: list[str] = []
    previous = None
    for k in keep:
        lines = edited.get(k, section.items[k])
        first = next((i for i, line in enumerate(lines) if line.strip()), len(lines))
        if out and (first > 0 or previous != k - 1):
            out.append("")
        for line in lines[first:]:
            if line.strip() or out[-1].strip():
                out.append(line)
        previous = k
    if out and out[-1].strip():
        out.append("")
    return tuple(out)


def identifiers(text: str) -> set[str]:
    """The identifiers of code: a name a comment mentions keeps nothing alive."""
    return set(IDENTIFIER.findall(COMMENT.sub("", text)))
