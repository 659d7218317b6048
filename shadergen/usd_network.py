"""UsdShade networks -> MaterialX elements: each material's surface network onto our nodes.

A shader prim becomes one node element: `info:id` names either a UsdPreviewSurface node
(`UsdPreviewSurface`, `UsdUVTexture`, `UsdPrimvarReader_*`, `UsdTransform2d`, onto our nodedefs of
the same nodes) or a MaterialX nodedef (`ND_standard_surface_surfaceshader`, ...). Connections are
followed through node graphs and material interfaces with UsdShade's own resolution, so a node
element holds either a value or a `nodename` connection (through a `convert` node where USD
connects one underlying type across roles, a float3 into a color3f or normal3f). Node names are the
prim paths made into MaterialX names; `labels` maps every element path back to the prim path users
know it by, and every error names a prim path as its `where`.
"""
import os

from .element import Element
from .errors import ShaderGenError
from .library import Scope
from .types import TYPES

# MaterialX's own render context first: a material carrying both is meant for MaterialX there.
SURFACE_OUTPUTS = ("mtlx:surface", "surface")

# UsdPreviewSurface shader ids and the nodedefs that implement them here.
PRIMVAR_TYPES = {"float": "float", "float2": "vector2", "float3": "vector3", "float4": "vector4", "int": "integer",
                 "string": "string", "normal": "vector3", "point": "vector3", "vector": "vector3"}
USD_NODEDEFS = {
    "UsdPreviewSurface": "ND_UsdPreviewSurface_surfaceshader",
    "UsdUVTexture": "ND_UsdUVTexture_23",
    "UsdTransform2d": "ND_UsdTransform2d",
    **{f"UsdPrimvarReader_{usd}": f"ND_UsdPrimvarReader_{mx}" for usd, mx in PRIMVAR_TYPES.items()},
}
# USD connects values of one underlying type whatever their roles (float3, color3f, normal3f,
# vector3f, point3f, texCoord3f are one float3): where our nodedefs give the two ends different
# types of one size, a MaterialX `convert` node between them keeps the graph typed.
ROLE_CONVERSIONS = {("color3", "vector3"), ("vector3", "color3"), ("color4", "vector4"), ("vector4", "color4")}
# MaterialX nodedefs that 1.39 renamed, which USD written for 1.38 still names (`space`, gone in 1.39,
# is then an input the nodedef lacks and is ignored with a warning).
RENAMED_NODEDEFS = {"ND_normalmap": "ND_normalmap_float"}
# UsdGeom's name for the primary texture coordinates: a reader of it is our texcoord node, which
# reads the mesh's first uv set, as Hydra binds the mesh's `st` primvar.
PRIMARY_UV_PRIMVAR = "st"

# UsdUVTexture's wrap modes that our nodedef spells differently (useMetadata: the nodedef's default).
WRAP_MODES = {"repeat": "periodic", "black": "black", "clamp": "clamp", "mirror": "mirror", "periodic": "periodic"}
# Colour space names USD writes (sourceColorSpace tokens, colorSpace metadata) -> MaterialX's.
COLORSPACES = {"sRGB": "srgb_texture", "srgb_rec709_scene": "srgb_texture", "raw": "raw", "data": "raw",
               "g22_rec709_scene": "g22_rec709", "g18_rec709_scene": "g18_rec709", "lin_rec709_scene": "lin_rec709",
               "lin_ap1_scene": "acescg"}
# sourceColorSpace "auto": the UsdPreviewSurface spec reads 8-bit images as sRGB, all else as linear;
# the bit depth is judged by the format, since generation never opens the image.
EIGHT_BIT_FORMATS = (".png", ".jpg", ".jpeg", ".bmp", ".tga", ".gif")


def mx_name(prim_path: str) -> str:
    """A MaterialX element name for a prim path (`/World/Looks/Mat` -> `World_Looks_Mat`)."""
    name = "".join(c if c.isalnum() or c == "_" else "_" for c in prim_path.strip("/"))
    return name if name and not name[0].isdigit() else "_" + name


