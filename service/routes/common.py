"""What several routers share: the documented error responses and the media types."""
from fastapi import Response

from ..models import ErrorResponse

# every route may answer these with the contract's error object
ERRORS = {status: {"model": ErrorResponse} for status in (400, 403, 404, 408, 413, 415, 422, 503, 504)}

JSON = "application/json"
USD_TYPES = {"model/vnd.usda": "usda", "model/vnd.usdz+zip": "usdz"}  # media type -> document format


def media_type_of(request) -> str:
    return request.headers.get("content-type", JSON).split(";")[0].strip().lower()
PNG = "image/png"
PNG_RESPONSE = {"content": {PNG: {"schema": {"type": "string", "format": "binary"}}},
                "description": "the thumbnail (sRGB PNG)"}


def json_bytes(body: bytes, status_code: int = 200) -> Response:
    """Records leave as the bytes the generator (or the cache) produced: re-validating a large
    record on every cached request would cost more than the lookup."""
    return Response(body, status_code=status_code, media_type=JSON)
