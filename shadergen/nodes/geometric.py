"""Geometric nodes (seed 2.5, figure 6): data from the mesh, carried from the vertex stage.

Each node asks for the app-data stream it reads and the vertex data that carries it to the
pixel stage; the vertex stage computes the requested space once, however many nodes read it.
"""
from ..code import build
from .base import NodeImpl, register

WORLD = ("world",)


def transform(matrix, vector, point: bool):
    """A 3-vector through a 4x4 matrix, as a point (w 1) or a direction (w 0)."""
    w = build.number(1.0 if point else 0.0)
    return build.field(build.binary("*", matrix, build.construct("vec4", vector, w)), "xyz")


def world_position():
    """The world-space position the vertex stage computes before anything else."""
    return build.field(build.name("hPositionWorld", "local", "vec4"), "xyz")


def _space(node) -> str:
    space = node.input_value("space", "object")
    return "world" if space in WORLD else "object"


class _SpaceVector(NodeImpl):
    """position, normal, tangent, bitangent in object (= model) or world space."""
    stream = ""  # app data suffix: position, normal, ...
    matrix = ""  # the matrix taking it to world space
    normalized = True  # a direction (normalized), not a point
    fixed_inputs = frozenset({"space", "index"})

    @classmethod
    def varying(cls, ctx, space: str):
        """The pixel-stage expression of this vector in `space` (also used by the surface node)."""
        attr = ctx.app_data(f"i_{cls.stream}", "vector3")
        if space == "world":
            ctx.private_uniform(cls.matrix, "matrix44", ("vertex",))
            matrix = build.name(cls.matrix, "uniform", "mat4")
            expr = build.call("normalize", transform(matrix, attr, point=False)) if cls.normalized \
                else world_position()
        else:
            expr = attr
        return ctx.vertex_data(f"{cls.stream}{space.capitalize()}", "vector3", expr)

    def emit_function_call(self, node, ctx):
        varying = self.varying(ctx, _space(node))
        out = next(iter(node.outputs.values()))
        ctx.assign(out, build.call("normalize", varying) if self.normalized else varying)


@register("IM_position_vector3")
class Position(_SpaceVector):
    stream, matrix, normalized = "position", "u_worldMatrix", False


@register("IM_normal_vector3")
class Normal(_SpaceVector):
    stream, matrix = "normal", "u_worldInverseTransposeMatrix"


@register("IM_tangent_vector3")
class Tangent(_SpaceVector):
    stream, matrix = "tangent", "u_worldMatrix"


@register("IM_bitangent_vector3")
class Bitangent(NodeImpl):
    """Meshes carry normals and tangents; the bitangent is their cross product in the vertex stage."""
    fixed_inputs = frozenset({"space", "index"})

    def emit_function_call(self, node, ctx):
        space = _space(node)
        n, t = ctx.app_data("i_normal", "vector3"), ctx.app_data("i_tangent", "vector3")
        expr = build.call("cross", n, t)
        if space == "world":
            m = ctx.private_uniform("u_worldMatrix", "matrix44", ("vertex",))
            expr = build.call("normalize", transform(m, expr, point=False))
        varying = ctx.vertex_data(f"bitangent{space.capitalize()}", "vector3", expr)
        ctx.assign(next(iter(node.outputs.values())), build.call("normalize", varying))


@register("IM_texcoord_vector2", "IM_texcoord_vector3")
class TexCoord(NodeImpl):
    """The index selects the stream when the shader is generated; it stays listed as MaterialX does."""

    def emit_function_call(self, node, ctx):
        out = next(iter(node.outputs.values()))
        index = int(node.input_value("index", 0))
        attr = ctx.app_data(f"i_texcoord_{index}", out.type)
        ctx.assign(out, ctx.vertex_data(f"texcoord_{index}", out.type, attr))


@register("IM_geomcolor_float", "IM_geomcolor_color3", "IM_geomcolor_color4")
class GeomColor(NodeImpl):
    fixed_inputs = frozenset({"index"})
    COMPONENTS = {"float": "x", "color3": "xyz", "color4": ""}

    def emit_function_call(self, node, ctx):
        out = next(iter(node.outputs.values()))
        index = int(node.input_value("index", 0))
        attr = ctx.app_data(f"i_color_{index}", "color4")
        color = ctx.vertex_data(f"color_{index}", "color4", attr)
        which = self.COMPONENTS[out.type]
        ctx.assign(out, build.field(color, which) if which else color)


GEOMPROP_TYPES = ("integer", "float", "color3", "color4", "vector2", "vector3", "vector4")


@register(*(f"IM_geompropvalue_{t}" for t in GEOMPROP_TYPES))
class GeomPropValue(NodeImpl):
    """A named primvar: a vertex stream `i_geomprop_<name>`; booleans cannot be vertex attributes,
    so they come from a uniform `u_geomprop_<name>` instead (and stay editable, as uniforms are).
    For streams the primvar name and `default` are fixed when the shader is generated: the listing
    gives the stream `default` as its value, what a renderer binds for a mesh without the primvar."""
    fixed_inputs = frozenset({"geomprop", "default"})

    def emit_function_call(self, node, ctx):
        out = next(iter(node.outputs.values()))
        name = node.input_value("geomprop", "") or node.name
        if out.type == "boolean":
            ctx.assign(out, ctx.private_uniform(f"u_geomprop_{name}", out.type))
            return
        attr = ctx.app_data(f"i_geomprop_{name}", out.type, node.input_value("default"))
        if out.type == "integer":  # integer varyings would need `flat`: carry it as a float
            carried = ctx.vertex_data(f"geomprop_{name}", "float", build.convert("float", attr))
            ctx.assign(out, build.convert("int", carried))
        else:
            ctx.assign(out, ctx.vertex_data(f"geomprop_{name}", out.type, attr))


@register("IM_geompropvalue_boolean")
class GeomPropValueBoolean(GeomPropValue):
    fixed_inputs = frozenset()


@register("IM_geompropvalueuniform_string", "IM_geompropvalueuniform_filename")
class GeomPropValueUniform(NodeImpl):
    fixed_inputs = frozenset({"geomprop"})

    def emit_function_call(self, node, ctx):
        out = next(iter(node.outputs.values()))
        name = node.input_value("geomprop", "") or node.name
        ctx.assign(out, ctx.private_uniform(f"u_geomprop_{name}", out.type))
