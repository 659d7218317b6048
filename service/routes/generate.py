"""POST /v1/generate: a JSON body, or the raw XML with the parameters in the query."""
from typing import Annotated

from fastapi import APIRouter, Query, Request, Response
from pydantic import ValidationError

from ..deps import GenerationDep
from ..errors import ServiceError, from_validation_error
from ..generation import GenerateParams
from ..models import GenerateRequest, Interface, ShaderRecord
from .common import ERRORS, json_bytes

router = APIRouter(prefix="/v1", tags=["generate"])

XML_TYPES = ("application/xml", "text/xml")
BODY = {"requestBody": {"required": True, "content": {
    "application/json": {"schema": GenerateRequest.model_json_schema()},
    "application/xml": {"schema": {"type": "string", "description": "the MaterialX document; "
                                   "target, element, interface and source come from the query"}},
}}}


@router.post("/generate", response_model=ShaderRecord, responses=ERRORS, openapi_extra=BODY,
             summary="Generate a shader and its variable listings")
async def generate(
    request: Request,
    generation: GenerationDep,
    target: Annotated[str, Query(max_length=64, description="with an XML body")] = "glsl",
    element: Annotated[str | None, Query(max_length=1024, description="with an XML body")] = None,
    interface: Annotated[Interface, Query(description="with an XML body")] = "complete",
    source: Annotated[bool, Query(description="with an XML body")] = True,
) -> Response:
    media_type = request.headers.get("content-type", "application/json").split(";")[0].strip().lower()
    body = await request.body()
    if media_type in XML_TYPES:
        document, params = body, GenerateParams(target, element, interface, source)
    elif media_type == "application/json":
        try:
            req = GenerateRequest.model_validate_json(body)
        except ValidationError as exc:
            raise from_validation_error(exc) from None
        document, params = req.document.encode(), GenerateParams(req.target, req.element, req.interface, req.source)
    else:
        raise ServiceError("unsupported_media_type", f"send application/json or application/xml, not {media_type}")
    return json_bytes(await generation.generate(document, params))
