"""Feature sections and decided compiler macros resolved on the IR, as features.resolve does on
text: a section of a feature the stage needs (`#ifdef MX_FEATURE_X`, X among `features`) stays
without its directives, the section of one it does not need gives its `other` (the `#else` side,
or nothing); `features` None (a stage whose nodes were not asked) needs every feature. A compiler
macro the caller decided (`macros`: (name, defined) pairs, code/externals.py's environment_macros) resolves
the same way; any other macro's section stays a Section, for a target to write out or to give its
default. An `if`'s `else` clause held by a section (ir.Section) becomes that `if`'s `else` or
`else if`, or none.

Library items recur in every request: each item's result is memoised per the decisions of the
macros it mentions, so a request only looks up what it decides. A library function's results for
every decision a stage can make are worked out with the library's cache (code/library.py) and read
from it: a new process then neither reads, rebuilds and walks the function's body nor prints the
copy (the printed library holds them).
"""
from functools import lru_cache
from itertools import product

from .. import ir
from ..facts import facts
from .rewrite import rebuild_list

FEATURE_PREFIX = "MX_FEATURE_"


def run(items: list, features: frozenset | None, macros: frozenset = frozenset(), library=None) -> tuple[list, int]:
    """The items with their sections resolved, and how many sections were resolved. Memoised per
    (items, features, macros): a module's items recur in every request. `library`: the items'
    CodeLibrary, whose `resolution(item, decisions)` answers for its own functions."""
    out, count = _run(tuple(items), None if features is None else frozenset(features), frozenset(macros), library)
    return list(out), count


@lru_cache(maxsize=4096)
def _run(items: tuple, features: frozenset | None, macros: frozenset, library) -> tuple[tuple, int]:
    decided = dict(macros)
    out, count = [], 0
    for item in items:
        mentioned = macros_in(item)
        if not mentioned:
            out.append(item)
            continue
        decisions = tuple((m, decision(m, features, decided)) for m in mentioned)
        found = library.resolution(item, decisions) if library is not None else None
        resolved, n = found if found is not None else _resolved(item, decisions)
        out.extend(resolved)
        count += n
    return tuple(out), count


def decisions_of(mentioned: tuple, decided_options) -> list[tuple]:
    """Every `decisions` (resolve's) a stage can make of the macros `mentioned`, as _run makes
    them (decision), when the macros it decides are one of `decided_options` ((name, defined)
    sets) and it needs any set of the features among them. In order, each once."""
    features = [m[len(FEATURE_PREFIX):] for m in mentioned if m.startswith(FEATURE_PREFIX)]
    out = {}
    for decided in decided_options:
        decided = dict(decided)
        for needed in product((True, False), repeat=len(features)):
            chosen = frozenset(f for f, n in zip(features, needed) if n)
            out.setdefault(tuple((m, decision(m, chosen, decided)) for m in mentioned))
    return list(out)


def decision(macro: str, features: frozenset | None, decided: dict) -> bool | None:
    """Whether `macro` is defined for this stage; None where the stage leaves it to the target."""
    if macro in decided:
        return decided[macro]
    if macro.startswith(FEATURE_PREFIX):
        return features is None or macro[len(FEATURE_PREFIX):] in features
    return None


@lru_cache(maxsize=16384)
def macros_in(item) -> tuple[str, ...]:
    """The macros the sections of a top-level item or Section test, sorted: an item's from its
    facts (read once per library item, without its body where the library's cache holds them)."""
    if isinstance(item, ir.Section):
        found = {item.macro}
        for inner in (*item.body, *(item.other or ())):
            found.update(macros_in(inner))
        return tuple(sorted(found))
    return tuple(sorted(facts(item).macros)) if isinstance(item, ir.Item) else ()  # (a comment: none)


def resolve(item, decisions: tuple) -> tuple[tuple, int]:
    """(the items `item` becomes, the sections resolved) for `decisions`, ((macro, decision) of
    each macro it mentions, in macros_in's order)."""
    defined = {m: d for m, d in decisions if d is not None}
    count = 0

    def section(stmt):
        nonlocal count
        if not isinstance(stmt, ir.Section) or stmt.macro not in defined:
            return None
        count += 1
        return stmt.body if defined[stmt.macro] == stmt.defined else (stmt.other or [])

    return tuple(rebuild_list([item], section)), count


_resolved = lru_cache(maxsize=16384)(resolve)  # (a copy per item and decisions: later passes' memos hit)
