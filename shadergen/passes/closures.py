"""Closure simplification: lobes that cannot contribute are removed, and the closure operators
around them simplify. A removed closure is an unconnected closure input: the closure's zero (no
response, everything let through). The rules are per closure operator, not per shading model:

- a lobe whose `weight` is a constant <= 0 is removed, where it gives the closure's zero there
  (read from the lobe function's IR: SourceFunctionImpl); an emitter whose `color`
  is a constant black is removed;
- `layer` with a removed top is its base, with a removed base its top;
- `add` with a removed operand is the other;
- a closure node whose closure inputs are all removed is removed (mix, multiply, layer, add, and
  modifiers such as generalized_schlick_edf give zero from zero);
- `mix` at weight 0 or 1 and `multiply` by 1 are algebraic identities (fold.py).

Afterwards each surface knows whether any lobe under it transmits light, so that the transmission
context is only written where it can contribute.
"""
from ..graph import Graph, Input, Node
from ..nodes.base import SourceFunctionImpl
from ..types import TYPES
from .edit import can_pass, pass_through, readers, set_constant
from .fold import constant
from .order import topological_order

PASS_THROUGH = {"layer": (("top", "base"), ("base", "top")), "add": (("in1", "in2"), ("in2", "in1"))}
CLOSURE_TYPES = frozenset(name for name, t in TYPES.items() if t.is_closure)


def is_closure_node(node: Node) -> bool:
    return any(o.type in CLOSURE_TYPES for o in node.outputs.values())


def closure_inputs(node: Node) -> list[Input]:
    return [i for i in node.inputs.values() if TYPES[i.type].is_closure]


def prune_closures(graph: Graph) -> int:
    """Returns how many closure nodes were removed or bypassed."""
    reading = None  # who reads each output: found at the first edit (most graphs have none)
    count = 0
    for node in graph.nodes:
        if not is_closure_node(node):
            continue
        if removable(node):
            reading = readers(graph) if reading is None else reading
            for out in node.outputs.values():
                for inp in reading.pop(id(out), []):
                    set_constant(inp, None)
            count += 1
            continue
        for removed, kept in PASS_THROUGH.get(node.category, ()):
            inp = node.inputs.get(removed)
            if inp is not None and _is_removed(inp) and can_pass(node.inputs[kept], node):
                reading = readers(graph) if reading is None else reading
                pass_through(graph, node, node.inputs[kept], reading)
                count += 1
                break
    if count:  # unchanged, the order stands
        graph.nodes = topological_order(graph.outputs)
    for node in graph.nodes:
        if node.category == "surface" and "bsdf" in node.inputs:
            node.facts["transmission"] = any(transmits(n) for n in closure_tree(node.inputs["bsdf"]))
    return count


def _is_removed(inp: Input) -> bool:
    return inp.connection is None and inp.socket is None and not inp.public


def removable(node: Node) -> bool:
    closures = closure_inputs(node)
    if closures:
        return all(_is_removed(i) for i in closures)
    known, weight = constant(node, "weight")
    if known and _at_most_zero(weight):
        impl = node.impl
        return isinstance(impl, SourceFunctionImpl) and impl.empty_at_zero_weight
    known, color = constant(node, "color")
    return known and next(iter(node.outputs.values())).type == "EDF" and _at_most_zero(color, exact=True)


def _at_most_zero(value, exact: bool = False) -> bool:
    values = value if isinstance(value, tuple) else (value,)
    return all(v == 0 if exact else v <= 0 for v in values)


def closure_tree(inp: Input, stop=lambda node: False) -> list[Node]:
    """The closure nodes an input reads, directly or through other closure nodes; a node for
    which `stop` is true is neither listed nor walked through."""
    found, stack, seen = [], [inp], set()
    while stack:
        conn = stack.pop().connection
        if conn is None or id(conn.node) in seen or not is_closure_node(conn.node) or stop(conn.node):
            continue
        seen.add(id(conn.node))
        found.append(conn.node)
        stack.extend(closure_inputs(conn.node))
    return found


def transmits(node: Node) -> bool:
    """Whether a closure node can answer the transmission context: its source handles it (and its
    scatter_mode, when a constant, is not reflection only). Other kinds are assumed to. An operator
    (layer, mix, add, ...) only passes on what its lobes answer: they decide."""
    if closure_inputs(node):
        return False
    known, mode = constant(node, "scatter_mode")
    if known and mode == "R":
        return False
    impl = node.impl
    return impl.handles_transmission if isinstance(impl, SourceFunctionImpl) else True
