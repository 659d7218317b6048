"""Struct members nothing reads, and the statements that only store them.

A library struct carries what every use of it needs: the specular lobe keeps its tangent frame,
its directional albedo and its Fresnel set-up for the light loop, which a shader lit by the
environment alone does not have. Such a member is written when the struct is prepared and never
read. A member (a struct's, by the checked type of what it is read from) is dead when every
occurrence of it in the stage's kept items is inside a store to a dead member (`lobe.frame = ...;`,
`lobe.Vt.z = max(lobe.Vt.z, ...);`, `lobe.Vt = lobe.V * lobe.frame;` once Vt is dead) that does
nothing else (no call that writes through a parameter or outside itself). Those statements go, and
the members. A member the roots (main, generated functions) mention stays: they are read, never
edited. A struct built by its constructor (positional arguments), compared whole, or the type of a
global, a uniform or a stage variable (an interface: a layout a client binds) keeps every member,
and every struct keeps at least its first (no target has empty structs). Unlike the text pass, a
store under a brace-less `if` goes too (the IR has no braces to keep right); an `if` left with
nothing to do goes with it when its condition calls nothing.

Rewritten items are memoised per (item, the dead members it holds): a request adds up facts, and
rebuilds only what its dead set has not rebuilt before.
"""
from collections import Counter
from functools import lru_cache

from .. import ir
from ..facts import Facts, collect, facts
from .rewrite import items_in, rebuild_list


def run(items: list, roots=()) -> tuple[list, int]:
    """The items without dead members and their stores; the count is members plus statements
    removed. `roots`: statements and generated functions, or their facts.collect. Memoised per
    (items, the members the roots mention, the structs they build)."""
    root_facts = roots if isinstance(roots, Facts) else collect(roots)
    out, count = _run(tuple(items), frozenset(root_facts.members), root_facts.whole)
    return list(out), count


@lru_cache(maxsize=4096)
def _run(items: tuple, root_members: frozenset, root_whole: frozenset) -> tuple[tuple, int]:
    flat = [i for unit in items for i in items_in(unit)]
    structs = [i for i in flat if isinstance(i, ir.Struct)]
    if not structs:
        return items, 0
    item_facts = [facts(i) for i in flat]
    whole = set(root_whole).union(*(f.whole for f in item_facts))
    whole.update(i.type.partition("[")[0] for i in flat if isinstance(i, ir.Global))
    members = {s.name: [m for _, m in s.members] for s in structs if s.name not in whole}
    candidates = {(s, m) for s, ms in members.items() for m in ms}
    total = Counter()
    for f in item_facts:
        total.update(f.members)
    untyped = {m for s, m in total if s is None} | {m for s, m in root_members if s is None}
    candidates = {c for c in candidates if c not in root_members and c[1] not in untyped}
    stores = [s for f in item_facts for s in f.stores if s.removable]
    dead = _dead(candidates, total, stores)
    for name, ms in members.items():  # every struct keeps a member: take its first out and look again
        if ms and all((name, m) in dead for m in ms):
            candidates.discard((name, ms[0]))
            dead = _dead(candidates, total, stores)
    if not dead:
        return items, 0
    dropped = {id(s.statement) for s in stores if s.members & dead}
    count = len(dead) + len(dropped)
    return tuple(_without(unit, held) if (held := frozenset(dead & _held(unit))) else unit for unit in items), count


def _dead(candidates: set, total: Counter, stores: list) -> set:
    """The candidates every occurrence of which is inside a store to a dead member (itself or
    another), to a fixed point."""
    inside = {}
    for s in stores:
        for m in s.occurrences.keys() & candidates:
            inside.setdefault(m, []).append(s)
    dead: set = set()
    changed = True
    while changed:
        changed = False
        for m in sorted(candidates - dead):
            within = sum(s.occurrences[m] for s in inside.get(m, ()) if m in s.members or s.members & dead)
            if within == total[m]:
                dead.add(m)
                changed = True
    return dead


@lru_cache(maxsize=16384)
def _held(unit) -> frozenset:
    """The (struct, member) pairs an item declares or stores: what of a dead set can change it."""
    found = set()
    for item in items_in(unit):
        if isinstance(item, ir.Struct):
            found.update((item.name, m) for _, m in item.members)
        else:
            for s in facts(item).stores:
                found.update(s.members)
    return frozenset(found)


@lru_cache(maxsize=16384)
def _without(unit, dead: frozenset):
    """`unit` without the dead members it declares and the stores of them it holds."""
    if isinstance(unit, ir.Struct):
        return ir.replace(unit, members=[(t, m) for t, m in unit.members if (unit.name, m) not in dead])
    if isinstance(unit, ir.Section):
        return ir.replace(unit, body=[_without(u, dead) for u in unit.body],
                          other=None if unit.other is None else [_without(u, dead) for u in unit.other])
    drop = {id(s.statement) for s in facts(unit).stores if s.removable and s.members & dead}
    return rebuild_list([unit], lambda stmt: [] if id(stmt) in drop else None)[0]
