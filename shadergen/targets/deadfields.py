"""Struct members nothing reads, and the statements that only store them (GLSL, ESSL, WGSL).

A library struct carries what every use of it needs: the specular lobe keeps its tangent frame,
its directional albedo and its Fresnel set-up for the light loop, which a shader lit by the
environment alone does not have. Such a member is written when the struct is prepared and never
read. A member is dead when every `.member` of the stage is inside a statement that stores to a
dead member (`lobe.frame = ...;`, `lobe.Vt.z = max(lobe.Vt.z, ...);`, `lobe.Vt = lobe.V *
lobe.frame;` once Vt is dead) and such a statement does nothing else: no call that writes through
an `out` parameter or a pointer, no increment, no second assignment. Those statements go, and the
members. Structs a stage builds with their constructor (`ClosureData(...)`) keep every member,
since the constructor's arguments are positional; so do statements a brace-less `if`/`for`
governs, and the last member of a struct. Names are matched without types: a `.member` of any
struct counts as a read, which can only keep more.

The facts of each item (a function, a struct) are memoised: library items recur in every request,
and a request only adds them up over the items its stage keeps.
"""
import re
from collections import Counter, namedtuple
from functools import lru_cache

MEMBER_USE = re.compile(r"\.([A-Za-z_]\w*)\b")
# a call read backwards: `(`, blanks, then the name reversed (kept when it starts with a letter or
# `_`). Forwards, the regex engine tries a name at every letter of the text; backwards it jumps from
# one `(` to the next: ten times faster over the library code of a shader
REVERSED_CALL = re.compile(r"\(\s*(\w+)")
NAME_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_")
# a statement storing to a member: `name.member`, `(*pointer).member`, optionally a swizzle of it
STORE = re.compile(r"^\s*(?:\w+|\(\*\w+\))\.([A-Za-z_]\w*)(?:\.[A-Za-z_]\w*)?\s*(?:[-+*/]?=)(?!=)")
OTHER_EFFECT = re.compile(r"\+\+|--|(?<![&])&(?![&])|[^=!<>+\-*/]=[^=]")
BUILTIN_WRITERS = frozenset({"modf", "frexp"})  # GLSL's value-returning built-ins with an out parameter
SIGNATURE = re.compile(r"^(?:fn|\w+)\s+(\w+)\s*\(([^()]*)\)")
WRITTEN_PARAMETER = re.compile(r"\b(?:out|inout)\b|\bptr<")
GLSL_STRUCT = re.compile(r"^struct\s+(\w+)\s*$")
GLSL_MEMBER = re.compile(r"^\s*\w+\s+(\w+)\s*(?:\[\w*\])?\s*;")
WGSL_STRUCT = re.compile(r"^struct\s+(\w+)\s*\{(.*)\}\s*$")


# Named tuples, not dataclasses: a cold process would import dataclasses for these alone (see graph.py).
# Store: `lines` within the item; `reads` every `.member` of the statement, its own target included
Store = namedtuple("Store", "member lines reads calls other_effect")
# Struct: `members` maps a member to its line within the item (WGSL: the struct's one line)
Struct = namedtuple("Struct", "name members one_line")
# Facts: what one item contributes: its struct (or None), member reads (a Counter), calls, stores,
# and the name of the function if it writes through a parameter (else None)
Facts = namedtuple("Facts", "struct reads calls stores writer")


def without_dead_members(items: list[tuple[str, ...]], roots: str, root_words: set[str]) -> dict[int, tuple[str, ...]]:
    """For the items a stage keeps: item index -> the item without its dead members'
    declarations and the statements that store them, for each item that changes; empty when
    nothing is dead. The roots (main, declarations: `root_words` their identifiers) are read,
    never edited: a member whose name they contain stays, and so do the members of a struct
    they construct."""
    facts = [_facts(item) for item in items]
    structs = [(k, f.struct) for k, f in enumerate(facts) if f.struct is not None]
    if not structs:
        return {}
    built = {s.name for _, s in structs  # positional constructors: their members stay
             if f"{s.name}(" in roots or any(s.name in f.calls for f in facts)}
    candidates = {m for _, s in structs if s.name not in built for m in s.members}
    candidates -= {m for _, s in structs if s.name in built for m in s.members}
    candidates -= root_words
    if not candidates:
        return {}
    writers = BUILTIN_WRITERS.union(f.writer for f in facts if f.writer)
    stores = [(k, s) for k, f in enumerate(facts) for s in f.stores if s.member in candidates]
    for _, s in stores:
        if s.other_effect or s.calls & writers:
            candidates.discard(s.member)  # a store that cannot go keeps its member
    reads = dict.fromkeys(candidates, 0)
    for f in facts:
        for m in f.reads.keys() & candidates:
            reads[m] += f.reads[m]
    dead = _fixed_point(candidates, reads, [s for _, s in stores if s.member in candidates])
    for _, s in structs:  # GLSL and WGSL have no empty structs: the last member stays
        if dead >= set(s.members):
            dead.discard(min(s.members))
    drop: dict[int, set[int]] = {}
    for k, s in stores:
        if s.member in dead:
            drop.setdefault(k, set()).update(s.lines)
    for k, s in structs:
        if dead.intersection(s.members):
            drop.setdefault(k, set()).update(() if s.one_line else (i for m, i in s.members.items() if m in dead))
    return {k: tuple(_rewrite_struct(line, dead) for i, line in enumerate(items[k]) if i not in lines)
            for k, lines in drop.items()}


