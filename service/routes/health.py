"""GET /healthz (liveness: cheap, answers while the process runs), GET /readyz (readiness: the
generator pool, the render pool and the cache each checked) and GET /metrics (Prometheus)."""
from fastapi import APIRouter, Response
from fastapi.responses import JSONResponse

from ..cache import CacheUnavailable
from ..deps import ServicesDep
from ..jobs import JobError
from ..metrics import CONTENT_TYPE, QUEUE_DEPTH, exposition
from ..models import ComponentReadiness, Health, Readiness

router = APIRouter(tags=["operations"])

READINESS_PROBE_KEY = "health:probe"


async def healthz(services: ServicesDep) -> Health:
    return Health(status="ok", library_hash=services.generation.library_hash,
                  cache=services.store.name, jobs=services.jobs.name)


# GET first: a request with another method is answered 405 with the first route's `Allow`, which
# must name the documented method. HEAD (as HTTP defines it for any GET) stays out of the schema.
router.get("/healthz", response_model=Health, summary="Liveness and configuration")(healthz)
router.head("/healthz", response_model=Health, include_in_schema=False)(healthz)


@router.get("/readyz", response_model=Readiness, responses={503: {"model": Readiness}},
            summary="Readiness: 503 while the generator pool, the render pool or the cache is down, "
                    "or no generator or render process answered its heartbeat within the deadline")
async def readyz(services: ServicesDep) -> JSONResponse:
    pool = services.generation.pool
    # a child that runs but sends no heartbeat (stopped, wedged) is as good as none
    generator = ComponentReadiness(ready=pool.alive == pool.size and pool.answering > 0,
                                   detail=f"{pool.alive}/{pool.size} generator processes, {pool.answering} answering "
                                          f"within {pool.limits.silent_s:g} s, {pool.depth} jobs queued")
    render_ready, render_detail = await services.jobs.health()
    try:
        await services.store.aread(READINESS_PROBE_KEY)
        cache = ComponentReadiness(ready=True, detail=f"{services.store.name} answers")
    except CacheUnavailable as exc:
        cache = ComponentReadiness(ready=False, detail=f"{services.store.name}: {exc}")
    render = ComponentReadiness(ready=render_ready, detail=render_detail)
    ready = generator.ready and render.ready and cache.ready
    body = Readiness(status="ready" if ready else "not_ready", generator=generator, render=render, cache=cache)
    return JSONResponse(body.model_dump(), status_code=200 if ready else 503)


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
