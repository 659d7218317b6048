"""Upgrade documents written for older MaterialX versions to 1.39.

Steps run in version order, each a pass of small rules over the whole element tree, so a later
step sees what an earlier one produced (a 1.37 `channels` attribute becomes a 1.38 swizzle node,
which the 1.39 step turns into extract/combine nodes):
- before 1.26 (1.22, 1.25): `opgraph` graphs, `shader` elements, connections written as
  `opgraphnode` values, and materials' `override` values by public name;
- before 1.37 (1.36 and older): color2 is vector2; nodes whose name said less than their
  signature (`invert` of a matrix, `rotate`, `compare`, `transformpoint/vector/normal` by a
  matrix, `combine`, `separate`) renamed, `geomattr` is `geomprop`;
- before 1.38: materials whose `shaderref` children name their shader node (1.22-1.37), the
  1.37 BSDF nodes (`*_brdf`, `*_btdf`, a `base` input instead of a layer), `channels`, atan2's
  inputs in the 1.38 order;
- before 1.39: normalmap's space, swizzle, atan2's inputs named `iny`/`inx`, subsurface_bsdf's
  radius a color3, thin_film_bsdf layers as inputs of the lobe below.
The rules are the standard's (the specification's release notes per version); each step is
checked against the listing the reference's generator makes of the same old document by
bench/upgrade.py.
`upgrade` records what it changed as warnings.
"""
from .element import Element

SWIZZLE_TYPES = {"r": 0, "x": 0, "g": 1, "y": 1, "b": 2, "z": 2, "a": 3, "w": 3}
SHADER_TYPES = {"surface": "surfaceshader", "displacement": "displacementshader", "volume": "volumeshader"}


def _walk(elem: Element):
    yield elem
    for c in elem.children:
        yield from _walk(c)


def _graph_node(graph: Element | None, name: str | None) -> Element | None:
    node = graph.child(name) if graph is not None and name else None
    return node if node is not None and node.category not in ("input", "output") else None


# -- before 1.26 -------------------------------------------------------------------------------

def _opgraph(elem: Element) -> bool:
    """1.22 called node graphs `opgraph`, and the 1.22 constant's value `color`."""
    if elem.category == "opgraph":
        elem.category = "nodegraph"
        return True
    value = elem.child("color") if elem.category == "constant" else None
    if value is not None and elem.child("value") is None:
        value.name = value.attrs["name"] = "value"
        elem._by_name = None
        return True
    return False


def _opgraphnode(port: Element) -> bool:
    """A connection written as a port of type `opgraphnode` whose value names the upstream node."""
    if port.get("type") != "opgraphnode" or port.parent is None:
        return False
    owner = port.parent
    if owner.category == "output":
        owner.attrs["nodename"] = port.get("value", "")
        owner.remove_child(port)
        return True
    upstream = _graph_node(owner.parent, port.get("value"))
    port.attrs["nodename"] = port.attrs.pop("value", "")
    port.attrs["type"] = upstream.get("type", "float") if upstream is not None else "float"
    return True


def _shader(elem: Element) -> bool:
    """A 1.22/1.25 `<shader shadername|shaderprogram="standard_surface">` is a shader node, its
    inputs reading graph outputs through `graphname`/`graphoutput`."""
    if elem.category != "shader":
        return False
    elem.category = elem.attrs.pop("shadername", None) or elem.attrs.pop("shaderprogram", None) or "shader"
    elem.attrs["type"] = SHADER_TYPES.get(elem.attrs.pop("shadertype", "surface"), "surfaceshader")
    for inp in elem.children_of("input", "parameter"):
        if inp.get("graphname"):
            inp.attrs["nodegraph"] = inp.attrs.pop("graphname")
        if inp.get("graphoutput"):
            inp.attrs["output"] = inp.attrs.pop("graphoutput")
    return True


# -- before 1.37 -------------------------------------------------------------------------------

CHANNEL_COUNT = {"color2": 2, "vector2": 2, "color3": 3, "vector3": 3, "color4": 4, "vector4": 4}
COLOR2_OUTPUTS = {"outr": "outx", "outa": "outy"}  # a color2's channels were r and a


def _rename_ports(node: Element, names: dict[str, str]) -> None:
    """Rename a node's inputs at once (so a swap reads the old names), e.g. {"in1": "in2", "in2": "in1"}."""
    for port in node.children_of("input", "parameter"):
        if port.name in names:
            port.name = port.attrs["name"] = names[port.name]
    node._by_name = None


