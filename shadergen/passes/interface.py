"""Binding the interface (seed 2.4 step 4): which inputs are PublicUniforms of the shader.

| mode | public |
| --- | --- |
| complete | every editable input of the document's nodes |
| reduced | filenames, inputs bound to an interface, the inputs of the element drawn |
| specialized | filenames, inputs bound to an interface, and the inputs named in `keep` |

Everything else is a constant from here on, which is what lets folding see through it.
"""
from ..graph import Graph, Input, Node
from ..library import Library
from ..nodes import implementation_for
from ..types import TYPES

NOT_PUBLISHED = {"BSDF", "EDF", "VDF", "lightshader", "none"}


def choose_implementations(nodes: list[Node], library: Library) -> None:
    """The NodeImpl of every node not yet given one (a nodegraph's node is expanded instead)."""
    for node in nodes:
        if node.impl is None and node.implementation.category != "nodegraph":
            node.impl = implementation_for(node.implementation, library)


def document_path(inp: Input) -> str:
    """How a caller names a document input in `keep`: `node/input` (its element path)."""
    return f"{inp.node.path}/{inp.name}"


def is_public(inp: Input, node: Node, graph: Graph, mode: str, keep: frozenset[str]) -> bool:
    if inp.connection is not None or inp.socket is not None or inp.type in NOT_PUBLISHED or inp.derived:
        return False
    if TYPES[inp.type].is_closure and node is not graph.root and not inp.meta.get("interface"):
        return False  # an unconnected shader input inside the graph has nothing to edit
    editable = node.implementation.category == "nodegraph" or node.impl.is_editable(inp.name)
    if not editable and inp.type != "filename":
        return False
    if inp.type == "filename" or inp.meta.get("interface"):
        return True
    if mode == "specialized":
        return document_path(inp) in keep or inp.path in keep
    return mode == "complete" or node is graph.root


def bind_interface(graph: Graph, mode: str, keep: frozenset[str]) -> int:
    """Marks the public inputs of the document's own nodes (before nodegraphs are expanded: an
    expanded body reads its node's public inputs through sockets). Returns how many are public."""
    named = set()
    for node in graph.nodes:
        if node.category == "constant":
            continue  # only a constant drawn directly is left after eliding: it stays a literal, as in MaterialX
        for inp in node.inputs.values():
            named.update((document_path(inp), inp.path))
            if not is_public(inp, node, graph, mode, keep):
                continue
            if node is graph.root and not inp.authored:
                inp.path = f"{node.nodedef.name}/{inp.name}"
            inp.public = True
            graph.interface.append(inp)
    graph.warnings.extend(f"keep: no input '{path}' in this element's graph" for path in sorted(keep - named))
    return len(graph.interface)


def publish_textures(graph: Graph) -> int:
    """A texture fixed inside a nodegraph body still needs a sampler: it is public too."""
    count = 0
    for node in graph.nodes:
        for inp in node.inputs.values():
            if inp.type == "filename" and inp.is_constant():
                inp.public = True
                graph.interface.append(inp)
                count += 1
    return count
