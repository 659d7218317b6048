"""GET /v1/preview/...: the thumbnail scene for browsers that draw records themselves (the
editor's WebGL2 preview), so a live preview and a thumbnail show the same picture."""
import asyncio

from fastapi import APIRouter, Path, Response

from ..errors import ServiceError
from ..models import PreviewScene
from ..preview import preview_assets
from .common import ERRORS

router = APIRouter(prefix="/v1/preview", tags=["preview"])

BINARY = "application/octet-stream"
# the assets never change while a process runs; a day is short enough for a redeploy
CACHE_CONTROL = {"Cache-Control": "public, max-age=86400"}


@router.get("/scene", response_model=PreviewScene, summary="The thumbnail scene: uniforms, mesh and environment")
async def scene() -> Response:
    description, _ = await asyncio.to_thread(preview_assets)
    return Response(PreviewScene.model_validate(description).model_dump_json(), media_type="application/json",
                    headers=CACHE_CONTROL)


@router.get("/arrays/{name}", response_class=Response, summary="One array of the scene as raw little-endian data",
            responses={200: {"content": {BINARY: {"schema": {"type": "string", "format": "binary"}}},
                             "description": "float32 (uint32 for `indices`): a vertex stream or an environment map"},
                       **ERRORS})
async def array(name: str = Path(max_length=64, description="a mesh stream, `indices`, or an environment sampler")
                ) -> Response:
    _, arrays = await asyncio.to_thread(preview_assets)
    if name not in arrays:
        raise ServiceError("not_found", f"no preview array '{name}'; the scene lists them", "name")
    return Response(arrays[name], media_type=BINARY, headers=CACHE_CONTROL)