def _readers(node: Element):
    """The ports and outputs of the node's graph that read it."""
    graph = node.parent
    for elem in graph.children if graph is not None else ():
        for port in [elem] if elem.category == "output" else elem.children_of("input", "parameter"):
            if port.get("nodename") == node.name:
                yield port


def _color2(elem: Element) -> bool:
    """1.37 dropped color2 for vector2: a separate of a color2 gave outr and outa, now outx and outy."""
    if elem.get("type") != "color2":
        return False
    elem.attrs["type"] = "vector2"
    owner = elem.parent
    if elem.category in ("input", "parameter") and owner is not None and owner.category in ("separate", "separate2"):
        for port in _readers(owner):
            if port.get("output") in COLOR2_OUTPUTS:
                port.attrs["output"] = COLOR2_OUTPUTS[port.get("output")]
    return True


def _compare(node: Element) -> bool:
    """`compare` is `ifgreatereq` (in1 where value1 >= value2, else in2): intest and cutoff are
    value1 and value2, and in1 and in2 trade places (compare's in1 is the value below the cutoff)."""
    if node.category != "compare":
        return False
    node.category = "ifgreatereq"
    _rename_ports(node, {"intest": "value1", "cutoff": "value2", "in1": "in2", "in2": "in1"})
    return True


def _invert_matrix(node: Element) -> bool:
    """`invert` of a matrix (its inverse, not 1 - in) is invertmatrix."""
    if node.category != "invert" or node.get("type") not in ("matrix33", "matrix44"):
        return False
    node.category = "invertmatrix"
    return True


def _rotate(node: Element) -> bool:
    """`rotate` of a vector2 is rotate2d, of a vector3 rotate3d."""
    if node.category != "rotate" or node.get("type") not in ("vector2", "vector3"):
        return False
    node.category = "rotate2d" if node.get("type") == "vector2" else "rotate3d"
    return True


def _transform_by_matrix(node: Element) -> bool:
    """transformpoint/vector/normal by a `mat` input (not between named spaces) is transformmatrix."""
    if node.category not in ("transformpoint", "transformvector", "transformnormal") or node.child("mat") is None:
        return False
    node.category = "transformmatrix"
    return True


def _combine(node: Element) -> bool:
    """`combine` is combineN, N the channels of its type."""
    size = CHANNEL_COUNT.get(node.get("type"))
    if node.category != "combine" or size is None:
        return False
    node.category = f"combine{size}"
    return True


def _separate(node: Element) -> bool:
    """`separate` is separateN, N the channels of its input's type."""
    source = node.child("in") if node.category == "separate" else None
    size = CHANNEL_COUNT.get(source.get("type")) if source is not None else None
    if size is None:
        return False
    node.category = f"separate{size}"
    return True


def _geomattr(elem: Element) -> bool:
    """1.37 calls geometry attributes geometry properties: `geomattr` in a geominfo is `geomprop`,
    and `geomattrvalue attrname=` is `geompropvalue geomprop=`."""
    if elem.category == "geomattr":
        elem.category = "geomprop"
        return True
    if elem.category == "geomattrvalue":
        elem.category = "geompropvalue"
        if "attrname" in elem.attrs:
            elem.attrs["geomprop"] = elem.attrs.pop("attrname")
        return True
    return False


# -- before 1.38 -------------------------------------------------------------------------------

def _shader_node_of(material: Element, ref: Element) -> Element:
    """The shader node a shaderref names: a 1.22/1.25 shader of that name (with the material's
    overrides of its public names applied), or a node the 1.37 shaderref itself describes."""
    root = material.parent
    shader = root.child(ref.name)
    if shader is not None and shader.category not in ("material", "surfacematerial"):
        for override in material.children_of("override"):
            for inp in shader.children_of("input", "parameter"):
                if inp.get("publicname") == override.name and override.get("value") is not None:
                    inp.attrs["value"] = override.get("value")
        return shader
    node = ref.get("node") or ref.get("nodedef", "ND_shader").removeprefix("ND_").rsplit("_", 1)[0]
    attrs = {"name": ref.name, "type": SHADER_TYPES.get(ref.get("shadertype", "surface"), "surfaceshader")}
    if ref.get("nodedef"):
        attrs["nodedef"] = ref.get("nodedef")
    shader = Element(node, attrs)
    for bind in ref.children_of("bindinput", "bindparam", "bindtoken"):
        port = {k: v for k, v in bind.attrs.items() if k not in ("output", "nodegraph")}
        if bind.get("nodegraph"):
            port |= {"nodegraph": bind.get("nodegraph"), "output": bind.get("output", "")}
        shader.add_child(Element("token" if bind.category == "bindtoken" else "input", port))
    root.add_child(shader, root.children.index(material))
    return shader


