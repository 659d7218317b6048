"""transformpoint / transformvector / transformnormal between object (model) and world space.

The spaces are known when the shader is generated, so the node becomes one matrix product with
the predefined matrix uniform (or nothing, when both spaces are the same)."""
from ..code import build
from .base import NodeImpl, register
from .geometric import transform

OBJECT_SPACES = ("object", "model")
MATRIX = {  # (kind, to world?) -> matrix uniform
    ("point", True): "u_worldMatrix", ("point", False): "u_worldInverseMatrix",
    ("vector", True): "u_worldMatrix", ("vector", False): "u_worldInverseMatrix",
    ("normal", True): "u_worldInverseTransposeMatrix", ("normal", False): "u_worldTransposeMatrix",
}


class _Transform(NodeImpl):
    kind = ""  # point, vector or normal

    def emit_function_call(self, node, ctx):
        src = "object" if node.input_value("fromspace", "object") in OBJECT_SPACES else "world"
        dst = "object" if node.input_value("tospace", "world") in OBJECT_SPACES else "world"
        value = ctx.value(node.inputs["in"])
        out = next(iter(node.outputs.values()))
        if src == dst:
            ctx.assign(out, value)
            return
        m = ctx.private_uniform(MATRIX[(self.kind, dst == "world")], "matrix44")
        expr = transform(m, value, point=self.kind == "point")
        ctx.assign(out, build.call("normalize", expr) if self.kind == "normal" else expr)


@register("IM_transformpoint_vector3")
class TransformPoint(_Transform):
    kind = "point"


@register("IM_transformvector_vector3")
class TransformVector(_Transform):
    kind = "vector"


@register("IM_transformnormal_vector3")
class TransformNormal(_Transform):
    kind = "normal"
