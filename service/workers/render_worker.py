"""Render child process: one Renderer, whose EGL context is created in this process on its first
render and kept for every job after it (a context cannot cross a fork, and creating one per job
would cost more than most renders)."""
from shadergen.render import Renderer, RenderError
from shadergen.render.imageio import encode_png
from shadergen.render.worker import lp_threads_for

from ..config import get_settings
from .child import serve


class RenderHandler:
    def __init__(self):
        settings = get_settings()
        roots = settings.texture_roots
        # the pool's processes share the machine's cores instead of each taking all of them
        self.renderer = Renderer(texture_roots=roots, search_paths=roots,
                                 lp_threads=lp_threads_for(settings.render_workers))

    def __call__(self, message: dict, payload: bytes) -> tuple[dict, bytes]:
        return render(self.renderer, message)


def render(renderer, request: dict) -> tuple[dict, bytes]:
    """Shared with the Celery task: the request is `{"record", "size", "mesh"}`."""
    try:
        result = renderer.render(request["record"], size=request["size"], mesh=request["mesh"], document_dir=None)
    except RenderError as exc:
        code = getattr(exc, "code", None) or "render_failed"
        return {"error": {"code": code, "message": str(exc), "where": getattr(exc, "where", None)}}, b""
    return {"timings_ms": result.timings_ms, "warnings": list(result.warnings)}, encode_png(result.rgba)


def main() -> None:
    serve(RenderHandler(), {"ready": True})


if __name__ == "__main__":
    main()
