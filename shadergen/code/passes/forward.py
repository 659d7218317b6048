"""Forwarding functions called straight.

A library function whose whole body is `return target(arguments);`, each argument one of its own
parameters, in the order it takes them, or a literal, is a name for a call: the way of lighting or
the features a shader was generated for often reduce a dispatcher to one (the environment a lobe
reflects, without a thin film, is the samples without the film). Its callers call the target
instead, with their own arguments put where the parameters were, and the forwarding function
leaves the stage. The same computation (facts.py checks it per function): every parameter is passed
once, in order, with the same type and qualifier as the target's parameter it becomes, and the
return types are equal; here, per stage, the target and the forwarding function each have one
definition among the items (by name: no overload a target resolving names could choose otherwise,
no other side of a section the key would also name). A forwarding function the
roots (main) call is left alone, and so are its callers: the roots are not edited.
"""
from functools import lru_cache

from .. import ir
from ..facts import Facts, collect, facts
from .rewrite import items_in, rebuild_list


def run(items: list, roots=()) -> tuple[list, int]:
    """The items with calls of forwarding functions made to their targets and the forwarding
    functions dropped; the count is the calls redirected. `roots`: statements and generated
    functions, or their facts.collect. Memoised per (items, what the roots call)."""
    root_facts = roots if isinstance(roots, Facts) else collect(roots)
    out, count = _run(tuple(items), frozenset(root_facts.calls))
    return list(out), count


@lru_cache(maxsize=4096)
def _run(items: tuple, called_by_roots: frozenset) -> tuple[tuple, int]:
    flat = [i for unit in items for i in items_in(unit)]
    definitions: dict[str, int] = {}
    for i in flat:
        if isinstance(i, ir.Function):
            definitions[i.name] = definitions.get(i.name, 0) + 1
    forwarders = frozenset(i for i in flat if isinstance(i, ir.Function) and facts(i).forwards is not None
                           and definitions[i.name] == 1 and definitions.get(facts(i).forwards[0].name) == 1
                           and i.key not in called_by_roots)
    if not forwarders:
        return items, 0
    keys = {f.key for f in forwarders}
    out, count = [], 0
    for unit in items:
        kept = _without_forwarders(unit, keys)
        if kept is None:
            continue
        if any(not keys.isdisjoint(facts(i).calls) for i in items_in(kept)):
            kept, n = _redirected(kept, forwarders)
            count += n
        out.append(kept)
    return tuple(out), count


def _without_forwarders(unit, keys):
    if isinstance(unit, ir.Function):
        return None if unit.key in keys else unit
    if not isinstance(unit, ir.Section):
        return unit
    body = [k for k in (_without_forwarders(u, keys) for u in unit.body) if k is not None]
    other = [k for k in (_without_forwarders(u, keys) for u in unit.other or ()) if k is not None]
    if not body and not other:
        return None
    if len(body) == len(unit.body) and len(other) == len(unit.other or ()):
        return unit
    return ir.replace(unit, body=body, other=other or None)


@lru_cache(maxsize=16384)
def _redirected(unit, forwarders: frozenset) -> tuple:
    """`unit` with every call of a forwarding function made to its target (through chains of
    them), and how many calls changed."""
    by_key = {f.key: facts(f).forwards for f in forwarders}
    count = 0

    def call(expr):
        nonlocal count
        seen = set()
        while isinstance(expr, ir.Call) and expr.callee is not None and expr.callee.key in by_key \
                and expr.callee.key not in seen:
            seen.add(expr.callee.key)
            target, arguments = by_key[expr.callee.key]
            given = {p.name: a for p, a in zip(expr.callee.params, expr.args)}
            args = [given[a.name] if isinstance(a, ir.Name) and a.name in given and a.kind in ("param", None) else a
                    for a in arguments]
            expr = ir.Call(target.name, args, type=expr.type, where=expr.where, callee=target)
            count += 1
        return expr

    return rebuild_list([unit], expression=call)[0], count
