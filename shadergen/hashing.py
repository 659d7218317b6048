"""The canonical graph hash: the cache key of a generated shader.

It covers everything the output depends on and nothing else: the prepared graph (nodes in
topological order with their definitions, implementations, bound values and connections; the
public uniforms with their listing paths), the target, the interface mode and the library's output key (library files,
their folder and the generator's code: fingerprint.py). XML formatting, element order and unused nodes never reach the prepared graph, so they
cannot change the key. Document-local definitions are hashed by content.

With structural names (naming.py) the source holds no element name, so the topology hash leaves
the names out with the values: materials built alike from differently named nodes share it.
"""
import marshal

from .digest import graph_digest
from .element import Element
from .graph import Graph

# Nodes whose name the code holds even under structural names: a primvar read without a `geomprop`
# is the primvar of the node's name (nodes/geometric.py), which a renderer binds the mesh's stream by.
NAMED_BY_NODE = ("geompropvalue", "geompropvalueuniform")
LISTING_ONLY = ("colorspace", "unit", "ui")  # a uniform's metadata that only its listing entry carries


def _element_digest(e: Element) -> list:
    return [e.category, sorted(e.attrs.items()), [_element_digest(c) for c in e.children]]


def graph_hashes(graph: Graph, *, element: str, target: str, interface: str, library_hash: str,
                 local_ids: set[int], names: str = "structural", cms: str | None = None,
                 ui_in_source: bool = False) -> tuple[str, str]:
    """(hash, topology hash). `element`: the name path the record reports. `library_hash`: the
    library's output key (fingerprint.py), which covers the generator's code too. `local_ids`: ids
    of the implementation elements the document itself declares. The topology hash leaves out the
    values of the public uniforms (what a value-free source leaves to the listing) and the element's
    name (a record of the same topology is rebound to both); the hash adds them. When the values are
    written into the source, the two are the same. `names`: "structural" leaves the nodes', outputs'
    and uniforms' names and paths out of the topology hash too (the source does not hold them);
    "document" keeps them in it, as the source holds them. `cms`: the colour management system's
    identity (an OCIO config's name and content, cms/ocio.py); None for the built-in one, whose
    keys stay what they were before systems existed. `ui_in_source`: the target writes a uniform's
    ui metadata into the source (OSL's parameter hints): then it is no listing's alone."""
    document_names = names == "document"
    listing_only = LISTING_ONLY if not ui_in_source else tuple(k for k in LISTING_ONLY if k != "ui")
    index = {id(n): i for i, n in enumerate(graph.nodes)}
    public = {id(p): i for i, p in enumerate(graph.interface)}

    digests: dict[int, list] = {}  # id(element) -> its digest: thousands of uses share one local definition

    def local_key(e: Element) -> list:
        if id(e) not in digests:
            digests[id(e)] = _element_digest(e)
        return digests[id(e)]

    # what the document calls things, and what the listing alone says of a uniform (its colour space
    # and unit: their conversions are nodes of the graph by now; its ui hints), and which inputs the
    # document set (the passes have acted on it, the listing's paths still show it): in the source
    # only with document names
    named = [[[p.owner.name, p.path, [_ordered(p.meta.get(k)) for k in LISTING_ONLY]] for p in graph.interface],
             [n.name for n in graph.nodes], list(graph.outputs),
             [[inp.authored for inp in n.inputs.values()] for n in graph.nodes]]

    def meta(port) -> tuple | None:
        m = port.meta
        if not m or document_names or m.keys().isdisjoint(listing_only):  # most metadata has none of them
            return _ordered(m)
        return _ordered({k: v for k, v in m.items() if k not in listing_only})

    uniforms = [[p.name, p.type, meta(p)] for p in graph.interface]
    nodes = []
    get_public = public.get
    for n in graph.nodes:
        inputs = []
        for inp in n.inputs.values():
            # (the loop runs for every input of every node: the per-input helpers are written inline)
            connection, socket, m = inp.connection, inp.socket, inp.meta
            conn = [index[id(connection.node)], connection.name] if connection is not None else None
            uniform = get_public(id(socket if socket is not None else inp))
            if m:
                m = meta(inp)
            # no path: after the passes only a public uniform's path reaches the record (the listing),
            # and `uniforms` has it; the others' (a third of the bytes hashed) are where they came from
            inputs.append([inp.name, inp.type, None if inp.public else inp.value, conn, uniform,
                           inp.authored if document_names else None, m])
        impl = n.implementation
        impl_key = local_key(impl) if id(impl) in local_ids else impl.name
        nodedef_key = local_key(n.nodedef) if id(impl) in local_ids else n.nodedef.name
        scope = [[index[id(cond)], branch] for cond, branch in n.scope]
        name = n.name if document_names or n.category in NAMED_BY_NODE else None
        nodes.append([name, n.category, nodedef_key, impl_key, scope, inputs, sorted(n.outputs)])
    outputs = [[index[id(o.node)], o.name] for o in graph.outputs.values()]
    structure = _canonical(
        {"target": target, "interface": interface, "library": library_hash, "values_in_source": graph.values_in_source,
         "environment": graph.environment, "lights": graph.lights,
         "root": index.get(id(graph.root)) if graph.root is not None else None,
         "nodes": nodes, "outputs": outputs, "uniforms": uniforms, "names": named if document_names else names}
        | ({"cms": cms} if cms is not None else {})
        | ({"texture_width": graph.texture_width} if graph.texture_width is not None else {}))
    # the element's name: two elements whose prepared graphs are alike (nodegraphs that differ only
    # in their names, with no public uniform to carry a path) still have records of their own
    values = _canonical([element, [p.value for p in graph.interface], named])
    topology = graph_digest(structure)  # the structure hashed once for both: the hash goes on to the values
    full = topology.copy()
    full.update(b"\0" + values)
    full = full.hexdigest()
    return full, full if graph.values_in_source else topology.hexdigest()


def _canonical(data) -> bytes:
    """The bytes hashed: marshal's format version 2, which writes what the structure holds (lists,
    tuples, dicts in their order, strings, numbers, None, booleans) by value alone (version 3 and
    later write an object seen twice as a reference to it, and a string by whether it is interned).
    A third of the time of sorted JSON, which was a sixth of preparing a warm Examples element. A
    dict is written in its order: the structure's own are built in one, a port's metadata (in the
    document's attribute order) is `_ordered` first."""
    return marshal.dumps(data, 2)


def _ordered(value):
    """A metadata dict (and the dicts in it) as its items in key order; None for an empty one."""
    if value.__class__ is not dict:
        return value
    if not value:
        return None
    items = sorted(value.items())
    if dict in map(type, value.values()):  # (rarely: a port's ui hints in its metadata)
        items = [(k, _ordered(v)) for k, v in items]
    return tuple(items)
