"""Nodes whose meaning is an edit of the graph, made by a pass before any code is written."""
from ..errors import ShaderGenError
from .base import NodeImpl, register


@register("IM_thinfilmbxdf")
class ResolvedByPass(NodeImpl):
    """thinfilmbxdf: passes/thin_film.py gives its film to the lobes under it and removes it."""

    def emit_function_call(self, node, ctx) -> None:
        raise ShaderGenError("internal_error", f"<{node.category}> reached emission: a pass should have resolved it",
                             node.path)
