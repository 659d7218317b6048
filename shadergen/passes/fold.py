"""Folding by value: a node whose inputs are all constants becomes its value in the inputs that
read it (shadergen/evaluate.py computes it), and a `constant` node of that value where it drives a
shader output; nodes with some constant inputs simplify by algebraic identities (x*1, x*0, x+0, mix
at 0 or 1, a conditional on constants, a switch on a constant). The constants are what the
interface left fixed, so `specialized` folds the most."""
from ..evaluate import CONDITIONS, NotFoldable, evaluate_outputs
from ..graph import Graph, GraphBuilder, Input, Node, Output
from ..types import TYPES, default_value
from .edit import can_pass, pass_through, readers, set_constant
from .order import topological_order

BLENDS = ("mix", "plus", "minus", "difference", "screen", "overlay", "burn", "dodge")  # bg at mix 0
# ...except where the implementation's guard against a division by zero gives 0 whatever the mix
# (compositing_impl.mtlx): a known fg must be clear of it
GUARDED_FG = {"burn": lambda f: abs(f) >= 1.0e-8, "dodge": lambda f: abs(1.0 - f) >= 1.0e-8}


def fold_constants(graph: Graph, builder: GraphBuilder) -> int:
    """Returns how many nodes were folded or simplified. `builder` makes the constant nodes."""
    reading = readers(graph)
    count = 0
    for node in graph.nodes:
        if fold_node(graph, node, reading, builder) or simplify(graph, node, reading):
            count += 1
    if count:  # unchanged, the order stands
        graph.nodes = topological_order(graph.outputs)
    return count


def constant(node: Node, name: str):
    """(True, value) when the input is a constant, else (False, None)."""
    inp = node.inputs.get(name)
    if inp is None or not inp.is_constant() or inp.type == "filename":
        return False, None
    return True, inp.value


def fold_node(graph: Graph, node: Node, reading: dict, builder: GraphBuilder) -> bool:
    if node.category == "constant" or not node.inputs or \
            any(not inp.is_constant() or inp.type == "filename" for inp in node.inputs.values()):
        return False
    try:
        values = evaluate_outputs(node.category, {n: i.value for n, i in node.inputs.items()},
                                  [(o.name, o.type) for o in node.outputs.values()])
    except NotFoldable:
        return False
    for out in node.outputs.values():
        for inp in reading.pop(id(out), []):
            set_constant(inp, values[out.name])
    for name, out in graph.outputs.items():
        if out.node is node:
            # Left as an expression, it would be made of literals alone: work the GPU does for every
            # pixel, and in WGSL abstract-typed, which only constant expressions may be.
            graph.outputs[name] = constant_output(builder, out, values[out.name])
    return True


def constant_output(builder: GraphBuilder, out: Output, value) -> Output:
    """The output of a `constant` node holding `value`, named as the node it stands for."""
    nodedef = builder.scope.nodedef(f"ND_constant_{out.type}")
    node = builder.new_node(out.node.name, "constant", out.type, nodedef,
                            builder.scope.implementation(nodedef, builder.target), out.node.path)
    node.name = out.node.name if len(out.node.outputs) == 1 else f"{out.node.name}_{out.name}"
    node.instance, node.scope = out.node.instance, out.node.scope
    node.inputs["value"].value, node.inputs["value"].path = value, None
    return node.outputs["out"]


def _clear_of_guard(node: Node) -> bool:
    """Whether the node's fg is known to miss its guard (GUARDED_FG), or it has none."""
    clear = GUARDED_FG.get(node.category)
    if clear is None:
        return True
    known, fg = constant(node, "fg")
    return known and all(clear(c) for c in (fg if isinstance(fg, tuple) else (fg,)))


def _all(value, wanted: float) -> bool:
    return all(c == wanted for c in value) if isinstance(value, tuple) else value == wanted


def simplify(graph: Graph, node: Node, reading: dict) -> bool:
    """An identity that lets an input stand for the node (or a zero for its output)."""
    source = identity_source(node)
    if isinstance(source, Input):
        if not can_pass(source, node):
            return False
        pass_through(graph, node, source, reading)
        return True
    if source == "zero":
        out = next(iter(node.outputs.values()))
        if id(out) not in reading:
            return False
        for inp in reading.pop(id(out)):
            set_constant(inp, default_value(out.type))  # what the emitted literal of no value is
        return True
    return False


def identity_source(node: Node):
    """The input the node's output equals, "zero" when it is the type's zero, or None."""
    c, i = node.category, node.inputs
    if c in BLENDS and "bg" in i:
        known, w = constant(node, "mix")
        if known and _all(w, 0.0) and _clear_of_guard(node):
            return i["bg"]
        if known and c == "mix" and _all(w, 1.0):
            return i["fg"]
    if c in CONDITIONS and "in1" in i:
        (k1, v1), (k2, v2) = constant(node, "value1"), constant(node, "value2")
        if k1 and k2:
            return i["in1"] if CONDITIONS[c](v1, v2) else i["in2"]
    if c == "switch":
        known, which = constant(node, "which")
        if known:
            return next((i[f"in{k}"] for k in range(1, 11) if which < k and f"in{k}" in i), "zero")
    if c == "rotate3d":
        known, amount = constant(node, "amount")
        if known and amount == 0.0:
            return i["in"]  # a turn by 0 degrees about any axis
    if c in ("add", "subtract", "multiply", "divide", "power") and "in2" in i:
        return _arithmetic_identity(node)
    return None


def _arithmetic_identity(node: Node):
    c, i = node.category, node.inputs
    (k1, a), (k2, b) = constant(node, "in1"), constant(node, "in2")
    closure = TYPES[i["in1"].type].is_closure
    if c == "add" and k2 and _all(b, 0.0):
        return i["in1"]
    if c == "add" and k1 and _all(a, 0.0):
        return i["in2"]
    if c == "subtract" and k2 and _all(b, 0.0):
        return i["in1"]
    if c in ("multiply", "divide", "power") and k2 and _all(b, 1.0):
        return i["in1"]
    if c == "multiply" and k1 and not closure and _all(a, 1.0):
        return i["in2"]
    if c == "multiply" and ((k2 and _all(b, 0.0) and i["in1"].type != "BSDF") or (k1 and not closure and _all(a, 0.0))):
        return "zero"  # a BSDF scaled by 0 still passes light to what lies beneath: kept
    return None
