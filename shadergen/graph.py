"""ShaderGraph: the one IR every target sees (seed 2.4, initialisation steps).

`GraphBuilder` turns a renderable element (or a nodegraph implementation's body) into nodes:
it resolves nodedefs and implementations while walking upstream from the outputs (so unused
paths never enter the graph), connects default geometric nodes and inserts colour-space and
unit transforms. Everything after building is a named pass in `passes/`.
"""
import re
from collections import namedtuple

from . import types as T
from .element import Element
from .cms import BUILTIN
from .errors import ShaderGenError
from .library import Scope

# Conditional nodes and their branch inputs (seed 2.4 step 5): a node feeding only one branch
# of a varying conditional is computed inside that branch.
BRANCH_INPUTS = {
    "ifgreater": ("in1", "in2"), "ifgreatereq": ("in1", "in2"), "ifequal": ("in1", "in2"),
    "switch": tuple(f"in{i}" for i in range(1, 11)),
}
TARGET_UNITS = {"distance": "meter"}


# The IR's classes are plain classes, not dataclasses: a cold `generate` process would spend a
# tenth of its time importing the dataclasses module (and inspect) and generating their methods.
NodeRef = namedtuple("NodeRef", "elem output")  # a connection's upstream node, before the node is built


class Socket:
    """An interface input of a nodegraph body: while the body is expanded, the input of the node
    it implements (`origin`); afterwards, a published uniform read by several inputs of the body."""
    __slots__ = ("name", "type", "value", "path", "meta", "consumers", "origin", "public", "default")

    def __init__(self, name: str, type: str, value: object = None, path: str | None = None, meta: dict | None = None,
                 origin: "Input | None" = None, public: bool = False, default: object = None):
        self.name = name
        self.type = type
        self.value = value
        self.path = path
        self.meta = {} if meta is None else meta  # enum, enumvalues, uniform, colorspace, unit, ui...
        self.consumers: list[Input] = []
        self.origin = origin
        self.public = public  # a PublicUniform of the shader
        self.default = default  # the nodedef's value: a value-free shader's initializer

    @property
    def owner(self) -> "Node":
        return self.origin.node


class Output:
    """A node's output: what inputs connect to."""
    __slots__ = ("name", "type", "node")

    def __init__(self, name: str, type: str, node: "Node"):
        self.name = name
        self.type = type
        self.node = node


class Input:
    """A node's input: a value, a connection, a socket of an expanded body, or a public uniform."""
    __slots__ = ("name", "type", "node", "value", "path", "connection", "socket", "meta", "authored", "public",
                 "parameter", "default", "derived")

    def __init__(self, name: str, type: str, node: "Node", value: object = None, path: str | None = None,
                 meta: dict | None = None, authored: bool = False, default: object = None):
        self.name = name
        self.type = type
        self.node = node
        self.value = value
        self.path = path  # element path of the document input it binds to (listings)
        self.connection: Output | None = None
        self.socket: Socket | None = None
        self.meta = {} if meta is None else meta
        self.authored = authored  # set in the document (not a nodedef default)
        self.public = False  # a PublicUniform of the shader (decided by the interface pass)
        self.parameter: str | None = None  # the body interface input it was bound to, inside an expanded nodegraph
        self.default = default  # the nodedef's value: a value-free shader's initializer
        # a value the generator derives from the document's structure (a unit conversion's factor):
        # no input of the document, so never a uniform; its value is in the topology hash
        self.derived = False

    @property
    def owner(self) -> "Node":
        return self.node

    def bind_socket(self, socket: Socket) -> None:
        self.socket = socket
        socket.consumers.append(self)

    def unbind_socket(self) -> None:
        if self.socket is not None:
            self.socket.consumers.remove(self)
            self.socket = None

    def is_constant(self) -> bool:
        """Neither connected nor live: its value is fixed when the shader is generated."""
        return self.connection is None and self.socket is None and not self.public