def format_value(value, type_name: str, where: str) -> str:
    """A USD value (Gf vector, matrix, number, bool, string) as a MaterialX value string of `type_name`."""
    if type_name in ("string", "filename"):
        return str(value)
    if type_name == "boolean":
        return "true" if value else "false"
    flat = _flatten(value)
    if len(flat) != max(TYPES[type_name].size, 1) or isinstance(flat[0], str):
        raise ShaderGenError("type_mismatch", f"a value of {len(flat)} component(s) cannot be a {type_name}", where)
    if type_name == "integer":
        return str(int(flat[0]))
    return ", ".join(f"{float(v):.7g}" for v in flat)  # float32 precision, as USD holds and GL reads it


def enum_value(token: str, decl: Element, where: str) -> str:
    """The integer of a token USD writes for an enumerated input (opacityMode "presence" -> 1)."""
    names = decl.get("enum").split(",")
    values = (decl.get("enumvalues") or ",".join(map(str, range(len(names))))).split(",")
    if token not in names:
        raise ShaderGenError("invalid_value", f"'{token}' is not one of {', '.join(names)}", where)
    return values[names.index(token)].strip()


def _flatten(value) -> list:
    if isinstance(value, (bool, int, float, str)):
        return [value]
    out = []
    for part in value:  # Gf vectors iterate their components, Gf matrices their rows
        out.extend(_flatten(part))
    return out


