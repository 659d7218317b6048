"""What the lobes of a surface need at a shading point, written once before its contexts: their
weight there, and the state of the lobes whose source prepares them.

Weights. Which closures reach the surface is decided from the mix weights above them.

A closure under a `mix` reaches the surface only while the mix gives it a share: `fg` where the mix
weight is not 0, `bg` where it is not 1. Every other closure operator passes what reaches it on to
all its closure inputs: `layer` sees the base through the top, `add` sums both, and `multiply`
needs its input even at weight 0, because what that input lets through to a base below (its
throughput) is not scaled. The conditions are carried down the closure graph (a closure read
twice reaches the surface when either reader gives it a share) and written once per shading
point; a lobe (a closure with a `weight` input) that does not reach the surface is given weight 0
there, so that its own early exit skips its work in every context: one uniform branch per lobe,
inside the lobe, not one per call site.

Preparation. A lobe whose source defines `<function>_prepare` (its inputs, then an `out` state) does
its light-independent work there (normal, Fresnel set-up, directional albedo, the environment it
reflects), once per shading point; its call in each context then takes the shading context and that
state instead of its inputs (SourceFunctionImpl reads this from the function's IR).
"""
from ..code import build, ir
from ..graph import Input, Node
from ..passes.closures import closure_inputs, is_closure_node
from ..passes.fold import constant
from .base import SourceFunctionImpl

SHARE_GONE = {"mix": {"fg": 0.0, "bg": 1.0}}  # operator -> input -> the weight at which it gets nothing
WEIGHT_INPUT = {"mix": "mix"}


def closure_nodes(inp: Input) -> list[Node]:
    """The closure nodes `inp` reads, readers before what they read."""
    order: list[Node] = []
    seen: set[int] = set()
    stack = [(inp.connection.node, False)] if inp.connection is not None else []
    while stack:
        node, done = stack.pop()
        if done:
            order.append(node)
            continue
        if id(node) in seen or not is_closure_node(node):
            continue
        seen.add(id(node))
        stack.append((node, True))
        # reversed, so that the first input is visited first: callers write them in that order
        stack.extend((i.connection.node, False) for i in reversed(closure_inputs(node)) if i.connection is not None)
    return order[::-1]


def emit_lobes(ctx, inp: Input, point_arguments) -> None:
    """The weights, then the prepared states, of the lobes `inp` reads. `point_arguments()`
    declares the shading point's closure data on first use and returns what a prepare call takes
    before the lobe's inputs."""
    nodes = ctx.closure_nodes(inp)
    emit_weights(ctx, nodes)
    ctx.prepared_lobes = {}
    for node in reversed(nodes):  # in the order the contexts call them
        impl = node.impl
        state = impl.prepared_state if isinstance(impl, SourceFunctionImpl) else None
        if state is not None:
            args = point_arguments() + [ctx.value(i) for i in node.inputs.values()]
            lobe = ctx.prepared_lobes[id(node)] = ctx.local(state, ctx.namer(f"{ctx.names.node(node)}_lobe"))
            ctx.call_statement(f"{impl.function}_prepare", args + [lobe])


def emit_weights(ctx, nodes: list[Node]) -> None:
    """Declares each lobe's weight at this point where a mix above it may take it away, and makes
    the lobe's calls read it (ctx.lobe_weights)."""
    if not nodes:
        return
    reached: dict[int, list[ir.Expr | None]] = {id(nodes[0]): [None]}  # None: always reached
    declarations: list[ir.Stmt] = []
    for node in nodes:
        condition = _any(reached.get(id(node), [build.boolean(False)]))
        inputs = closure_inputs(node)
        if inputs:
            if condition is not None and not isinstance(condition, ir.Name):
                condition = _declare(ctx, declarations, "bool", f"{ctx.names.node(node)}_reached", condition)
            for i in inputs:
                if i.connection is not None:
                    share = _share_condition(ctx, node, i)
                    reached.setdefault(id(i.connection.node), []).append(_all(condition, share))
        elif condition is not None and "weight" in node.inputs and node.inputs["weight"].type == "float":
            weight = node.inputs["weight"]
            ctx.lobe_weights[id(weight)] = _declare(ctx, declarations, "float", f"{ctx.names.node(node)}_active_weight",
                                                    build.select(condition, ctx.value(weight), build.number(0.0)))
    if declarations:
        ctx.body.comment("lobes under a mix: weight 0 where the mix leaves them out")
        for statement in declarations:
            ctx.body.add(statement)


def _share_condition(ctx, node: Node, inp: Input) -> ir.Expr | None:
    """When `node` passes anything to its closure input `inp` (None: always)."""
    gone = SHARE_GONE.get(node.category, {}).get(inp.name)
    if gone is None:
        return None
    weight = node.inputs[WEIGHT_INPUT[node.category]]
    known, value = constant(node, weight.name)
    if known:
        return None if value != gone else build.boolean(False)
    return build.binary("!=", ctx.value(weight), build.number(gone))


def _declare(ctx, declarations: list[ir.Stmt], type_name: str, wanted: str, expression: ir.Expr) -> ir.Name:
    name = ctx.namer(wanted)
    declarations.append(ir.Declare(type_name, name, expression, False))
    return build.name(name, "local", type_name)


def _all(a: ir.Expr | None, b: ir.Expr | None) -> ir.Expr | None:
    if a is None or b is None:
        return b if a is None else a
    return build.binary("&&", a, b)


def _any(conditions: list[ir.Expr | None]) -> ir.Expr | None:
    if None in conditions:
        return None
    if len(conditions) == 1:  # (most closures are read once)
        return conditions[0]
    unique = list({repr(c): c for c in conditions}.values())  # the same condition reached twice, once
    return unique[0] if len(unique) == 1 else build.any_of(unique)
