"""Convolution nodes (blur, heighttonormal).

A convolution needs its input at neighbouring texture coordinates. When the input is not read
from a texture there is nothing to convolve: all samples are equal, so blur returns its input and
heighttonormal the flat normal, which is what the kernels give for equal samples.
"""
from .base import NodeImpl, register

BLUR_TYPES = ("float", "color3", "color4", "vector2", "vector3", "vector4")


@register(*(f"IM_blur_{t}_genglsl" for t in BLUR_TYPES))
class Blur(NodeImpl):
    def emit_function_call(self, node, ctx):
        ctx.assign(next(iter(node.outputs.values())), ctx.value(node.inputs["in"]))


@register("IM_heighttonormal_vector3_genglsl")
class HeightToNormal(NodeImpl):
    def emit_function_call(self, node, ctx):
        ctx.assign(next(iter(node.outputs.values())), "vec3(0.5, 0.5, 1.0)")