class NetworkTranslator:
    """Adds node elements to `root` for the shader prims materials reach, each prim once."""

    def __init__(self, scope: Scope, root: Element, asset_value, warnings: list[str]):
        from pxr import Usd, UsdShade  # imported here: only USD documents pay for usd-core

        self.Usd, self.UsdShade = Usd, UsdShade
        self.scope = scope
        self.root = root
        self.asset_value = asset_value  # (attribute, Sdf.AssetPath, where) -> filename string
        self.warnings = warnings
        self.nodes: dict[str, Element] = {}  # prim path -> its node element
        self.labels: dict[str, str] = {}  # element path -> prim path (or attribute path)
        self.names: set[str] = {c.name for c in root.children}
        self.conversions: dict[tuple[str, str | None, str], Element] = {}  # (node, output, type) -> convert

    def unique_name(self, prim_path: str) -> str:
        base = name = mx_name(prim_path)
        n = 1
        while name in self.names:
            name, n = f"{base}_{n}", n + 1
        self.names.add(name)
        return name

    # -- materials ---------------------------------------------------------------------------
    def material(self, material, name: str) -> Element:
        """The surfacematerial element of a UsdShadeMaterial, its network translated first."""
        where = str(material.GetPath())
        elem = Element("surfacematerial", {"name": name, "type": "material"})
        output = next((o for o in (material.GetOutput(n) for n in SURFACE_OUTPUTS) if o), None)
        sources = output.GetValueProducingAttributes(shaderOutputsOnly=True) if output else []
        if not sources:
            others = [o.GetBaseName() for o in material.GetOutputs() if o.GetBaseName().endswith(":surface")]
            elsewhere = f" (only outputs:{others[0]}, a render context not translated here)" if others else ""
            raise ShaderGenError("invalid_document", "the material has no connected outputs:mtlx:surface or "
                                 "outputs:surface" + elsewhere, where)
        node, _, out_type = self.connection(sources[0], where)
        if out_type != "surfaceshader":
            raise ShaderGenError("type_mismatch", f"the material's surface is a {out_type}, not a surfaceshader",
                                 where)
        elem.add_child(Element("input", {"name": "surfaceshader", "type": "surfaceshader", "nodename": node.name}))
        return elem

    def connection(self, attr, where: str) -> tuple[Element, str | None, str]:
        """The node element behind a shader output attribute, the nodedef output it names (None
        for a node with a single output) and that output's type."""
        prim = attr.GetPrim()
        node = self.node(prim)
        outputs = {o.name: o.get("type") for o in self.scope.nodedef_outputs(self.scope.nodedef(node.get("nodedef")))}
        usd_name = attr.GetBaseName()
        if len(outputs) == 1:  # `surface`, `result`, `out`: the one output, whatever USD calls it
            return node, None, next(iter(outputs.values()))
        if usd_name not in outputs:
            raise ShaderGenError("dangling_connection", f"{prim.GetPath()} has no output '{usd_name}'", where)
        return node, usd_name, outputs[usd_name]

    # -- shaders -----------------------------------------------------------------------------
    def node(self, prim) -> Element:
        """The node element of a shader prim, translating every shader upstream of it first.
        Iterative, so chains of any length translate; a connection back onto the current path is
        a cycle, named in full by prim paths."""
        root_path = str(prim.GetPath())
        if root_path in self.nodes:
            return self.nodes[root_path]
        stack = [(prim, iter(self.upstream(prim)))]
        on_path = [root_path]
        while stack:
            current, deps = stack[-1]
            dep = next(deps, None)
            if dep is None:
                stack.pop()
                on_path.pop()
                self.nodes[str(current.GetPath())] = self.make_node(current)
                continue
            dep_path = str(dep.GetPath())
            if dep_path in on_path:
                cycle = on_path[on_path.index(dep_path):] + [dep_path]
                raise ShaderGenError("cycle", "connection cycle: " + " -> ".join(cycle), dep_path)
            if dep_path not in self.nodes:
                on_path.append(dep_path)
                stack.append((dep, iter(self.upstream(dep))))
        return self.nodes[root_path]

    def upstream(self, prim):
        for _, sources in self.input_sources(prim):
            if sources and self.UsdShade.Output.IsOutput(sources[0]):
                yield sources[0].GetPrim()

    def input_sources(self, prim):
        """(input, value-producing attributes) of each input of a shader: a connected input
        resolves through node graphs and material interfaces to a shader output or a value."""
        shader = self.UsdShade.Shader(prim)
        if not shader:
            raise ShaderGenError("invalid_document", f"connected prim is a {prim.GetTypeName() or 'typeless prim'}, "
                                 "not a Shader", str(prim.GetPath()))
        for inp in shader.GetInputs():
            where = str(inp.GetAttr().GetPath())
            _, invalid = inp.GetConnectedSources()
            if invalid:
                raise ShaderGenError("dangling_connection",
                                     f"connected to {invalid[0]}, which is not an output or input here", where)
            yield inp, inp.GetValueProducingAttributes(shaderOutputsOnly=False)

    def nodedef_of(self, shader, where: str) -> Element:
        shader_id = shader.GetShaderId()
        if not shader_id:
            raise ShaderGenError("unknown_node", "the shader has no info:id (sourceAsset and sourceCode shaders "
                                 "are not translated)", where)
        nodedef = self.scope.nodedef(USD_NODEDEFS.get(shader_id, RENAMED_NODEDEFS.get(shader_id, shader_id)))
        if nodedef is None:
            raise ShaderGenError("unknown_node", f"shader id '{shader_id}' is neither a UsdPreviewSurface node nor "
                                 "a MaterialX nodedef", where)
        return nodedef

    def make_node(self, prim) -> Element:
        prim_path = str(prim.GetPath())
        shader = self.UsdShade.Shader(prim)
        nodedef = self.nodedef_of(shader, prim_path)
        decls = {i.name: i for i in self.scope.nodedef_inputs(nodedef)}
        values = dict(self.input_sources(prim))
        if nodedef.name == USD_NODEDEFS["UsdPrimvarReader_float2"] and self.reads_primary_uv(values):
            nodedef, values = self.scope.nodedef("ND_texcoord_vector2"), {}
            decls = {i.name: i for i in self.scope.nodedef_inputs(nodedef)}
        outputs = self.scope.nodedef_outputs(nodedef)
        node = Element(nodedef.get("node"), {
            "name": self.unique_name(prim_path), "nodedef": nodedef.name,
            "type": outputs[0].get("type") if len(outputs) == 1 else "multioutput"})
        self.labels[node.name] = prim_path
        self.labels.update({f"{node.name}/{name}": f"{prim_path}.inputs:{name}" for name in decls})
        self.root.add_child(node)
        for inp, sources in values.items():
            name, where = inp.GetBaseName(), str(inp.GetAttr().GetPath())
            decl = decls.get(name)
            if decl is None:
                if name != "sourceColorSpace" or nodedef.get("node") != "UsdUVTexture":
                    self.warnings.append(f"{where}: input '{name}' is not on {nodedef.name}; ignored")
                continue
            elem = self.input_element(decl, sources, where)
            if elem is not None:
                node.add_child(elem)
        if nodedef.get("node") == "UsdUVTexture":
            self.texture_colorspace(node, values)
        return node

    def reads_primary_uv(self, values: dict) -> bool:
        varname = next((s for i, s in values.items() if i.GetBaseName() == "varname"), None)
        return bool(varname) and not self.UsdShade.Output.IsOutput(varname[0]) \
            and varname[0].Get() == PRIMARY_UV_PRIMVAR

    def input_element(self, decl: Element, sources: list, where: str) -> Element | None:
        name, type_name = decl.name, decl.get("type")
        if not sources:
            return None  # neither value nor connection: the nodedef's default
        if len(sources) > 1:
            self.warnings.append(f"{where}: {len(sources)} connections; the first is used")
        source = sources[0]
        attrs = {"name": name, "type": type_name}
        if self.UsdShade.Output.IsOutput(source):
            node, output, out_type = self.connection(source, where)
            if (out_type, type_name) in ROLE_CONVERSIONS:
                node, output = self.role_conversion(node, output, out_type, type_name, where), None
            attrs["nodename"] = node.name
            if output:
                attrs["output"] = output
            return Element("input", attrs)
        value = self.authored_value(source, where)
        if value is None:
            return None
        if type_name == "filename":
            attrs["value"] = self.asset_value(source, value, where)
        elif name in ("wrapS", "wrapT") and isinstance(value, str):
            if value not in WRAP_MODES:
                return None  # useMetadata: no metadata is read, so the nodedef's default
            attrs["value"] = WRAP_MODES[value]
        elif type_name == "integer" and isinstance(value, str) and decl.get("enum"):
            attrs["value"] = enum_value(value, decl, where)
        else:
            attrs["value"] = format_value(value, type_name, where)
        colorspace = source.GetColorSpace() if source.HasColorSpace() else None
        if colorspace and type_name in ("color3", "color4", "filename"):
            attrs["colorspace"] = COLORSPACES.get(colorspace, colorspace)
        return Element("input", attrs)

    def authored_value(self, attr, where: str):
        """The attribute's value; one that is animated is read at its first time sample, the frame a
        viewer opens the stage at (its default value, which is all a plain Get reads, is often unset)."""
        if attr.GetNumTimeSamples() == 0:
            return attr.Get()
        self.warnings.append(f"{where}: animated; the value at its first time sample is used")
        return attr.Get(self.Usd.TimeCode.EarliestTime())

    def role_conversion(self, node: Element, output: str | None, from_type: str, to_type: str, where: str) -> Element:
        """The convert node reading `node`'s output as `to_type`, one per output and type."""
        key = (node.name, output, to_type)
        if key not in self.conversions:
            convert = Element("convert", {"name": self.unique_name(f"{node.name}_{output or 'out'}_as_{to_type}"),
                                          "nodedef": f"ND_convert_{from_type}_{to_type}", "type": to_type})
            source = {"name": "in", "type": from_type, "nodename": node.name}
            convert.add_child(Element("input", {**source, "output": output} if output else source))
            self.labels[convert.name] = where
            self.root.add_child(convert)
            self.conversions[key] = convert
        return self.conversions[key]

    def texture_colorspace(self, node: Element, values: dict) -> None:
        """UsdUVTexture's sourceColorSpace as the colour space of its file (an explicit one wins
        over the file's colorSpace metadata; `auto` decides by format only without it)."""
        file = node.child("file")
        if file is None:
            return
        sources = next((s for i, s in values.items() if i.GetBaseName() == "sourceColorSpace"), None)
        token = sources[0].Get() if sources and not self.UsdShade.Output.IsOutput(sources[0]) else "auto"
        if token in COLORSPACES:
            file.attrs["colorspace"] = COLORSPACES[token]
        elif "colorspace" not in file.attrs:
            eight_bit = os.path.splitext(file.get("value", "").rstrip("]"))[1].lower() in EIGHT_BIT_FORMATS
            file.attrs["colorspace"] = "srgb_texture" if eight_bit else "raw"
