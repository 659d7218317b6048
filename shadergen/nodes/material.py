"""Material nodes: a material is the surface (or volume) shader connected to it."""
from ..code.values import value_expr
from .base import NodeImpl, register


@register("IM_surfacematerial", "IM_volumematerial")
class Material(NodeImpl):
    def emit_function_call(self, node, ctx):
        shader_input = node.inputs.get("surfaceshader") or node.inputs.get("volumeshader")
        out = next(iter(node.outputs.values()))
        if shader_input is not None and shader_input.connection is not None:
            ctx.assign(out, ctx.value(shader_input))
        else:
            ctx.assign(out, value_expr(out.type, None))
