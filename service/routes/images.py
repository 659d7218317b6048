"""POST /v1/images/decode: an image file the browser cannot decode (EXR, TIFF, TGA) as float32
pixels, for the editor's dropped environments and textures; nothing is stored."""
import asyncio
from typing import Annotated

from fastapi import APIRouter, Query, Request, Response

from ..config import get_settings
from ..images import NAME_PATTERN, decode_image
from .common import ERRORS

router = APIRouter(prefix="/v1/images", tags=["images"])
# its body is an image file, as large as a texture the editor may fetch (SHADERGEN_MAX_TEXTURE_BYTES)
DECODE_PATH = "/v1/images/decode"

FLOATS = "application/octet-stream"
BODY = {"requestBody": {"required": True, "content": {
    FLOATS: {"schema": {"type": "string", "format": "binary", "description": "the image file as it is on disk"}}}}}
PIXELS = {200: {"content": {FLOATS: {"schema": {"type": "string", "format": "binary"}}},
                "description": "float32 little-endian pixels, rows top first, channels interleaved; the size in "
                               "X-Image-Width, X-Image-Height and X-Image-Channels"}}


@router.post("/decode", response_class=Response, responses={**PIXELS, **ERRORS}, openapi_extra=BODY,
             summary="Decode an EXR, TIFF or TGA file to float pixels (nothing stored)")
async def decode(request: Request,
                 name: Annotated[str, Query(min_length=5, max_length=255, pattern=NAME_PATTERN,
                                            description="the file's name; its suffix chooses the reader")]
                 ) -> Response:
    body = await request.body()
    image = await asyncio.to_thread(decode_image, body, name, get_settings().max_texture_bytes)
    headers = {"X-Image-Width": str(image.width), "X-Image-Height": str(image.height),
               "X-Image-Channels": str(image.channels), "Cache-Control": "no-store"}
    return Response(image.pixels.tobytes(), media_type=FLOATS, headers=headers)
