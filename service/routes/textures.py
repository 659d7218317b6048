"""GET /v1/textures: an image a document names, from the texture roots, for browsers that draw
records themselves (the editor's preview binds it as a thumbnail would)."""
import asyncio

from fastapi import APIRouter, Query
from fastapi.responses import FileResponse

from ..config import get_settings
from ..textures import MEDIA_TYPES, find_texture
from .common import ERRORS

router = APIRouter(prefix="/v1", tags=["textures"])

IMAGE_RESPONSE = {"content": {media: {"schema": {"type": "string", "format": "binary"}}
                              for media in sorted(set(MEDIA_TYPES.values()))},
                  "description": "the file as it is on disk"}


@router.get("/textures", response_class=FileResponse, summary="A texture file from the configured texture roots",
            responses={200: IMAGE_RESPONSE, **ERRORS})
async def texture(path: str = Query(min_length=1, max_length=4096,
                                    description="a filename as the record lists it (after the document's "
                                                "fileprefix): relative to a texture root, or absolute inside one")
                  ) -> FileResponse:
    settings = get_settings()
    found = await asyncio.to_thread(find_texture, path, settings.texture_roots, settings.max_texture_bytes)
    return FileResponse(found.path, media_type=found.media_type, headers={"Cache-Control": "no-cache"})