class Node:
    """A node of the graph: its definition, implementation and ports."""
    __slots__ = ("name", "category", "type", "nodedef", "implementation", "path", "inputs", "outputs", "scope", "impl",
                 "instance", "facts")

    def __init__(self, name: str, category: str, type: str, nodedef: Element, implementation: Element | None,
                 path: str, instance: "Instance | None" = None):
        self.name = name
        self.category = category
        self.type = type
        self.nodedef = nodedef
        self.implementation = implementation
        self.path = path
        self.inputs: dict[str, Input] = {}
        self.outputs: dict[str, Output] = {}
        self.scope: tuple = ()  # ((conditional node, branch input name), ...) outermost first; () is global
        self.impl = None  # the NodeImpl writing its code, chosen when the graph is prepared
        self.instance = instance  # the expanded nodegraph it comes from; None: the document's own
        self.facts: dict = {}  # what the passes learned for emission (e.g. "transmission")

    def input_value(self, name: str, default=None):
        """An input's value as the node's code is generated with it: its own, or inside an expanded
        nodegraph the value of the interface input it reads (which `complete` publishes, but a
        setting such as a primvar's name is written into the code all the same)."""
        inp = self.inputs.get(name)
        value = None if inp is None else inp.value if inp.socket is None else inp.socket.value
        return default if value is None else value

    def upstream(self) -> list["Node"]:
        return [inp.connection.node for inp in self.inputs.values() if inp.connection is not None]


class Instance:
    """One use of a nodegraph implementation, expanded into the graph: the node it replaced and
    the expansion it sits in (nested nodegraphs)."""

    def __init__(self, graph_elem: Element, node: Node, parent: "Instance | None"):
        self.graph_elem = graph_elem
        self.node = node
        self.parent = parent
        self.sockets: dict[str, Socket] = {}
        self.outputs: dict[str, Output] = {}


class Function:
    """A nodegraph body written once and called by several nodes: its own small graph whose
    inputs read `params` (in the order of the calling node's inputs)."""

    def __init__(self, name: str, graph: "Graph", params: list[Socket], outputs: list[Output]):
        self.name = name
        self.graph = graph
        self.params = params
        self.outputs = outputs  # in the order of the calling node's outputs


class Graph:
    """Nodes in topological order, the outputs a shader writes, and what the passes decided."""

    def __init__(self, nodes: list[Node], outputs: dict[str, Output], root: Node | None = None,
                 warnings: list[str] | None = None, interface_mode: str = "complete", values_in_source: bool = False,
                 environment: str | None = None, lights: bool = True, texture_width: float | None = None):
        self.nodes = nodes
        self.outputs = outputs
        self.root = root  # the node a shader was generated from, when it is a node
        self.warnings = [] if warnings is None else warnings
        self.interface: list = []  # the public uniforms (Input | Socket), in listing order
        self.passes: dict[str, int] = {}  # edits each pass made, in pass order
        self.expanded_size = 0  # nodes once nodegraphs are expanded, as counted before (passes/expand.py)
        self.interface_mode = interface_mode
        self.values_in_source = values_in_source  # uniform initializers hold the document's values, not the nodedef's
        self.environment = environment  # the environment lighting it is generated for (features.ENVIRONMENTS), or either
        self.lights = lights  # lit by a light rig too; False: by the environment alone (no light loop)
        self.texture_width = texture_width  # OSL's texture() filter width, None: OIIO's default (api.prepare_all)


# nodedef input attributes a port's metadata keeps as they are
META_ATTRIBUTES = ("enum", "enumvalues", "uniform", "defaultgeomprop", "unittype")
# ui attribute -> its key in a listing's `ui`, in the order listings write them
UI_ATTRIBUTES = {"uiname": "name", "uifolder": "folder", "uimin": "min", "uimax": "max", "uisoftmin": "softmin",
                 "uisoftmax": "softmax", "uistep": "step", "uiadvanced": "advanced", "doc": "doc", "enum": "enum",
                 "enumvalues": "enumvalues"}