def _material(elem: Element) -> bool:
    """A `<material>` of shaderrefs is a surfacematerial node reading the shader nodes."""
    if elem.category != "material" or not elem.children_of("shaderref"):
        return False
    inputs = []
    for ref in elem.children_of("shaderref"):
        shader = _shader_node_of(elem, ref)
        inputs.append(Element("input", {"name": shader.get("type"), "type": shader.get("type"),
                                        "nodename": shader.name}))
    for child in list(elem.children):
        elem.remove_child(child)
    for inp in inputs:
        elem.add_child(inp)
    elem.category, elem.attrs["type"] = "surfacematerial", "material"
    return True


RENAMED_BSDFS = {"diffuse_brdf": "oren_nayar_diffuse_bsdf", "burley_diffuse_brdf": "burley_diffuse_bsdf",
                 "dielectric_brdf": "dielectric_bsdf", "dielectric_btdf": "dielectric_bsdf",
                 "generalized_schlick_brdf": "generalized_schlick_bsdf", "sheen_brdf": "sheen_bsdf",
                 "subsurface_brdf": "subsurface_bsdf", "conductor_brdf": "conductor_bsdf"}


def _reconnect(graph: Element, old: str, new: str, skip: Element) -> None:
    """Point every port of a graph that reads node `old` at node `new` instead."""
    for elem in graph.children:
        ports = [elem] if elem.category == "output" else elem.children_of("input", "parameter")
        for port in ports:
            if port.get("nodename") == old and elem is not skip:
                port.attrs["nodename"] = new


def _bsdf_1_37(node: Element) -> bool:
    """1.38 renamed the BSDF nodes; a transmission is a dielectric with scatter_mode T, a
    conductor takes ior/extinction (from artistic_ior), and a `base` input is a layer node."""
    if node.category not in RENAMED_BSDFS:
        return False
    graph, old_category = node.parent, node.category
    node.category = RENAMED_BSDFS[old_category]
    if old_category == "dielectric_btdf":
        node.add_child(Element("input", {"name": "scatter_mode", "type": "string", "value": "T"}))
        interior = node.child("interior")
        if interior is not None:
            node.remove_child(interior)
    if old_category == "conductor_brdf":
        artistic = Element("artistic_ior", {"name": f"{node.name}_artistic_ior", "type": "multioutput"})
        for name in ("reflectivity", "edge_color"):
            port = node.child(name)
            if port is not None:
                node.remove_child(port)
                artistic.add_child(port)
        for name in ("ior", "extinction"):
            node.add_child(Element("input", {"name": name, "type": "color3", "nodename": artistic.name,
                                             "output": name}))
        graph.add_child(artistic, graph.children.index(node))
    base = node.child("base")
    if base is not None:
        node.remove_child(base)
        layer = Element("layer", {"name": f"{node.name}_layer", "type": "BSDF"})
        layer.add_child(Element("input", {"name": "top", "type": "BSDF", "nodename": node.name}))
        layer.add_child(Element("input", {k: v for k, v in base.attrs.items()} | {"name": "base"}))
        _reconnect(graph, node.name, layer.name, layer)
        graph.add_child(layer, graph.children.index(node) + 1)
    return True


def _channels(port: Element) -> bool:
    """A 1.37 `channels` attribute on a connection is a 1.38 swizzle node between the two."""
    channels = port.get("channels")
    if channels is None or port.category not in ("input", "parameter", "output"):
        return False
    del port.attrs["channels"]
    owner = port if port.category == "output" else port.parent
    graph = owner.parent
    upstream = _graph_node(graph, port.get("nodename"))
    if upstream is None or graph is None:
        return True  # nothing to reorder: the value is read as written
    swizzle = Element("swizzle", {"name": f"{owner.name}_{port.name}_swizzle", "type": port.get("type")})
    source = {"name": "in", "type": upstream.get("type"), "nodename": upstream.name}
    if port.get("output"):
        source["output"] = port.attrs.pop("output")
    swizzle.add_child(Element("input", source))
    swizzle.add_child(Element("input", {"name": "channels", "type": "string", "value": channels}))
    graph.add_child(swizzle, graph.children.index(owner))
    port.attrs["nodename"] = swizzle.name
    return True


