"""One job interface for thumbnails, two back ends: the local render pool (default: processes on
this machine, nothing else to start) and Celery on Redis (`SHADERGEN_BROKER=redis://...`, workers
on any machine started with `shadergen worker`). A job is a render request,
`{"record": <shader record>, "size": int, "mesh": str, "env_method": str}`; its result a PNG."""
from abc import ABC, abstractmethod
from dataclasses import dataclass, field


@dataclass
class RenderResult:
    png: bytes
    timings_ms: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    program_reused: bool | None = None  # the worker drew it with a program it had compiled before (None: not said)


@dataclass
class JobState:
    id: str
    state: str  # queued, running, done, failed
    error: dict | None = None
    result: RenderResult | None = None
    attempts: int = 0  # 2 once a worker died on the job and it was tried again


class JobError(Exception):
    """A job that failed: `code` is a contract error code (timeout, render_failed,
    worker_crashed, queue_full, unavailable, ...)."""

    def __init__(self, code: str, message: str, where: str | None = None):
        super().__init__(message)
        self.code, self.message, self.where = code, message, where


class JobBackend(ABC):
    name: str

    @abstractmethod
    async def render(self, request: dict) -> RenderResult:
        """Render and wait; raises JobError."""

    @abstractmethod
    async def submit(self, request: dict) -> str:
        """Queue a render and return its job id at once; raises JobError (queue_full)."""

    @abstractmethod
    async def status(self, job_id: str) -> JobState | None:
        """None for a job this back end does not know (never existed, or expired)."""

    @abstractmethod
    async def depth(self) -> int:
        """Jobs waiting for a worker."""

    @abstractmethod
    async def health(self) -> tuple[bool, str]:
        """(ready, detail) for the readiness check: the back end answers, and some render
        process answered its heartbeat within the deadline."""

    async def close(self) -> None:
        pass


async def open_jobs(settings) -> JobBackend:
    if settings.broker:
        from .celery_backend import CeleryJobs

        return CeleryJobs(settings)
    from .local import LocalJobs

    return await LocalJobs.connect(settings)
