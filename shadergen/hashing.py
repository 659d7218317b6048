"""The canonical graph hash: the cache key of a generated shader.

It covers everything the output depends on and nothing else: the prepared graph (nodes in
topological order with their definitions, implementations, bound values and connections; the
public uniforms with their listing paths), the target, the interface mode and the library's output key (library files,
their folder and the generator's code: fingerprint.py). XML formatting, element order and unused nodes never reach the prepared graph, so they
cannot change the key. Document-local definitions are hashed by content.
"""
import hashlib
import json

from .element import Element
from .graph import Graph


def _element_digest(e: Element) -> list:
    return [e.category, sorted(e.attrs.items()), [_element_digest(c) for c in e.children]]


def graph_hashes(graph: Graph, *, element: str, target: str, interface: str, library_hash: str,
                 local_ids: set[int]) -> tuple[str, str]:
    """(hash, topology hash). `element`: the name path the record reports. `library_hash`: the
    library's output key (fingerprint.py), which covers the generator's code too. `local_ids`: ids
    of the implementation elements the document itself declares. The topology hash leaves out the
    values of the public uniforms (what a value-free source leaves to the listing) and the element's
    name (a record of the same topology is rebound to both); the hash adds them. When the values are
    written into the source, the two are the same."""
    index = {id(n): i for i, n in enumerate(graph.nodes)}
    public = {id(p): i for i, p in enumerate(graph.interface)}

    def value(port):
        return None if port.public else port.value

    digests: dict[int, list] = {}  # id(element) -> its digest: thousands of uses share one local definition

    def local_key(e: Element) -> list:
        if id(e) not in digests:
            digests[id(e)] = _element_digest(e)
        return digests[id(e)]

    uniforms = [[p.owner.name, p.name, p.type, p.path, p.meta] for p in graph.interface]
    nodes = []
    for n in graph.nodes:
        inputs = []
        for inp in n.inputs.values():
            conn = [index[id(inp.connection.node)], inp.connection.name] if inp.connection is not None else None
            uniform = public.get(id(inp.socket if inp.socket is not None else inp))
            # no path: after the passes only a public uniform's path reaches the record (the listing),
            # and `uniforms` has it; the others' (a third of the bytes hashed) are where they came from
            inputs.append([inp.name, inp.type, value(inp), conn, uniform, inp.authored, inp.meta])
        impl = n.implementation
        impl_key = local_key(impl) if id(impl) in local_ids else impl.name
        nodedef_key = local_key(n.nodedef) if id(impl) in local_ids else n.nodedef.name
        scope = [[index[id(cond)], branch] for cond, branch in n.scope]
        nodes.append([n.name, n.category, nodedef_key, impl_key, scope, inputs, sorted(n.outputs)])
    outputs = [[name, index[id(o.node)], o.name] for name, o in graph.outputs.items()]
    structure = _canonical(
        {"target": target, "interface": interface, "library": library_hash, "values_in_source": graph.values_in_source,
         "environment": graph.environment, "lights": graph.lights,
         "root": index.get(id(graph.root)) if graph.root is not None else None,
         "nodes": nodes, "outputs": outputs, "uniforms": uniforms})
    # the element's name: two elements whose prepared graphs are alike (nodegraphs that differ only
    # in their names, with no public uniform to carry a path) still have records of their own
    values = _canonical([element, [p.value for p in graph.interface]])
    full = hashlib.sha256(structure + b"\0" + values).hexdigest()
    return full, full if graph.values_in_source else hashlib.sha256(structure).hexdigest()


def _canonical(data) -> bytes:
    """JSON with sorted keys at every level (metadata dicts too), so equal content hashes equally;
    tuples (vector values) are arrays, as lists are."""
    return json.dumps(data, sort_keys=True, separators=(",", ":"), default=str).encode()