def _atan2_order(node: Element) -> bool:
    """1.38 swapped atan2's two inputs: a 1.37 document's in1 is the 1.38 in2, and in2 is in1."""
    if node.category != "atan2" or node.child("in1") is None and node.child("in2") is None:
        return False
    _rename_ports(node, {"in1": "in2", "in2": "in1"})
    return True


# -- before 1.39 -------------------------------------------------------------------------------

def _unique_name(graph: Element, base: str) -> str:
    name, n = base, 1
    while graph.child(name) is not None:
        n += 1
        name = f"{base}{n}"
    return name


def _normalmap(node: Element) -> bool:
    """1.39 removed normalmap's `space` input and the generic ND_normalmap. An object-space map
    holds the normal itself, encoded in [0, 1]: it becomes normalize(in * 2 - 1)."""
    if node.category != "normalmap":
        return False
    changed = False
    if node.get("nodedef") == "ND_normalmap":
        del node.attrs["nodedef"]
        changed = True
    space = node.child("space")
    if space is not None:
        node.remove_child(space)
        changed = True
        if space.get("value") == "object":
            _decode_object_space_normal(node)
    return changed


def _decode_object_space_normal(node: Element) -> None:
    graph, source = node.parent, node.child("in")
    scaled = Element("multiply", {"name": _unique_name(graph, "multiply"), "type": "vector3"})
    if source is not None:
        scaled.add_child(Element("input", {k: v for k, v in source.attrs.items()} | {"name": "in1"}))
    scaled.add_child(Element("input", {"name": "in2", "type": "float", "value": "2.0"}))
    graph.add_child(scaled, graph.children.index(node))
    shifted = Element("subtract", {"name": _unique_name(graph, "subtract"), "type": "vector3"})
    shifted.add_child(Element("input", {"name": "in1", "type": "vector3", "nodename": scaled.name}))
    shifted.add_child(Element("input", {"name": "in2", "type": "float", "value": "1.0"}))
    graph.add_child(shifted, graph.children.index(node))
    for child in list(node.children):
        node.remove_child(child)
    node.category = "normalize"
    node.add_child(Element("input", {"name": "in", "type": "vector3", "nodename": shifted.name}))


CHANNEL_OUTPUTS = {"color": ("outr", "outg", "outb", "outa"), "vector": ("outx", "outy", "outz", "outw")}
CONNECTION_ATTRIBUTES = ("nodename", "nodegraph", "interfacename", "output")


def _swizzle(node: Element) -> bool:
    """1.39 removed `swizzle`. A swizzled value is a `constant` of the reordered value; one channel
    of a connection is an `extract`; several are a `combineN` of one `separateN` of the source
    (the 0/1 letters as values). A float source has no channels: it is read as it is (a `dot`, or
    every input of the combine)."""
    if node.category != "swizzle":
        return False
    channels_input = node.child("channels")
    channels = channels_input.get("value", "") if channels_input is not None else ""
    source = node.child("in")
    node.attrs.pop("nodedef", None)
    if channels_input is not None:
        node.remove_child(channels_input)
    if source is not None:
        source.attrs.pop("nodedef", None)
    if source is None or not any(source.get(k) for k in CONNECTION_ATTRIBUTES):
        _swizzled_constant(node, source, channels)
        return True
    source_type = source.get("type", "float")
    if len(channels) <= 1:
        if source_type == "float":
            node.category = "dot"
        else:
            node.category = "extract"
            node.add_child(Element("input", {"name": "index", "type": "integer",
                                             "value": str(SWIZZLE_TYPES.get(channels or "r", 0))}))
        return True
    graph = node.parent
    node.category = f"combine{len(channels)}"
    node.remove_child(source)
    separate = None
    if source_type != "float":
        size = int(source_type[-1])
        separate = Element(f"separate{size}", {"name": _unique_name(graph, f"{node.name}_separate"),
                                               "type": "multioutput"})
        separate.add_child(Element("input", {k: v for k, v in source.attrs.items()} | {"name": "in"}))
        graph.add_child(separate, graph.children.index(node))
    outputs = CHANNEL_OUTPUTS["color" if source_type.startswith("color") else "vector"]
    for i, ch in enumerate(channels):
        inp = Element("input", {"name": f"in{i + 1}", "type": "float"})
        if ch in "01":
            inp.attrs["value"] = ch + ".0"
        elif separate is None:
            inp.attrs |= {k: v for k, v in source.attrs.items() if k not in ("name", "type")}
        else:
            inp.attrs |= {"nodename": separate.name, "output": outputs[SWIZZLE_TYPES.get(ch, 0)]}
        node.add_child(inp)
    return True


