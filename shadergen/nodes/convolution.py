"""blur: a convolution needs its input at neighbouring texture coordinates, which a value
computed once per pixel does not have; all samples are equal, so the kernel returns the input
(MaterialX's hardware generators do the same). heighttonormal, which can work from screen-space
derivatives instead, is a source function (mx_heighttonormal.glsl).
"""
from .base import NodeImpl, register

BLUR_TYPES = ("float", "color3", "color4", "vector2", "vector3", "vector4")


@register(*(f"IM_blur_{t}" for t in BLUR_TYPES))
class Blur(NodeImpl):
    def emit_function_call(self, node, ctx):
        ctx.assign(next(iter(node.outputs.values())), ctx.value(node.inputs["in"]))
