"""Nodegraph implementations expanded into the graph (seed 2.3.3), so that every later pass sees
through them: a node implemented by a nodegraph is replaced by the nodes of its body.

Each use gets its own copy of the body (an `Instance`, its nodes named after the node it
replaces). The body's interface inputs take the node's bindings: a connection, a value (a
constant from here on), or a public uniform, which becomes a Socket the body's inputs share.
Whether identical bodies are written once as a function is decided after the other passes.

Nesting multiplies: a body that uses another definition twice, twelve levels deep, is 4,096
copies of the innermost body, from a document of a few kilobytes. So the nodes an expansion would
make are counted first, from each definition's body built once, and a graph over
MAX_EXPANDED_NODES, or nesting deeper than MAX_NESTING, is refused (too_large) before any copy
is made.
"""
from ..element import Element
from ..errors import ShaderGenError
from ..graph import Graph, GraphBuilder, Input, Instance, Node, Output, Socket
from .elide import elide_passthrough_nodes
from .order import topological_order

# Far above any real material: the largest graph of MaterialX's examples and test suite expands to
# 147 nodes, with uses nested 3 deep (bench/expansion.py prints both). At the limits a graph still
# generates in seconds and in a few hundred MB: function sharing compares bodies (nested uses
# included) depth by depth, so its work grows with the nodes times the nesting.
# A count past CAPPED_COUNT is reported as "at least" that.
MAX_EXPANDED_NODES = 50_000
MAX_NESTING = 32
CAPPED_COUNT = 10 ** 15


def expand_nodegraphs(graph: Graph, builder: GraphBuilder) -> int:
    """Returns how many nodegraph uses were expanded."""
    pending = [n for n in graph.nodes if is_nodegraph_use(n)]
    graph.expanded_size = check_expanded_size(graph, builder)
    replaced: dict[int, Output] = {}  # id(output of an expanded node) -> the body output that replaces it
    nodes = list(graph.nodes)
    expanded: set[int] = set()
    # id(public port) -> its place in graph.interface: a socket takes its outer input's place there
    positions = {id(p): i for i, p in enumerate(graph.interface)}
    while pending:
        node = pending.pop()
        expanded.add(id(node))
        instance = Instance(node.implementation, node, node.instance)
        body = expand(instance, builder, graph, positions)
        for name, out in node.outputs.items():
            if name in instance.outputs:
                replaced[id(out)] = instance.outputs[name]
        nodes.extend(body)
        pending.extend(n for n in body if is_nodegraph_use(n))
    if not expanded:
        return 0

    def follow(out: Output, where: str) -> Output:
        while id(out.node) in expanded:
            if id(out) not in replaced:
                raise ShaderGenError("invalid_implementation",
                                     f"nodegraph '{out.node.implementation.name}' has no output '{out.name}'", where)
            out = replaced[id(out)]
        return out

    for node in nodes:
        for inp in node.inputs.values():
            if inp.connection is not None:
                inp.connection = follow(inp.connection, node.path)
    for name, out in list(graph.outputs.items()):
        graph.outputs[name] = follow(out, name)
    graph.nodes = topological_order(graph.outputs)
    return len(expanded)


def is_nodegraph_use(node: Node) -> bool:
    return node.implementation.category == "nodegraph"


def check_expanded_size(graph: Graph, builder: GraphBuilder) -> int:
    """The nodes the graph will have once every use is expanded (an upper bound: outputs no one
    reads are dropped afterwards); raises too_large, naming the largest use, over the limit."""
    sizes: dict[int, int] = {}  # id(nodegraph) -> the nodes one use of it expands to
    total, largest, largest_size = 0, None, 0
    for node in graph.nodes:
        size = use_size(node, builder, sizes) if is_nodegraph_use(node) else 1
        total = min(total + size, CAPPED_COUNT)
        if size > largest_size:
            largest, largest_size = node, size
    if total > MAX_EXPANDED_NODES:
        def count(n: int) -> str:
            return f"at least {n:,}" if n >= CAPPED_COUNT else f"{n:,}"
        raise ShaderGenError("too_large", f"expanding its nodegraphs would give the graph {count(total)} nodes, over "
                             f"the limit of {MAX_EXPANDED_NODES:,}; the largest part, '{largest.name}' "
                             f"({largest.implementation.name}), makes {count(largest_size)}", largest.path)
    return total


def use_size(node: Node, builder: GraphBuilder, sizes: dict[int, int]) -> int:
    """The nodes one use of `node`'s nodegraph expands to, nested uses expanded too, from each
    definition's body built once: a depth-first walk over definitions, not over copies. A
    definition reached again below itself would expand forever (a cycle); nesting deeper than
    MAX_NESTING is refused (too_large)."""
    def frame(user: Node) -> list:  # [nodegraph, its nested uses still to count, its size so far]
        body = body_template(user.implementation, builder, user).nodes
        nested = [n for n in body if is_nodegraph_use(n)]
        return [user.implementation, iter(nested), len(body) - len(nested)]

    stack = [] if id(node.implementation) in sizes else [frame(node)]
    while stack:
        top = stack[-1]
        user = next(top[1], None)
        if user is None:
            stack.pop()
            sizes[id(top[0])] = size = min(top[2], CAPPED_COUNT)
            if stack:
                stack[-1][2] += size
            continue
        elem = user.implementation
        if id(elem) in sizes:
            top[2] += sizes[id(elem)]
            continue
        chain = [f[0] for f in stack]
        if any(e is elem for e in chain):
            cycle = chain[next(i for i, e in enumerate(chain) if e is elem):] + [elem]
            raise ShaderGenError("cycle", "nodegraph implementation instantiates itself: "
                                 + " -> ".join(e.name for e in cycle), elem.path)
        if len(stack) >= MAX_NESTING:
            raise ShaderGenError("too_large", f"nodegraphs nested more than {MAX_NESTING} deep: "
                                 + " -> ".join(e.name for e in chain + [elem]), node.path)
        stack.append(frame(user))
    return sizes[id(node.implementation)]