def input_meta(decl: Element) -> dict:
    """What listings and the syntax need from a nodedef input: enums, uniform flag, ui metadata."""
    attrs = decl.attrs
    meta = {key: attrs[key] for key in META_ATTRIBUTES if attrs.get(key) is not None}
    ui = ui_hints(decl)
    if ui:
        meta["ui"] = ui
    return meta


def ui_hints(decl: Element) -> dict:
    """An input's ui metadata, typed (types.parse_ui_hint); most document inputs have none."""
    attrs = decl.attrs
    if UI_ATTRIBUTES.keys().isdisjoint(attrs):
        return {}
    where, type_name = decl.path, attrs.get("type")
    return {hint: T.parse_ui_hint(hint, type_name, attrs[key], where)
            for key, hint in UI_ATTRIBUTES.items() if attrs.get(key) is not None}


class GraphBuilder:
    """Walks a document upstream from one renderable element and builds its ShaderGraph."""

    def __init__(self, scope: Scope, target: str, doc_root: Element, interface: dict[str, Socket] | None = None,
                 instance: Instance | None = None, cms=BUILTIN):
        self.scope = scope
        self.cms = cms  # the colour management system (cms/): what colour-space transforms are
        self.instance = instance  # the nodegraph use being expanded; its nodes are named after the node it replaces
        self.prefix = f"{instance.node.name}_" if instance is not None else ""
        self.interface = interface  # nodedef inputs, when building a nodegraph implementation
        self.target = target
        self.doc_root = doc_root
        self.nodes: dict[int, Node] = {}  # id(element) -> node
        self.names: set[str] = set()
        self.geom_nodes: dict[str, Node] = {}
        self.synthetic: list[Element] = []  # elements made here (default geometric nodes)
        self.redirect: dict[int, Output] = {}  # id(output) -> the transform node output that replaces it
        self.warnings: list[str] = []

    # -- naming ---------------------------------------------------------------------------
    def unique(self, name: str) -> str:
        base, n = name, 1
        while name in self.names:
            name = f"{base}{n}"
            n += 1
        self.names.add(name)
        return name

    # -- nodedef resolution ----------------------------------------------------------------
    def resolve_nodedef(self, elem: Element) -> Element:
        authored = tuple((i.name, i.get("type")) for i in elem.children_of("input", "parameter"))
        key = ("nodedef", elem.category, elem.get("nodedef"), elem.get("type"), elem.get("version"), authored)
        return self.scope.library_fact(key, lambda: self._resolve_nodedef(elem))

    def _resolve_nodedef(self, elem: Element) -> Element:
        name = elem.get("nodedef")
        if name:
            nd = self.scope.nodedef(name)
            if nd is None:
                raise ShaderGenError("unknown_nodedef", f"nodedef '{name}' not found", elem.path)
            return nd
        candidates = self.scope.nodedefs_for(elem.category)
        if not candidates:
            raise ShaderGenError("unknown_node", f"no node definition for <{elem.category}>", elem.path)
        out_type = elem.get("type")
        authored = {i.name: i.get("type") for i in elem.children_of("input", "parameter")}
        version = elem.get("version")
        matches = []
        for nd in candidates:
            outputs = self.scope.nodedef_output_types(nd)
            if out_type and out_type != "multioutput":
                # the first output's type, else the nodedef's (older documents type the nodedef)
                if (outputs[0] if outputs and outputs[0] is not None else nd.get("type")) != out_type:
                    continue
            elif out_type == "multioutput" and len(outputs) < 2:
                continue
            decls = {i.name: i.get("type") for i in self.scope.nodedef_inputs(nd)}
            if any(n in decls and t and decls[n] != t for n, t in authored.items()):
                continue
            matches.append(nd)
        if not matches:
            raise ShaderGenError(
                "type_mismatch",
                f"no <{elem.category}> definition matches output type '{out_type}' and inputs "
                + ", ".join(f"{n}:{t}" for n, t in authored.items()), elem.path)
        if version:
            versioned = [nd for nd in matches if nd.get("version") == version]
            if not versioned:
                raise ShaderGenError("unknown_nodedef", f"<{elem.category}> has no version '{version}'", elem.path)
            return versioned[0]
        # As MaterialX does: a definition declaring every authored input wins over one that merely
        # tolerates them (the seed's roughness_dual with roughnessX/Y over 1.39's vector2 one).
        exact = [nd for nd in matches if all(n in {i.name for i in self.scope.nodedef_inputs(nd)} for n in authored)]
        matches = exact or matches
        defaults = [nd for nd in matches if nd.get("isdefaultversion") == "true"]
        return (defaults or matches)[0]

    # -- building ----------------------------------------------------------------------------
    def node_for(self, elem: Element) -> Node:
        """The node of an element, building every node upstream of it first. Iterative, so graphs
        of any depth build; a connection back onto the current path is a cycle, named in full."""
        if id(elem) in self.nodes:
            return self.nodes[id(elem)]
        stack = [(elem, iter(self.upstream_elements(elem)))]
        on_path = {id(elem)}
        while stack:
            current, deps = stack[-1]
            dep = next(deps, None)
            if dep is None:
                stack.pop()
                on_path.discard(id(current))
                self.nodes[id(current)] = self._make_node(current)
            elif id(dep) in on_path:
                path = [e for e, _ in stack]
                cycle = path[path.index(dep):] + [dep]
                raise ShaderGenError("cycle", "cycle in the graph: " + " -> ".join(e.path for e in cycle), dep.path)
            elif id(dep) not in self.nodes:
                on_path.add(id(dep))
                stack.append((dep, iter(self.upstream_elements(dep))))
        return self.nodes[id(elem)]

    def upstream_elements(self, elem: Element):
        """The node elements an element's inputs connect to (through graph outputs and interfaces)."""
        for authored in elem.children_of("input", "parameter"):
            source = self.follow(authored)
            if isinstance(source, NodeRef):
                yield source.elem

    def _make_node(self, elem: Element) -> Node:
        nodedef = self.resolve_nodedef(elem)
        impl = self.scope.implementation(nodedef, self.target)
        if impl is None:
            raise ShaderGenError("unknown_node",
                                 f"no {self.target} implementation of '{nodedef.name}' for <{elem.category}>", elem.path)
        node = self.new_node(self.prefix + elem.name, elem.category, elem.get("type") or "", nodedef, impl, elem.path)
        for authored in elem.children_of("input", "parameter"):
            inp = node.inputs.get(authored.name)
            if inp is None:
                self.warnings.append(f"{authored.path}: input '{authored.name}' is not on {nodedef.name}; ignored")
                continue
            self.bind(inp, authored)
        for inp in list(node.inputs.values()):
            geomprop = inp.meta.get("defaultgeomprop")
            if geomprop and inp.connection is None and inp.socket is None and not inp.meta.get("interface"):
                # as MaterialX does: an unconnected geometric input reads the geometry, value or not;
                # one bound to an interface input with a value (a nodegraph drawn as its nodedef) reads that
                inp.connection = self.geomprop_output(geomprop, elem)
            elif inp.authored and inp.type != "filename":
                self.convert_units(inp)
                self.convert_colorspace(inp)
        self.convert_file_colorspace(node)
        return node

    def new_node(self, name: str, category: str, type_name: str, nodedef: Element, impl: Element,
                 path: str | None) -> Node:
        """A node with the ports of its nodedef (and the extra inputs its implementation declares).
        An input's listing path is the element path of the node's input, when the node has one; an
        input its implementation adds (image's uv_scale) is listed at the same place, `node/input`,
        where an application finds it, though a document cannot author it."""
        node = Node(self.unique(name), category, type_name, nodedef, impl, path or "", instance=self.instance)
        for out in self.scope.nodedef_outputs(nodedef):
            node.outputs[out.name] = Output(out.name, out.get("type"), node)
        if not node.outputs:
            node.outputs["out"] = Output("out", nodedef.get("type"), node)
        for name, t, value, meta in self.ports(nodedef, impl):
            inp = Input(name, t, node, value, None, meta=dict(meta), default=value)
            if path is not None:
                inp.path = f"{path}/{name}"
            node.inputs[name] = inp
        return node

    def ports(self, nodedef: Element, impl: Element) -> list[tuple]:
        """(name, type, value, meta) of each input a node of this definition has: its nodedef's
        (inherited ones included) and those its implementation adds."""
        return self.scope.library_fact(("ports", id(nodedef), id(impl)), lambda: [
            (decl.name, decl.get("type"), T.parse_value(decl.get("type"), decl.get("value"), decl.path),
             input_meta(decl))
            for decl in self.scope.nodedef_inputs(nodedef) + impl.children_of("input") if decl.category != "token"])

    # -- colour-space and unit transforms (seed 3.3, 3.4) --------------------------------------
    def transform_node(self, name: str, nodedef_name: str, where: str) -> Node | None:
        nodedef = self.scope.nodedef(nodedef_name)
        impl = self.scope.implementation(nodedef, self.target) if nodedef is not None else None
        if impl is None:
            self.warnings.append(f"{where}: no {self.target} transform '{nodedef_name}'; value used as is")
            return None
        node = self.new_node(name, nodedef.get("node"), "", nodedef, impl, None)
        node.path = where  # errors name the input the transform serves; its own inputs have no document path
        return node

    def insert_before(self, inp: Input, node: Node) -> Input:
        """Route an input's binding through `node`: its first input takes the binding, and the
        original input reads the node's output. Returns the node's first input."""
        first = next(iter(node.inputs.values()))
        first.value, first.path, first.connection, first.authored = inp.value, inp.path, inp.connection, True
        first.meta.update({k: v for k, v in inp.meta.items() if k in ("unit", "unittype", "colorspace")})
        if inp.socket is not None:
            first.bind_socket(inp.socket)
            inp.socket.consumers.remove(inp)
            inp.socket = None
        inp.connection = next(iter(node.outputs.values()))
        return first

    def convert_units(self, inp: Input) -> None:
        unit, unittype = inp.meta.get("unit"), inp.meta.get("unittype")
        if not unit or not unittype or inp.type not in ("float", "vector2", "vector3", "vector4"):
            return
        decl_unit = next((d.get("unit") for d in self.scope.nodedef_inputs(inp.node.nodedef) if d.name == inp.name),
                         None)  # the unit the implementation expects
        target = TARGET_UNITS.get(unittype) or decl_unit
        src_scale, dst_scale = self.scope.unit_scale(unittype, unit), self.scope.unit_scale(unittype, target or "")
        if src_scale is None or dst_scale is None:
            return
        suffix = "" if inp.type == "float" else "FA"
        node = self.transform_node(f"{inp.node.name}_{inp.name}_unit", f"ND_multiply_{inp.type}{suffix}", inp.path)
        if node is not None:
            self.insert_before(inp, node)
            factor = node.inputs["in2"]
            factor.value, factor.path, factor.authored, factor.derived = src_scale / dst_scale, None, True, True

    def colorspace_node(self, name: str, source: str | None, type_name: str, where: str) -> Node | None:
        """The working colour space is the document's own (MaterialX's rule): a document that names
        none is not colour managed at all. The colour management system makes the node."""
        return self.cms.transform(self, name, source, self.doc_root.get("colorspace"), type_name, where)

    def convert_colorspace(self, inp: Input) -> None:
        if inp.connection is not None or inp.socket is not None:
            return
        node = self.colorspace_node(f"{inp.node.name}_{inp.name}_cm", inp.meta.get("colorspace"), inp.type, inp.path)
        if node is not None:
            self.insert_before(inp, node)

    def convert_file_colorspace(self, node: Node) -> None:
        """A texture in another colour space is transformed after sampling, on the node's colour
        outputs (a multi-output image node such as gltf_colorimage has one colour and one alpha)."""
        file = next((i for i in node.inputs.values() if i.type == "filename"), None)
        if file is None:
            return
        for out in node.outputs.values():
            cm = self.colorspace_node(f"{node.name}_{out.name}_cm", file.meta.get("colorspace"), out.type, file.path)
            if cm is not None:
                next(iter(cm.inputs.values())).connection = out
                self.redirect[id(out)] = next(iter(cm.outputs.values()))

    def bind(self, inp: Input, authored: Element) -> None:
        """Bind a node input to what the document says: a connection, an interface input, or a value."""
        inp.authored = True
        if authored.get("type") and authored.get("type") != inp.type:
            raise ShaderGenError("type_mismatch", f"input '{inp.name}' is {inp.type}, document says "
                                 f"{authored.get('type')}", authored.path)
        for key in ("colorspace", "unit", "unittype"):
            if authored.get(key):
                inp.meta[key] = authored.get(key)
        if authored.get("colorspace") is None and inp.type in ("color3", "color4", "filename"):
            cs = authored.inherited("colorspace")
            if cs:
                inp.meta["colorspace"] = cs
        source = self.source_of(authored)
        if isinstance(source, Socket):
            inp.bind_socket(source)
        elif isinstance(source, Output):
            if source.type != inp.type:
                raise ShaderGenError("type_mismatch", f"input '{inp.name}' is {inp.type} but is connected to the "
                                     f"{source.type} output '{source.name}' of '{source.node.path or source.node.name}'",
                                     authored.path)
            inp.connection = source
        elif isinstance(source, Element) and source.get("defaultgeomprop") and source.get("value") is None:
            inp.connection = self.geomprop_output(source.get("defaultgeomprop"), source)  # a graph input reading geometry
        elif isinstance(source, Element):  # a value, possibly on an interface input
            inp.value = T.parse_value(inp.type, source.get("value"), source.path) if source.get("value") is not None \
                else inp.value
            inp.path = source.path
            if source is not authored:
                inp.meta["interface"] = True  # bound to a graph or document input: an interface value
            if inp.type == "filename" and inp.value:
                inp.value = (source.inherited("fileprefix") or "") + substitute_tokens(inp.value, source, self.scope)
            for key in ("colorspace", "unit", "unittype"):
                if source.get(key) and key not in inp.meta:
                    inp.meta[key] = source.get(key)
            for holder in (authored, source):  # the document's ui metadata overrides the nodedef's
                ui = ui_hints(holder)
                if ui:
                    inp.meta["ui"] = {**inp.meta.get("ui", {}), **ui}

    def source_of(self, port: Element):
        """Where a port's data comes from: an upstream node's Output, an interface Socket of the
        nodegraph being implemented, the Element holding its value, or None."""
        source = self.follow(port)
        if isinstance(source, NodeRef):
            return self.output_of(source.elem, source.output, port.path)
        return source

    def follow(self, port: Element):
        """Like source_of, but names an upstream node by its element (NodeRef) without building it."""
        for _ in range(256):
            graph = _graph_of(port)
            if port.get("nodename"):
                target = graph.child(port.get("nodename")) if graph is not None else None
                if target is None or target.category in ("input", "output", "nodedef", "nodegraph"):
                    raise ShaderGenError("dangling_connection", f"'{port.get('nodename')}' is not a node here",
                                         port.path)
                return NodeRef(target, port.get("output"))
            if port.get("nodegraph"):
                ng = self.doc_root.child(port.get("nodegraph"))
                if ng is None or ng.category != "nodegraph":
                    raise ShaderGenError("dangling_connection", f"nodegraph '{port.get('nodegraph')}' not found",
                                         port.path)
                outs = ng.children_of("output")
                out = ng.child(port.get("output")) if port.get("output") else (outs[0] if outs else None)
                if out is None or out.category != "output":
                    raise ShaderGenError("dangling_connection",
                                         f"nodegraph '{ng.name}' has no output '{port.get('output')}'", port.path)
                port = out
                continue
            if port.get("output") and port.category != "output":
                # an input naming an <output> of its own graph (the document's, at top level)
                out = graph.child(port.get("output")) if graph is not None else None
                if out is None or out.category != "output":
                    raise ShaderGenError("dangling_connection", f"output '{port.get('output')}' not found", port.path)
                port = out
                continue
            name = port.get("interfacename")
            if name:
                if self.interface is not None and name in self.interface:
                    return self.interface[name]
                iface = graph.child(name) if graph is not None else None
                if iface is None and graph is not None and graph.get("nodedef"):
                    # a definition's graph generated on its own: the nodedef's inputs are its interface
                    nodedef = self.scope.nodedef(graph.get("nodedef"))
                    iface = nodedef.child(name) if nodedef is not None else None
                if iface is None or iface.category != "input":
                    raise ShaderGenError("dangling_connection", f"interface input '{name}' not found", port.path)
                port = iface
                continue
            return port if port.category != "output" else None
        raise ShaderGenError("cycle", "interface connections loop", port.path)

    def output_of(self, node_elem: Element, output: str | None, where: str) -> Output:
        node = self.node_for(node_elem)
        out = node.outputs.get(output) if output else next(iter(node.outputs.values()))
        if out is None:
            raise ShaderGenError("dangling_connection", f"node '{node_elem.name}' has no output '{output}'", where)
        return self.redirect.get(id(out), out)

    def geomprop_output(self, name: str, where_elem: Element) -> Output:
        """One shared geometric node per geompropdef (UV0, Nworld, ...), as the seed's default connections."""
        if name in self.geom_nodes:
            return next(iter(self.geom_nodes[name].outputs.values()))
        gdef = self.scope.geompropdef(name)
        if gdef is None:
            raise ShaderGenError("unknown_geomprop", f"unknown default geomprop '{name}'", where_elem.path)
        attrs = {"name": f"geomprop_{name}", "type": gdef.get("type")}
        elem = Element(gdef.get("geomprop"), attrs, self.doc_root)
        for key in ("space", "index", "geomprop"):
            if gdef.get(key) is not None and key != "geomprop":
                elem.children.append(Element("input", {"name": key, "type": "integer" if key == "index" else "string",
                                                       "value": gdef.get(key)}, elem))
        self.synthetic.append(elem)  # `nodes` is keyed by id(element): keep it alive
        node = self.node_for(elem)
        for inp in node.inputs.values():  # published under the geompropdef's name
            if inp.authored:
                inp.path = name
        self.geom_nodes[name] = node
        return next(iter(node.outputs.values()))


TOKEN = re.compile(r"\[(\w+)\]")


def substitute_tokens(text: str, port: Element, scope: Scope) -> str:
    """Filename tokens `[name]` take the value of the nearest <token> on the node, its graph, or
    the nodedef the graph implements (document-level tokens are not in scope, as in MaterialX)."""
    if "[" not in text:
        return text
    tokens: dict[str, str] = {}
    e = port.parent
    while e is not None and e.category != "materialx":
        holders = [e]
        if e.category == "nodegraph" and e.get("nodedef"):
            nodedef = scope.nodedef(e.get("nodedef"))
            holders += [nodedef] if nodedef is not None else []
        for holder in holders:
            for t in holder.children_of("token"):
                tokens.setdefault(t.name, t.get("value", ""))
        e = e.parent
    return TOKEN.sub(lambda m: tokens.get(m.group(1), m.group(0)), text)


def _graph_of(port: Element) -> Element | None:
    """The graph (nodegraph or document) whose nodes a port's `nodename` and `interfacename` name."""
    if port.category == "output":
        return port.parent
    owner = port.parent
    if owner is None or owner.category == "materialx":
        return owner
    return owner.parent
