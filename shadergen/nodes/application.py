"""Application nodes: values the host sets each frame (seed figure 7: u_time, u_frame)."""
from .base import NodeImpl, register


@register("IM_time_float")
class Time(NodeImpl):
    def emit_function_call(self, node, ctx):
        ctx.assign(next(iter(node.outputs.values())), ctx.private_uniform("u_time", "float"))


@register("IM_frame_float")
class Frame(NodeImpl):
    def emit_function_call(self, node, ctx):
        ctx.assign(next(iter(node.outputs.values())), ctx.private_uniform("u_frame", "float"))
