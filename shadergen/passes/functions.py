"""Function form, decided after the other passes: identical expansions of one nodegraph become one
function and a call per use, where that is smaller than writing the body at each use.

Two uses are identical when their bodies, as the passes left them, have the same nodes, the same
connections and the same constants; only what arrives through the body's interface may differ.
Bodies with closures stay expanded: closures are evaluated per shading context by the surface.
Nested uses are decided first, so an outer body may call an inner function.
"""
from collections import Counter

from ..graph import Function, Graph, Input, Instance, Node, Output, Socket
from ..nodes.base import GraphFunctionImpl
from ..types import TYPES
from .order import assign_scopes, topological_order

SHADER_TYPES = {"surfaceshader", "volumeshader", "displacementshader", "lightshader", "material"}


def share_functions(graph: Graph, uniform_flow) -> int:
    """Returns how many uses became calls."""
    calls = 0
    uses = _uses(graph)
    for depth in sorted({d for _, d in uses.values()}, reverse=True):  # innermost first
        bodies = _bodies(graph, depth, uses)
        changed = False
        groups: dict[tuple, list[Instance]] = {}
        # a signature names its nodegraph: a use of one nodegraph used once at this depth is a group
        # of one, which stays expanded, so its signature (a walk over its body) is not worked out
        definitions = Counter(id(inst.graph_elem) for inst, _ in bodies.values())
        for inst, body in bodies.values():
            if definitions[id(inst.graph_elem)] == 1:
                continue
            signature = _signature(inst, body)
            if signature is not None:
                groups.setdefault(signature, []).append(inst)
        readers = None
        for group in groups.values():
            size = len(bodies[id(group[0])][1])
            if (len(group) - 1) * size <= len(group):
                continue  # writing the body at each use is no larger than a function and its calls
            if readers is None:  # calls to come read the body too
                readers = Readers(graph, graph.nodes + [inst.node for inst, _ in uses.values()])
            function = _make_function(group[0], bodies[id(group[0])][1], uniform_flow)
            impl = GraphFunctionImpl(function, any(uniform_flow(n) for n in function.graph.nodes))
            for inst in group:
                _call(graph, readers, inst, impl)
            calls += len(group)
            changed = True
        if changed:
            graph.nodes = topological_order(graph.outputs)
    return calls


def _uses(graph: Graph) -> dict[int, tuple[Instance, int]]:
    """id(use) -> (use, its depth of nesting; 0: a use in the document's own graph), for every
    expanded use of the graph, nested ones included."""
    uses: dict[int, tuple[Instance, int]] = {}
    for node in graph.nodes:
        chain, inst = [], node.instance
        while inst is not None and id(inst) not in uses:  # each use's chain is walked once
            chain.append(inst)
            inst = inst.parent
        depth = -1 if inst is None else uses[id(inst)][1]
        for inst in reversed(chain):
            depth += 1
            uses[id(inst)] = (inst, depth)
    return uses


def _inside(node: Node, inst: Instance) -> bool:
    outer = node.instance
    while outer is not None and outer is not inst:
        outer = outer.parent
    return outer is inst


def _bodies(graph: Graph, depth: int, uses: dict) -> dict[int, tuple[Instance, list[Node]]]:
    """The uses at `depth` with the nodes of their bodies (nested uses' included), in graph order."""
    enclosing: dict[int, Instance | None] = {}  # id(use) -> the use at `depth` it sits in, None: none
    bodies: dict[int, tuple[Instance, list[Node]]] = {}
    for node in graph.nodes:
        chain, inst = [], node.instance
        while inst is not None and id(inst) not in enclosing and uses[id(inst)][1] > depth:
            chain.append(inst)
            inst = inst.parent
        if inst is None or id(inst) in enclosing:
            use = None if inst is None else enclosing[id(inst)]
        else:
            use = inst if uses[id(inst)][1] == depth else None
            enclosing[id(inst)] = use
        for inst in chain:
            enclosing[id(inst)] = use
        if use is not None:
            bodies.setdefault(id(use), (use, []))[1].append(node)
    return bodies


