"""POST /v1/thumbnails: a PNG now, or with `?async=true` a job to poll at /v1/jobs/{id}. The body
is a JSON request, or a USD layer or usdz package with the options in the query."""
from typing import Annotated

from fastapi import APIRouter, Query, Request, Response
from fastapi.responses import JSONResponse
from pydantic import ValidationError

from ..deps import ThumbnailsDep
from ..errors import ServiceError, from_validation_error
from ..generation import GenerateParams
from ..models import EnvMethod, Interface, JobAccepted, Mesh, ThumbnailRequest
from ..thumbnails import ThumbnailOrder
from .common import ERRORS, JSON, PNG, PNG_RESPONSE, USD_TYPES, media_type_of

router = APIRouter(prefix="/v1", tags=["thumbnails"])

RunAsync = Annotated[bool, Query(alias="async", description="queue a job instead of waiting")]
WITH_USD = "with a USD body"
BODY = {"requestBody": {"required": True, "content": {
    JSON: {"schema": ThumbnailRequest.model_json_schema()},
    "model/vnd.usda": {"schema": {"type": "string", "description": "a USD layer that refers to no other file; "
                                  "textures come from the texture roots; element, interface, size, mesh and env_method "
                                  "come "
                                  "from the query"}},
    "model/vnd.usdz+zip": {"schema": {"type": "string", "format": "binary", "description": "a usdz package; its "
                                      "textures are read from inside it; options from the query"}},
}}}


@router.post("/thumbnails", responses={**ERRORS, 200: PNG_RESPONSE, 202: {"model": JobAccepted}},
             response_class=Response, openapi_extra=BODY, summary="Render a material thumbnail")
async def thumbnail(
    request: Request,
    thumbnails: ThumbnailsDep,
    run_async: RunAsync = False,
    element: Annotated[str | None, Query(max_length=1024, description=f"{WITH_USD}: a material's prim path")] = None,
    interface: Annotated[Interface, Query(description=WITH_USD)] = "complete",
    size: Annotated[int, Query(ge=16, le=1024, description=WITH_USD)] = 256,
    mesh: Annotated[Mesh, Query(description=WITH_USD)] = "sphere",
    env_method: Annotated[EnvMethod, Query(description=WITH_USD)] = "fis",
) -> Response:
    media_type = media_type_of(request)
    body = await request.body()
    if media_type in USD_TYPES:
        params = GenerateParams(element=element, interface=interface, document_format=USD_TYPES[media_type])
        order = ThumbnailOrder(body, params, size, mesh, env_method)
    elif media_type == JSON:
        try:
            req = ThumbnailRequest.model_validate_json(body)
        except ValidationError as exc:
            raise from_validation_error(exc) from None
        order = ThumbnailOrder(req.document.encode(), GenerateParams(element=req.element, interface=req.interface),
                               req.size, req.mesh, req.env_method)
    else:
        raise ServiceError("unsupported_media_type", "send application/json, model/vnd.usda or model/vnd.usdz+zip, "
                           f"not {media_type}")
    if run_async:
        job_id = await thumbnails.submit(order)
        accepted = JobAccepted(id=job_id, state="queued", status_url=f"/v1/jobs/{job_id}")
        return JSONResponse(accepted.model_dump(), status_code=202)
    return Response(await thumbnails.thumbnail(order), media_type=PNG)
