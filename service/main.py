"""The FastAPI app. `create_app` is the factory uvicorn calls in every worker process
(`uvicorn --factory service.main:create_app`); each worker builds its services in the lifespan."""
from contextlib import asynccontextmanager

from fastapi import FastAPI

import shadergen

from .config import get_settings
from .errors import install_error_handlers
from .fairness import RATIONED_PREFIX, FailureLedger, FairnessMiddleware
from .fastpath import GenerateFastPath
from .limits import BodyLimitMiddleware
from .metrics import MetricsMiddleware
from .models import ErrorResponse
from .routes import routers
from .routes.editor import editor_files
from .routes.images import DECODE_PATH
from .routes.thumbnails import BATCH_PATH
from .services import Services


@asynccontextmanager
async def lifespan(app: FastAPI):
    app.state.services = await Services.start(get_settings())
    try:
        yield
    finally:
        await app.state.services.stop()


def create_app() -> FastAPI:
    # Prometheus (/metrics) is the telemetry here; FastAPI's own OpenTelemetry layer stays off
    app = FastAPI(title="ShaderX service", version=shadergen.__version__, lifespan=lifespan,
                  telemetry={"tracing": False, "metrics": False, "logs": False},
                  description="MaterialX documents to shader source, variable listings and thumbnails.")
    install_error_handlers(app)
    # the last added runs first: metrics see everything, a client out of turns is held before its
    # body is read, the body limit applies to the fast path
    app.add_middleware(GenerateFastPath)
    settings = get_settings()
    app.add_middleware(BodyLimitMiddleware, max_bytes=settings.max_body_bytes, read_timeout_s=settings.body_timeout_s,
                       path_limits={BATCH_PATH: settings.max_batch_body_bytes,
                                    DECODE_PATH: settings.max_texture_bytes})
    if settings.client_failure_burst > 0:
        app.add_middleware(FairnessMiddleware, hold_s=settings.client_hold_s,
                           ledger=FailureLedger(settings.client_failure_burst, settings.client_failure_rate))
    app.add_middleware(MetricsMiddleware)
    rationed = {429: {"model": ErrorResponse, "description": "too many of this client's requests failed recently: "
                      "retry after the seconds in Retry-After"}}
    for router in routers:
        app.include_router(router, responses=rationed if f"{router.prefix}/".startswith(RATIONED_PREFIX) else None)
    app.mount("/editor", editor_files(), name="editor")
    return app
