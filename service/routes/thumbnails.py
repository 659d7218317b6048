"""POST /v1/thumbnails: a PNG now, or with `?async=true` a job to poll at /v1/jobs/{id}."""
from typing import Annotated

from fastapi import APIRouter, Query, Response
from fastapi.responses import JSONResponse

from ..deps import ThumbnailsDep
from ..models import JobAccepted, ThumbnailRequest
from .common import ERRORS, PNG, PNG_RESPONSE

router = APIRouter(prefix="/v1", tags=["thumbnails"])

RunAsync = Annotated[bool, Query(alias="async", description="queue a job instead of waiting")]


@router.post("/thumbnails", responses={**ERRORS, 200: PNG_RESPONSE, 202: {"model": JobAccepted}},
             response_class=Response, summary="Render a material thumbnail")
async def thumbnail(req: ThumbnailRequest, thumbnails: ThumbnailsDep, run_async: RunAsync = False) -> Response:
    if run_async:
        job_id = await thumbnails.submit(req)
        accepted = JobAccepted(id=job_id, state="queued", status_url=f"/v1/jobs/{job_id}")
        return JSONResponse(accepted.model_dump(), status_code=202)
    return Response(await thumbnails.thumbnail(req), media_type=PNG)
