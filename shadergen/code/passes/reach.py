"""Only what a stage's roots use: the functions main (and the generator's own functions) call,
directly or through what they call, and the structs, constants and globals those name.

Items come in library order (each file's includes before it, its items in source order): the kept
ones keep that order, except that an item comes after every item it uses (a definition before its
use). A top-level Section (a compiler macro's, left to the target) is kept with the items of its
sides that are used, and goes when none is. Functions are matched by key (the checker's callee is
the library's own Function; the item may be its resolved copy), the others by name.
"""
from functools import lru_cache

from .. import ir
from ..facts import Facts, collect, facts
from .rewrite import items_in


class Reached:
    """items: the kept items, in order; functions: their keys; structs, constants, globals: names;
    uniforms: the uniforms the kept code and the roots read; names: every name they read that is
    not a local or a parameter (uniforms, stage inputs, vertex data, constants, globals)."""
    __slots__ = ("items", "functions", "structs", "constants", "globals", "uniforms", "names")


def run(items: list, roots=(), names=()) -> tuple[Reached, int]:
    """What `roots` (statements, generated functions; or their facts.collect) and `names` (of items
    the generator uses by name: a struct it declares, a function it calls from text) reach among
    `items`; the count is the number of items left out. Memoised per (items, what the roots call
    and name): shaders of one topology reach the same, request after request."""
    root_facts = roots if isinstance(roots, Facts) else collect(roots)
    index = _index(tuple(items))
    starts = index.uses(root_facts) + tuple(i for name in names for i in index.by_name.get(name, ()))
    found, count = _reach(index, frozenset(starts))
    reached = Reached()
    for name in Reached.__slots__:
        setattr(reached, name, getattr(found, name))
    reached.items = list(found.items)  # the caller's to change
    reached.uniforms = found.uniforms | root_facts.uniforms
    reached.names = found.names.union(root_facts.names)
    return reached, count


class _Index:
    """The items of a stage by key and name, and what each uses among them (memoised here: the
    same items recur in every request of a topology)."""
    __slots__ = ("units", "by_key", "by_name", "unit_of", "used")

    def __init__(self, units: tuple):
        self.units = units  # top-level items and Sections
        self.by_key, self.by_name, self.unit_of, self.used = {}, {}, {}, {}
        for u, unit in enumerate(units):
            for item in items_in(unit):
                self.unit_of[id(item)] = u
                if isinstance(item, ir.Function):
                    self.by_key.setdefault(item.key, []).append(item)
                self.by_name.setdefault(item.name, []).append(item)

    def uses(self, f: Facts) -> tuple:
        found = [i for key in f.calls for i in self.by_key.get(key, ())]
        found += [i for name in f.names + f.types for i in self.by_name.get(name, ()) if not isinstance(i, ir.Function)]
        return tuple(found)

    def uses_of(self, item) -> tuple:
        if id(item) not in self.used:
            self.used[id(item)] = self.uses(facts(item))
        return self.used[id(item)]


@lru_cache(maxsize=256)
def _index(units: tuple) -> _Index:
    return _Index(units)


@lru_cache(maxsize=4096)
def _reach(index: _Index, starts: frozenset) -> tuple[Reached, int]:
    kept: dict[int, object] = {}
    todo = list(starts)
    read_uniforms, read_names = set(), set()
    while todo:
        item = todo.pop()
        if id(item) in kept:
            continue
        kept[id(item)] = item
        f = facts(item)
        read_uniforms |= f.uniforms
        read_names.update(f.names)
        todo.extend(index.uses_of(item))
    out = [_kept_part(index.units[u], kept) for u in _ordered(index, kept)]
    flat = [i for unit in out for i in items_in(unit)]
    reached = Reached()
    reached.items = out
    reached.functions = tuple(i.key for i in flat if isinstance(i, ir.Function))
    reached.structs = tuple(i.name for i in flat if isinstance(i, ir.Struct))
    reached.constants = tuple(i.name for i in flat if isinstance(i, ir.Constant))
    reached.globals = tuple(i.name for i in flat if isinstance(i, ir.Global))
    reached.uniforms = frozenset(read_uniforms)
    reached.names = frozenset(read_names)
    return reached, len(index.unit_of) - len(flat)


def _ordered(index: _Index, kept: dict) -> list[int]:
    """The units holding kept items, in library order, each after the units it uses."""
    unit_of = index.unit_of
    needed = sorted({unit_of[k] for k in kept})
    deps = {u: set() for u in needed}
    for item in kept.values():
        u = unit_of[id(item)]
        deps[u].update(unit_of[id(d)] for d in index.uses_of(item) if unit_of[id(d)] != u)
    order, placed, visiting = [], set(), set()

    def place(u):
        if u in placed or u in visiting:
            return
        visiting.add(u)
        for d in sorted(deps[u]):
            place(d)
        visiting.discard(u)
        placed.add(u)
        order.append(u)

    for u in needed:
        place(u)
    return order


def _kept_part(unit, kept):
    """A unit with only its kept items (a Section's unused items dropped; None when none is kept)."""
    if not isinstance(unit, ir.Section):
        return unit if id(unit) in kept else None
    body = [p for p in (_kept_part(u, kept) for u in unit.body) if p is not None]
    other = [p for p in (_kept_part(u, kept) for u in unit.other or ()) if p is not None]
    if not body and not other:
        return None
    if body == list(unit.body) and other == list(unit.other or ()):
        return unit
    return ir.replace(unit, body=body, other=other or None)
