"""The renderer's one error type: the project's ShaderGenError with render-specific codes."""
from shadergen.errors import ShaderGenError


class RenderError(ShaderGenError):
    """A render that cannot go on. Codes: invalid_record (missing or malformed stages/blocks),
    unsupported_target, compile_error (`where` is "stage:line"), missing_stream (the shader reads a
    vertex stream the mesh does not have), invalid_mesh, invalid_environment, invalid_lights,
    no_gl_context, context_misuse (a context used from another thread or a forked process)."""