def _swizzled_constant(node: Element, source: Element | None, channels: str) -> None:
    parts = (source.get("value", "") if source is not None else "").replace(",", " ").split() or ["0"]
    picked = [ch + ".0" if ch in "01" else parts[min(SWIZZLE_TYPES.get(ch, 0), len(parts) - 1)]
              for ch in channels or "r"]
    for child in list(node.children):
        node.remove_child(child)
    node.category = "constant"
    node.add_child(Element("input", {"name": "value", "type": node.get("type", "float"), "value": ", ".join(picked)}))


def _atan2_names(node: Element) -> bool:
    """1.39 named atan2's inputs for what they are: a 1.38 in1 is y, in2 is x."""
    if node.category != "atan2" or node.child("in1") is None and node.child("in2") is None:
        return False
    _rename_ports(node, {"in1": "iny", "in2": "inx"})
    return True


def _subsurface_radius(node: Element) -> bool:
    """1.39 made subsurface_bsdf's radius a color3: a vector3 one reaches it through a convert."""
    radius = node.child("radius") if node.category == "subsurface_bsdf" else None
    if radius is None or radius.get("type") != "vector3":
        return False
    graph = node.parent
    convert = Element("convert", {"name": _unique_name(graph, "convert"), "type": "color3"})
    convert.add_child(Element("input", {k: v for k, v in radius.attrs.items()} | {"name": "in"}))
    graph.add_child(convert, graph.children.index(node))
    radius.attrs = {"name": "radius", "type": "color3", "nodename": convert.name}
    return True


THIN_FILM_BASES = ("dielectric_bsdf", "conductor_bsdf", "generalized_schlick_bsdf")


def _thin_film(layer: Element) -> bool:
    """1.39 removed thin_film_bsdf: a thin film layered over a dielectric, conductor or generalized
    Schlick lobe is that lobe's own thinfilm_thickness and thinfilm_ior, and what read the layer
    reads the lobe."""
    if layer.category != "layer":
        return False
    graph = layer.parent
    top, base = (_graph_node(graph, layer.child(n).get("nodename") if layer.child(n) is not None else None)
                 for n in ("top", "base"))
    if top is None or base is None or top.category != "thin_film_bsdf" or base.category not in THIN_FILM_BASES:
        return False
    for old, new in (("thickness", "thinfilm_thickness"), ("ior", "thinfilm_ior")):
        port = top.child(old)
        if port is not None:
            base.add_child(Element("input", {k: v for k, v in port.attrs.items()} | {"name": new}))
    _reconnect(graph, layer.name, base.name, layer)
    graph.remove_child(layer)
    layer.parent = None
    if not any(True for _ in _readers(top)):
        graph.remove_child(top)
        top.parent = None
    return True


# (the version a step upgrades to, its rules), in order
STEPS = (((1, 26), (_opgraph, _opgraphnode, _shader)),
         ((1, 37), (_color2, _compare, _invert_matrix, _rotate, _transform_by_matrix, _combine, _separate,
                    _geomattr)),
         ((1, 38), (_material, _bsdf_1_37, _channels, _atan2_order)),
         ((1, 39), (_normalmap, _swizzle, _atan2_names, _subsurface_radius, _thin_film)))


def upgrade(doc) -> None:
    for version, rules in STEPS:
        if doc.version >= version:
            continue
        for elem in list(_walk(doc.root)):
            for rule in rules:
                if elem.parent is not None and rule(elem):
                    doc.warnings.append(f"upgraded {elem.path} to MaterialX {version[0]}.{version[1]} "
                                        f"({rule.__name__.strip('_')})")
    doc.root.attrs["version"] = "1.39"
