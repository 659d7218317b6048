"""Every failure leaves the service as the contract's error object,
`{"document", "element", "target", "error": {"code", "message", "where"}}`, with a 4xx status for
anything the client sent. The mapping lives here, once."""
import logging

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from pydantic import ValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException

from .config import get_settings
from .workers.pool import JobTimeout, PoolError, QueueFull, WorkerCrashed

log = logging.getLogger(__name__)

# codes answered with another status than 422 ("the document or request is wrong")
STATUS_BY_CODE = {
    "invalid_document": 400,
    "unsafe_xml": 400,
    "include_refused": 400,
    "path_not_allowed": 403,
    "not_found": 404,
    "request_timeout": 408,
    "too_large": 413,
    "unsupported_media_type": 415,
    "too_many_failures": 429,
    "queue_full": 503,
    "unavailable": 503,
    # the server's own time limit (a generation or render job, an answer from the render pool):
    # not the client's fault, and worth trying again
    "timeout": 504,
    "internal_error": 500,
    "worker_crashed": 500,
}


# statuses that say "the server cannot now, try again": they always carry Retry-After
RETRY_STATUSES = frozenset((503, 504))


class ServiceError(Exception):
    """A failure with a contract error code; `status` defaults from the code."""

    def __init__(self, code: str, message: str, where: str | None = None, *, status: int | None = None,
                 element: str | None = None, target: str | None = None, headers: dict | None = None):
        super().__init__(message)
        self.code, self.message, self.where = code, message, where
        self.status = status or STATUS_BY_CODE.get(code, 422)
        if self.status in RETRY_STATUSES and "Retry-After" not in (headers or {}):
            headers = {**(headers or {}), "Retry-After": str(get_settings().retry_after_s)}
        self.element, self.target, self.headers = element, target, headers

    @classmethod
    def from_generator(cls, error: dict, *, element=None, target=None) -> "ServiceError":
        return cls(error.get("code", "internal_error"), error.get("message", ""), error.get("where"),
                   element=element, target=target)

    @classmethod
    def from_job(cls, exc, retry_after_s: int) -> "ServiceError":
        """A job back end's JobError: a full queue, an absent pool or a time-out is worth trying again."""
        retry = STATUS_BY_CODE.get(exc.code) in RETRY_STATUSES
        return cls(exc.code, exc.message, exc.where, headers={"Retry-After": str(retry_after_s)} if retry else None)


def error_body(code: str, message: str, where: str | None = None, element=None, target=None) -> dict:
    return {"document": None, "element": element, "target": target,
            "error": {"code": code, "message": message, "where": where}}


def error_response(exc: ServiceError) -> JSONResponse:
    if exc.status >= 500:
        log.error("%s: %s%s", exc.code, exc.message, f" (at {exc.where})" if exc.where else "")
    return JSONResponse(error_body(exc.code, exc.message, exc.where, exc.element, exc.target),
                        status_code=exc.status, headers=exc.headers)


def from_validation_error(exc: RequestValidationError | ValidationError) -> ServiceError:
    errors = exc.errors()
    first = errors[0] if errors else {}
    where = ".".join(str(p) for p in first.get("loc", ())) or None
    return ServiceError("invalid_request", first.get("msg", "invalid request"), where)


def from_pool_error(exc: PoolError) -> ServiceError:
    code = ("timeout" if isinstance(exc, JobTimeout) else "queue_full" if isinstance(exc, QueueFull)
            else "worker_crashed" if isinstance(exc, WorkerCrashed) else "unavailable")
    return ServiceError(code, str(exc))


def install_error_handlers(app: FastAPI) -> None:
    @app.exception_handler(ServiceError)
    async def service_error(_: Request, exc: ServiceError):
        return error_response(exc)

    @app.exception_handler(RequestValidationError)
    async def validation_error(_: Request, exc: RequestValidationError):
        return error_response(from_validation_error(exc))

    @app.exception_handler(PoolError)
    async def pool_error(_: Request, exc: PoolError):
        # a pool's failure that no service turned into its own error (the node definitions,
        # asked of a generator once): the server's trouble, never a 500 for a full or hung pool
        return error_response(from_pool_error(exc))

    @app.exception_handler(StarletteHTTPException)
    async def http_error(_: Request, exc: StarletteHTTPException):
        code = {404: "not_found", 405: "method_not_allowed"}.get(exc.status_code, "invalid_request")
        return error_response(ServiceError(code, str(exc.detail), status=exc.status_code, headers=exc.headers))
