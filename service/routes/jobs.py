"""GET /v1/jobs/{id} (state of an async thumbnail) and /v1/jobs/{id}/thumbnail (its PNG)."""
from typing import Annotated

from fastapi import APIRouter, Path, Response

from ..config import get_settings
from ..deps import JobsDep
from ..errors import ServiceError
from ..jobs import JobBackend, JobError, JobState
from ..models import ErrorDetail, ErrorResponse, JobStatus
from .common import ERRORS, PNG, PNG_RESPONSE

router = APIRouter(prefix="/v1/jobs", tags=["jobs"])

JobId = Annotated[str, Path(pattern="^[0-9a-f]{32}$")]


async def _job(jobs: JobBackend, job_id: str) -> JobState:
    try:
        state = await jobs.status(job_id)
    except JobError as exc:  # the pool is restarting, or Redis is away
        raise ServiceError.from_job(exc, get_settings().retry_after_s) from None
    if state is None:
        raise ServiceError("not_found", f"no job {job_id} (jobs are kept for a limited time)")
    return state


@router.get("/{job_id}", response_model=JobStatus, responses=ERRORS, summary="State of a thumbnail job")
async def get_job(jobs: JobsDep, job_id: JobId) -> JobStatus:
    state = await _job(jobs, job_id)
    return JobStatus(
        id=state.id, state=state.state,
        error=ErrorDetail(**state.error) if state.error else None, attempts=state.attempts,
        thumbnail_url=f"/v1/jobs/{job_id}/thumbnail" if state.state == "done" else None,
        timings_ms=state.result.timings_ms if state.result else {},
    )


@router.get("/{job_id}/thumbnail", response_class=Response,
            responses={**ERRORS, 409: {"model": ErrorResponse}, 200: PNG_RESPONSE},
            summary="The PNG of a finished thumbnail job")
async def get_job_thumbnail(jobs: JobsDep, job_id: JobId) -> Response:
    state = await _job(jobs, job_id)
    if state.state == "failed":
        raise ServiceError(**state.error)
    if state.state != "done":
        raise ServiceError("not_ready", f"job {job_id} is {state.state}", status=409)
    return Response(state.result.png, media_type=PNG)
