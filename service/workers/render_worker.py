"""Render child process: one Renderer, whose EGL context is created in this process on its first
render and kept for every job after it (a context cannot cross a fork, and creating one per job
would cost more than most renders)."""
import base64
import os
import tempfile

from shadergen.cms import display_encoder
from shadergen.errors import ShaderGenError
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
        self.renderer = Renderer(texture_roots=roots, search_paths=roots, max_programs=programs_kept(settings),
                                 lp_threads=lp_threads_for(settings.render_workers))

    def __call__(self, message: dict, payload: bytes) -> tuple[dict, bytes]:
        return render(self.renderer, message)


def programs_kept(settings) -> int:
    """Compiled programs a render worker keeps for reuse: none without topology sharing."""
    return Renderer.MAX_PROGRAMS if settings.topology_sharing else 0


PACKAGE = "upload.usdz"  # a usdz upload's name in its job's folder


def render(renderer, request: dict) -> tuple[dict, bytes]:
    """Shared with the Celery task: the request is `{"record", "size", "mesh", "env_method"}`, `"display"`
    for an OCIO record (cms.display_encoder: the PNG through the config's display and view), and
    `"package"` (base64) for a usdz upload, whose record names its textures as members of the package."""
    if "package" not in request:
        return _render(renderer, request["record"], request, None)
    try:
        with tempfile.TemporaryDirectory(prefix="shadergen-job-") as folder:
            with open(os.path.join(folder, PACKAGE), "wb") as f:
                f.write(base64.b64decode(request["package"]))
            return _render(renderer, in_package(request["record"], PACKAGE), request, folder)
    finally:  # the package is gone with its folder: its textures go too, not kept for no later job
        renderer.trim_textures()


def in_package(record: dict, package: str) -> dict:
    """The record with each texture named as a member of `package` (`package[textures/a.png]`)."""
    blocks = {stage: {name: [dict(v, value=f"{package}[{v['value']}]") if v.get("type") == "filename"
                             and v.get("value") else v for v in variables]
                      for name, variables in block.items()}
              for stage, block in record["blocks"].items()}
    return dict(record, blocks=blocks)


def _render(renderer, record: dict, request: dict, document_dir: str | None) -> tuple[dict, bytes]:
    try:
        encode = display_encoder(request.get("display"))
        result = renderer.render(record, size=request["size"], mesh=request["mesh"], env_method=request["env_method"],
                                 document_dir=document_dir)
    except RenderError as exc:
        code = getattr(exc, "code", None) or "render_failed"
        return {"error": {"code": code, "message": str(exc), "where": getattr(exc, "where", None)}}, b""
    except ShaderGenError as exc:  # the display or view the request names
        return {"error": exc.to_dict()}, b""
    return ({"timings_ms": result.timings_ms, "warnings": list(result.warnings),
             "program_reused": result.program_reused}, encode_png(result.rgba, encode=encode))


def main() -> None:
    serve(RenderHandler(), {"ready": True})


if __name__ == "__main__":
    main()