def interface_parameter(inp: Input, inst: Instance) -> str | None:
    """The interface input of `inst` an input of its body reads, through nested uses; None when it
    reads something else."""
    while inp.node.instance is not inst:
        owner = inp.node.instance
        if owner is None or inp.parameter is None:
            return None
        inp = owner.node.inputs[inp.parameter]
    return inp.parameter


def _signature(inst: Instance, body: list[Node]) -> tuple | None:
    """What makes two uses share a function; None where a use cannot be a function."""
    index = {id(n): i for i, n in enumerate(body)}
    outputs = [inst.outputs.get(o.name) for o in inst.node.outputs.values()]
    if any(o is None or id(o.node) not in index for o in outputs):
        return None
    parts: list = [id(inst.graph_elem), tuple((index[id(o.node)], o.name) for o in outputs)]
    for n in body:
        if any(o.type in SHADER_TYPES or (o.type in TYPES and TYPES[o.type].is_closure) for o in n.outputs.values()):
            return None
        inputs = []
        for inp in n.inputs.values():
            param = interface_parameter(inp, inst)
            if param is not None:
                inputs.append((inp.name, "param", param))
            elif inp.connection is not None:
                if id(inp.connection.node) not in index:
                    return None  # reads a node outside the body other than through the interface
                inputs.append((inp.name, index[id(inp.connection.node)], inp.connection.name))
            elif inp.public or inp.socket is not None:
                inputs.append((inp.name, "uniform", id(inp.socket or inp)))
            else:
                inputs.append((inp.name, repr(inp.value), repr(sorted(inp.meta.items()))))
        called = n.impl.function if isinstance(n.impl, GraphFunctionImpl) else None
        parts.append((n.category, n.nodedef.name, n.implementation.name, id(called), tuple(inputs)))
    return tuple(parts)


def _make_function(inst: Instance, body: list[Node], uniform_flow) -> Function:
    """The first use's body becomes the function: its interface inputs read parameters."""
    params = {name: Socket(name, s.type, meta=dict(s.meta)) for name, s in inst.sockets.items()}
    for n in body:
        for inp in n.inputs.values():
            param = interface_parameter(inp, inst)
            if param is not None:
                inp.connection, inp.value = None, None
                inp.unbind_socket()
                inp.bind_socket(params[param])
    outputs = {o.name: inst.outputs[o.name] for o in inst.node.outputs.values()}
    graph = Graph(topological_order(outputs), outputs)
    assign_scopes(graph.nodes, uniform_flow)
    return Function(inst.graph_elem.name, graph, list(params.values()), list(outputs.values()))


class Readers:
    """What reads each output: the inputs of `nodes` and the graph's outputs, indexed once per
    depth, so that each call rewires only its own readers (a scan of the graph per call made
    many uses quadratic). Calls of one depth never read each other's bodies, so the index holds
    while they are made."""

    def __init__(self, graph: Graph, nodes: list[Node]):
        self.inputs: dict[int, list[Input]] = {}
        for node in nodes:
            for inp in node.inputs.values():
                if inp.connection is not None:
                    self.inputs.setdefault(id(inp.connection), []).append(inp)
        self.graph_outputs: dict[int, list[str]] = {}
        for name, out in graph.outputs.items():
            self.graph_outputs.setdefault(id(out), []).append(name)


def _call(graph: Graph, readers: Readers, inst: Instance, impl: GraphFunctionImpl) -> None:
    """The node the body replaced comes back as a call: what read the body's outputs reads it."""
    node = inst.node
    for name, socket in inst.sockets.items():
        if socket.public:  # the node's public input is the shared uniform
            node.inputs[name].bind_socket(socket)
    replaced: dict[int, Output] = {id(inst.outputs[o.name]): o for o in node.outputs.values()}
    for body_output, call_output in replaced.items():
        for inp in readers.inputs.get(body_output, ()):
            if id(inp.connection) == body_output and not _inside(inp.node, inst):
                inp.connection = call_output
        for name in readers.graph_outputs.get(body_output, ()):
            graph.outputs[name] = call_output
    node.impl = impl