class Body:
    """A nodegraph's body built once, bound to no use: its nodes (in topological order) read
    the sockets of a template interface, its node names lack the prefix of a use. `plan`: what
    copy_body makes each node of, read from the nodes once (a body is copied at every use): per
    node its fields, its outputs' (name, type) and its inputs' fields, a connection as (the
    place of the node it reads, that node's output), a socket as its name; and per output of the
    body (its name, the place of its node, the node's output)."""

    def __init__(self, nodes: list[Node], outputs: dict[str, Output], warnings: list[str]):
        self.nodes = nodes
        self.outputs = outputs
        self.warnings = warnings
        place = {id(n): i for i, n in enumerate(nodes)}
        self.plan = ([(t.name, t.category, t.type, t.nodedef, t.implementation, t.path,
                       tuple((o.name, o.type) for o in t.outputs.values()),
                       tuple((i.name, i.type, i.value, i.path, i.meta, i.authored, i.default,
                              None if i.connection is None else (place[id(i.connection.node)], i.connection.name),
                              None if i.socket is None else i.socket.name) for i in t.inputs.values()))
                      for t in nodes],
                     tuple((name, place[id(o.node)], o.name) for name, o in outputs.items()))


def expand(instance: Instance, outer: GraphBuilder, graph: Graph, positions: dict[int, int]) -> list:
    """Builds one use's body and binds its interface to the node's inputs; returns its nodes."""
    node, elem = instance.node, instance.graph_elem
    instance.sockets = {inp.name: Socket(inp.name, inp.type, inp.value, inp.path, dict(inp.meta), origin=inp,
                                         default=inp.default)
                        for inp in node.inputs.values()}
    template = body_template(elem, outer, node)
    body = copy_body(template, instance)
    graph.warnings.extend(template.warnings)
    for socket in instance.sockets.values():
        bind_socket(socket, graph, positions)
    return body


def body_template(elem: Element, outer: GraphBuilder, node: Node) -> Body:
    """A body depends only on its definition and the target: built once per library (per document,
    when the document defines something that could change how it resolves), copied for each use."""
    return outer.scope.library_fact(("body", id(elem), outer.target, outer.cms.identity),
                                    lambda: build_body(elem, outer, node))


def build_body(elem: Element, outer: GraphBuilder, node: Node) -> Body:
    interface = {inp.name: Socket(inp.name, inp.type) for inp in node.inputs.values()}
    builder = GraphBuilder(outer.scope, outer.target, elem.parent if elem.parent is not None else elem, interface,
                           cms=outer.cms)
    outputs = {}
    for out_elem in elem.children_of("output"):
        src = builder.source_of(out_elem)
        if not isinstance(src, Output):
            raise ShaderGenError("invalid_implementation", f"nodegraph output '{out_elem.name}' is not connected",
                                 out_elem.path)
        outputs[out_elem.name] = src
    elide_passthrough_nodes(outputs)
    return Body(topological_order(outputs), outputs, builder.warnings)  # the body ends at its sockets


def copy_body(template: Body, instance: Instance) -> list[Node]:
    """The template's nodes for one use: named after the node it replaces, reading its sockets."""
    prefix = f"{instance.node.name}_"
    sockets = instance.sockets
    copies: list[Node] = []
    nodes, outputs = template.plan
    for name, category, type_name, nodedef, implementation, path, node_outputs, node_inputs in nodes:
        n = Node(prefix + name, category, type_name, nodedef, implementation, path, instance)
        n.outputs = {out: Output(out, out_type, n) for out, out_type in node_outputs}
        inputs = n.inputs
        for name, type_name, value, path, meta, authored, default, connection, socket in node_inputs:
            inp = inputs[name] = Input(name, type_name, n, value, path, dict(meta), authored, default)
            if connection is not None:
                inp.connection = copies[connection[0]].outputs[connection[1]]
            if socket is not None:
                inp.bind_socket(sockets[socket])
        copies.append(n)
    instance.outputs = {name: copies[place].outputs[out] for name, place, out in outputs}
    return copies


def bind_socket(socket: Socket, graph: Graph, positions: dict[int, int]) -> None:
    outer: Input = socket.origin
    for inp in list(socket.consumers):
        inp.parameter = socket.name
    if outer.public:  # the node's public input: one uniform the body's inputs share
        socket.public, socket.path = True, outer.path
        positions[id(socket)] = place = positions.pop(id(outer))
        graph.interface[place] = socket
        outer.public = False
        return
    if outer.type == "filename" and outer.is_constant():  # a texture fixed by the node still needs a sampler
        socket.public, socket.path = True, outer.path
        positions[id(socket)] = len(graph.interface)
        graph.interface.append(socket)
        return
    for inp in list(socket.consumers):
        inp.unbind_socket()
        if outer.connection is not None:
            inp.connection = outer.connection
        elif outer.socket is not None:
            inp.bind_socket(outer.socket)
        else:
            inp.value, inp.path = outer.value, outer.path
            if inp.type == "string" and "enum" in outer.meta:  # the literal is the index in the node's enum
                for key in ("enum", "enumvalues"):
                    inp.meta.pop(key, None)
                    if key in outer.meta:
                        inp.meta[key] = outer.meta[key]
