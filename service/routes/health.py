"""GET /healthz and GET /metrics (Prometheus text format)."""
from fastapi import APIRouter, Response

from ..deps import ServicesDep
from ..jobs import JobError
from ..metrics import CONTENT_TYPE, QUEUE_DEPTH, exposition
from ..models import Health

router = APIRouter(tags=["operations"])


@router.get("/healthz", response_model=Health, summary="Liveness and configuration")
async def healthz(services: ServicesDep) -> Health:
    return Health(status="ok", library_hash=services.generation.library_hash,
                  cache=type(services.store).__name__, jobs=services.jobs.name)


@router.get("/metrics", response_class=Response, summary="Prometheus metrics",
            responses={200: {"content": {CONTENT_TYPE: {"schema": {"type": "string"}}}}})
async def metrics(services: ServicesDep) -> Response:
    # queue depths are read when scraped: the queues live in other processes (or on Redis)
    try:
        QUEUE_DEPTH.labels("render").set(await services.jobs.depth())
    except JobError:
        pass  # the pool is restarting or Redis is away: the scrape still answers
    QUEUE_DEPTH.labels("generate").set(services.generation.pool.depth)
    return Response(exposition(), media_type=CONTENT_TYPE)
