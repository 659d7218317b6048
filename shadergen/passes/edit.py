"""Edits the folding passes share: who reads an output, and rebinding those readers."""
from ..graph import Graph, Input, Node, Output


def readers(graph: Graph) -> dict[int, list[Input]]:
    """id(Output) -> the inputs connected to it."""
    found: dict[int, list[Input]] = {}
    for node in graph.nodes:
        for inp in node.inputs.values():
            if inp.connection is not None:
                found.setdefault(id(inp.connection), []).append(inp)
    return found


def set_constant(inp: Input, value) -> None:
    inp.connection, inp.value, inp.parameter = None, value, None
    inp.unbind_socket()


def can_pass(source: Input, node: Node) -> bool:
    """An input can stand for the node's output: same type, and not a public input of its own
    (a uniform belongs to one input)."""
    return len(node.outputs) == 1 and not source.public and source.type == next(iter(node.outputs.values())).type


def pass_through(graph: Graph, node: Node, source: Input, reading: dict[int, list[Input]]) -> None:
    """Whatever read the node's output reads what `source` reads instead."""
    out: Output = next(iter(node.outputs.values()))
    for inp in reading.pop(id(out), []):
        inp.unbind_socket()
        inp.connection, inp.value = source.connection, source.value
        inp.parameter = source.parameter if inp.node.instance is source.node.instance else None
        if source.socket is not None:
            inp.bind_socket(source.socket)
        if source.connection is not None:
            reading.setdefault(id(source.connection), []).append(inp)
    if source.connection is not None:
        for name, o in graph.outputs.items():
            if o is out:
                graph.outputs[name] = source.connection
