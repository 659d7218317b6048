"""POST /v1/thumbnails: a PNG now, or with `?async=true` a job to poll at /v1/jobs/{id}. The body
is a JSON request, or a USD layer or usdz package with the options in the query.
POST /v1/thumbnails/batch: a library's documents as one job (service/batches.py), polled at
/v1/thumbnails/batch/{id}, each PNG at /v1/thumbnails/batch/{id}/{index}."""
from typing import Annotated

from fastapi import APIRouter, Path, Query, Request, Response
from fastapi.responses import JSONResponse
from pydantic import ValidationError

from ..config import get_settings
from ..deps import BatchesDep, ThumbnailsDep
from ..errors import ServiceError, from_validation_error
from ..generation import GenerateParams
from ..models import (CMS_DOC, OCIO_CONFIG_PATTERN, VIEW_DOC, BatchStatus, Cms, EnvMethod, ErrorResponse, Interface,
                      JobAccepted, Mesh, ThumbnailBatchRequest, ThumbnailRequest)
from ..thumbnails import ThumbnailOrder
from .common import ERRORS, JSON, PNG, PNG_RESPONSE, USD_TYPES, media_type_of

router = APIRouter(prefix="/v1", tags=["thumbnails"])
BATCH_PATH = "/v1/thumbnails/batch"  # its body has a limit of its own (SHADERGEN_MAX_BATCH_BODY_BYTES)
BatchId = Annotated[str, Path(pattern="^[0-9a-f]{32}$")]

RunAsync = Annotated[bool, Query(alias="async", description="queue a job instead of waiting")]
WITH_USD = "with a USD body"
BODY = {"requestBody": {"required": True, "content": {
    JSON: {"schema": ThumbnailRequest.model_json_schema()},
    "model/vnd.usda": {"schema": {"type": "string", "description": "a USD layer that refers to no other file; "
                                  "textures come from the texture roots; element, interface, size, mesh, env_method, cms, "
                                  "ocio_config and view come from the query"}},
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
    cms: Annotated[Cms | None, Query(description=f"{WITH_USD}; {CMS_DOC}")] = None,
    ocio_config: Annotated[str | None, Query(max_length=256, pattern=OCIO_CONFIG_PATTERN, description=WITH_USD)] = None,
    view: Annotated[str | None, Query(min_length=1, max_length=256, description=f"{WITH_USD}; {VIEW_DOC}")] = None,
) -> Response:
    media_type = media_type_of(request)
    body = await request.body()
    if media_type in USD_TYPES:
        params = GenerateParams(element=element, interface=interface, document_format=USD_TYPES[media_type],
                                cms=cms, ocio_config=ocio_config)
        order = ThumbnailOrder(body, params, size, mesh, env_method, view)
    elif media_type == JSON:
        try:
            req = ThumbnailRequest.model_validate_json(body)
        except ValidationError as exc:
            raise from_validation_error(exc) from None
        params = GenerateParams(element=req.element, interface=req.interface, cms=req.cms, ocio_config=req.ocio_config)
        order = ThumbnailOrder(req.document.encode(), params, req.size, req.mesh, req.env_method, req.view)
    else:
        raise ServiceError("unsupported_media_type", "send application/json, model/vnd.usda or model/vnd.usdz+zip, "
                           f"not {media_type}")
    if run_async:
        job_id = await thumbnails.submit(order)
        accepted = JobAccepted(id=job_id, state="queued", status_url=f"/v1/jobs/{job_id}")
        return JSONResponse(accepted.model_dump(), status_code=202)
    return Response(await thumbnails.thumbnail(order), media_type=PNG)


@router.post("/thumbnails/batch", status_code=202, response_model=JobAccepted, responses=ERRORS,
             summary="Render the thumbnails of many documents as one job")
async def thumbnail_batch(req: ThumbnailBatchRequest, batches: BatchesDep) -> JSONResponse:
    limit = get_settings().max_batch_documents
    if len(req.documents) > limit:
        raise ServiceError("too_large", f"{len(req.documents)} documents in the batch, over the limit of {limit} "
                           "(SHADERGEN_MAX_BATCH_DOCUMENTS)", "documents")
    orders = [ThumbnailOrder(d.document.encode(), GenerateParams(element=d.element, interface=req.interface, cms=req.cms,
                                                                ocio_config=req.ocio_config),
                             req.size, req.mesh, req.env_method, req.view) for d in req.documents]
    batch_id = await batches.submit(orders, [d.name for d in req.documents])
    accepted = JobAccepted(id=batch_id, state="running", status_url=f"{BATCH_PATH}/{batch_id}")
    return JSONResponse(accepted.model_dump(), status_code=202)


@router.get("/thumbnails/batch/{batch_id}", response_model=BatchStatus, responses=ERRORS,
            summary="Progress of a thumbnail batch, and one result per document")
async def thumbnail_batch_status(batches: BatchesDep, batch_id: BatchId) -> BatchStatus:
    state = await batches.status(batch_id)
    for result in state["results"]:
        if result["state"] == "done":
            result["thumbnail_url"] = f"{BATCH_PATH}/{batch_id}/{result['index']}"
    return BatchStatus.model_validate(state)


@router.get("/thumbnails/batch/{batch_id}/{index}", response_class=Response,
            responses={**ERRORS, 409: {"model": ErrorResponse}, 200: PNG_RESPONSE},
            summary="The PNG of one document of a thumbnail batch")
async def thumbnail_batch_png(batches: BatchesDep, batch_id: BatchId,
                              index: Annotated[int, Path(ge=0, description="the document's place in the batch")]
                              ) -> Response:
    return Response(await batches.png(batch_id, index), media_type=PNG)
