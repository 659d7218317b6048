"""The renderer's one error type: the project's ShaderGenError with render-specific codes."""
from shadergen.errors import ShaderGenError


class RenderError(ShaderGenError):
    """A render that cannot go on. Codes: invalid_record (missing or malformed stages/blocks, an
    error record), unsupported_target, compile_error (`where` is "vertex:LINE", "pixel:LINE" or
    "link"), missing_stream (the shader reads a vertex stream the mesh lacks; `where` names it),
    invalid_mesh, invalid_environment, invalid_lights, invalid_image, invalid_output,
    invalid_request (bad size, nothing to write, ...), no_gl_context, context_misuse (a context
    used from another thread or a forked process); from RenderWorker: timeout, worker_died,
    internal_error; from the CLI: unavailable (no generator in this build)."""