def _fixed_point(candidates: set[str], reads: dict[str, int], stores: list[Store]) -> set[str]:
    """The members whose every read is inside a store to a dead member (itself or another)."""
    dead: set[str] = set()
    changed = True
    while changed:
        changed = False
        for m in sorted(candidates - dead):
            inside = sum(s.reads[m] for s in stores if s.member in dead or s.member == m)
            if reads[m] == inside:
                dead.add(m)
                changed = True
    return dead


def _rewrite_struct(line: str, dead: set[str]) -> str:
    """A one-line WGSL struct without the dead members."""
    m = WGSL_STRUCT.match(line)
    if m is None:
        return line
    entries = [entry for name, entry in _wgsl_entries(m.group(2)) if name not in dead]
    return f"struct {m.group(1)} {{ {', '.join(entries)} }}"


def code_of(line: str) -> str:
    """One line of source without its `//` comment (the scans of deadcode.py and forwarding.py too)."""
    return line.split("//", 1)[0] if "//" in line else line


@lru_cache(maxsize=8192)
def code_text(item: tuple[str, ...]) -> str:
    """An item's lines without their comments, joined: what every scan of an item reads."""
    return "\n".join([code_of(line) for line in item])


def called_names(code: str) -> frozenset[str]:
    """The names code calls: each a whole word before blanks and a `(`."""
    return frozenset(word[::-1] for word in REVERSED_CALL.findall(code[::-1]) if word[-1] in NAME_START)


@lru_cache(maxsize=8192)
def _facts(item: tuple[str, ...]) -> Facts:
    code = code_text(item)
    code_lines = code.split("\n")
    signature = SIGNATURE.match(_signature(code_lines))
    writer = signature.group(1) if signature and WRITTEN_PARAMETER.search(signature.group(2)) else None
    struct = _struct(item, code_lines) if "struct" in code else None
    return Facts(struct, Counter(MEMBER_USE.findall(code)), called_names(code),
                 _stores(code_lines), writer)


def _signature(code_lines: list[str]) -> str:
    """The item's first code line, continued up to its first `)` (a signature may span lines)."""
    first = next((k for k, line in enumerate(code_lines) if line.strip()), len(code_lines))
    header = ""
    for line in code_lines[first:]:
        header += line
        if ")" in line:
            break
    return header


def _struct(item: tuple[str, ...], code_lines: list[str]) -> Struct | None:
    for k, line in enumerate(item):
        if not line.startswith("struct"):  # both patterns start so: most items have no such line
            continue
        m = WGSL_STRUCT.match(line)
        if m:
            return Struct(m.group(1), {name: k for name, _ in _wgsl_entries(m.group(2))}, True)
        m = GLSL_STRUCT.match(line)
        if m and k + 1 < len(item) and item[k + 1].strip() == "{":
            members = {}
            for j in range(k + 2, len(item)):
                if item[j].strip().startswith("}"):
                    break
                member = GLSL_MEMBER.match(code_lines[j])
                if member is None:  # several declarators, or something unexpected: leave it alone
                    return None
                members[member.group(1)] = j
            return Struct(m.group(1), members, False) if members else None
    return None


def _wgsl_entries(body: str) -> list[tuple[str, str]]:
    """(member, entry) of a one-line WGSL struct body (`a: f32, b: array<f32, 3>`)."""
    entries, depth, start = [], 0, 0
    for k, ch in enumerate(body + ","):
        depth += {"<": 1, ">": -1}.get(ch, 0)
        if ch == "," and depth == 0:
            entry = body[start:k].strip()
            if entry:
                entries.append((entry.split(":", 1)[0].strip(), entry))
            start = k + 1
    return entries


def _stores(code_lines: list[str]) -> tuple[Store, ...]:
    """The store statements that could go on their own: not the body of a brace-less `if`,
    `else` or `for` (the code line before a store must end a statement or a block)."""
    found, taken = [], 0  # lines before `taken` are a found store's
    for k in [k for k, line in enumerate(code_lines) if "=" in line and "." in line]:  # what STORE needs
        if k < taken:
            continue
        code = code_lines[k].strip()
        m = STORE.match(code)
        if m is None or not _code_before(code_lines, k).endswith((";", "{", "}")):
            continue
        end, text = k, code
        while not text.endswith(";") and end + 1 < len(code_lines):
            end += 1
            text += " " + code_lines[end].strip()
        rhs = text.split("=", 1)[1]
        found.append(Store(m.group(1), range(k, end + 1), Counter(MEMBER_USE.findall(text)),
                           called_names(rhs), OTHER_EFFECT.search(rhs) is not None))
        taken = end + 1
    return tuple(found)


def _code_before(code_lines: list[str], k: int) -> str:
    """The last line before line k that has code, stripped ("" when none)."""
    for j in range(k - 1, -1, -1):
        code = code_lines[j].strip()
        if code:
            return code
    return ""
