"""Constant (and texture dot) nodes disappear: their consumers take over their value's binding."""
from ..graph import Node, Output
from .order import topological_order


def _elidable(node: Node) -> bool:
    """A dot is kept (its note is published) unless it passes a texture, which GLSL cannot hold
    in a local variable."""
    return node.category == "constant" or (node.category == "dot" and node.type == "filename")


def _source(node: Node):
    return node.inputs["value" if node.category == "constant" else "in"]


def elide_passthrough_nodes(outputs: dict[str, Output]) -> int:
    """Returns the number of connections that now bypass a node."""
    count = 0
    for node in topological_order(outputs):
        for inp in node.inputs.values():
            while inp.connection is not None and _elidable(inp.connection.node):
                src = _source(inp.connection.node)
                inp.connection = src.connection
                inp.value, inp.path = src.value, src.path
                if src.socket is not None:
                    inp.bind_socket(src.socket)
                count += 1
    for name, out in list(outputs.items()):
        if _elidable(out.node) and out.node.inputs:
            src = _source(out.node)
            if src.connection is not None:
                outputs[name] = src.connection
    return count
