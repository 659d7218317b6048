"""Service settings, read from SHADERGEN_* environment variables when first asked for (never at
import time), so tests and `shadergen serve` can set the environment before the app starts."""
import os
from functools import lru_cache
from pathlib import Path

from typing import Literal

from pydantic import BaseModel, Field, model_validator

ENV_PREFIX = "SHADERGEN_"
LIST_SEPARATORS = {"texture_roots": os.pathsep, "include_roots": os.pathsep, "trusted_proxies": ","}  # as PATH, and as uvicorn's FORWARDED_ALLOW_IPS


# where a container's memory limit is read (cgroup v2, v1): the machine's memory is not the container's
CGROUP_MEMORY_LIMITS = ("/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes")


def _physical_mib() -> int:
    """The memory this process may use: the machine's, or its container's limit if smaller."""
    limit = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    for path in CGROUP_MEMORY_LIMITS:
        try:
            text = Path(path).read_text().strip()
        except OSError:
            continue
        if text.isdigit():  # "max" (v2) or a huge number (v1) when there is no limit
            limit = min(limit, int(text))
    return limit >> 20


def _default_generate_memory_mib() -> int:
    # an eighth of the machine each (`shadergen serve` starts 2 API workers with one generator
    # each, beside one render worker at a quarter): every child at its limit leaves half the memory
    return min(1024, _physical_mib() // 8)


def _default_render_memory_mib() -> int:
    # resident at the peak, on llvmpipe: a 1024 px thumbnail 310 MB; one whose texture is a 4096 px
    # PNG 1.4 GB (decoded to float32, with its mipmaps), so two such textures fit
    return min(3072, _physical_mib() // 4)


def _default_cache_url() -> str:
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return f"sqlite:///{base / 'shadergen' / 'service-cache.sqlite3'}"


class Settings(BaseModel):
    # cache: sqlite:///path (one machine, all processes) or redis://host:port/db (several machines)
    cache: str = Field(default_factory=_default_cache_url)
    cache_max_bytes: int = 512 * 1024 * 1024
    # job back end for thumbnails: empty = local render pool; redis://... = Celery
    broker: str = ""
    render_workers: int = 1
    # how the local pool hands render jobs to its workers: "topology" (each job to the worker that
    # holds its compiled program, by consistent hashing: service/workers/routing.py) or "shared"
    # (one queue, the first free worker: each worker compiles every topology it meets)
    render_routing: Literal["topology", "shared"] = "topology"
    render_queue_size: int = 16
    render_timeout_s: float = 60.0
    # set by `shadergen serve` so every API worker shares one local render pool
    render_socket: str = ""
    generate_processes: int = 1
    generate_queue_size: int = 64
    generate_timeout_s: float = 10.0
    # resident memory (MiB) one generator / render process may reach: past it the process is
    # killed, replaced, and its request answered 413 too_large; 0 = no limit
    generate_memory_mib: int = Field(default_factory=_default_generate_memory_mib, ge=0)
    render_memory_mib: int = Field(default_factory=_default_render_memory_mib, ge=0)
    memory_poll_s: float = Field(0.05, gt=0)
    # every child process sends a heartbeat this often; one not heard from for ready_deadline_s
    # is not answering: /readyz is 503 while no generator (or no render process) answers, and
    # requests are refused at once with 503 instead of waiting behind it
    heartbeat_s: float = Field(1.0, gt=0)
    ready_deadline_s: float = Field(10.0, gt=0)
    max_body_bytes: int = 2 * 1024 * 1024
    # a thumbnail batch (POST /v1/thumbnails/batch) is a library in one request: its own body limit,
    # and at most this many documents (413 too_large naming the limit beyond it)
    max_batch_body_bytes: int = 64 * 1024 * 1024
    max_batch_documents: int = 1000
    # a batch's thumbnails in flight at once (each one a generation and a render job)
    batch_concurrency: int = Field(4, ge=1)
    # a batch whose API worker has said nothing of it for this long is taken over by the next poll
    batch_lease_s: float = Field(15.0, gt=0)
    # a request's body must arrive within this, its line and headers within head_timeout_s and
    # head_max_bytes: a slow or endless upload cannot hold a worker's memory or a connection
    body_timeout_s: float = 30.0
    head_timeout_s: float = 10.0
    head_max_bytes: int = 32 * 1024
    # a client address may fail this many requests in a row, then this many a second (per API
    # worker), before its requests wait up to client_hold_s for a turn or get 429 (fairness.py);
    # a burst of 0 turns the ledger off
    client_failure_burst: int = 64
    client_failure_rate: float = 8.0
    client_hold_s: float = 1.0
    # Documents that differ only in values share one source (the `top:` store: an edit is answered
    # without emitting) and one compiled program per render worker. False: every new document is
    # emitted and every thumbnail compiles its program: the baseline bench/editing.py measures against.
    topology_sharing: bool = True
    # colon-separated directories that textures named by documents may come from
    texture_roots: list[str] = Field(default_factory=list)
    # colon-separated directories an uploaded document's xi:include may read .mtlx files from
    # (relative hrefs only, confined to the root: shadergen/document.py IncludeRoots); none: refused
    include_roots: list[str] = Field(default_factory=list)
    # the largest texture file GET /v1/textures sends (the image its header declares is bounded
    # as the renderer bounds it, SHADERGEN_MAX_IMAGE_VALUES)
    max_texture_bytes: int = Field(64 * 1024 * 1024, gt=0)
    # comma-separated addresses (or networks) of reverse proxies whose X-Forwarded-For names the
    # client; empty: no proxy is trusted and the client is the connection's peer (uvicorn alone
    # would trust 127.0.0.1, letting any local client choose the address its failures count against)
    trusted_proxies: list[str] = Field(default_factory=list)
    retry_after_s: int = 2

    @model_validator(mode="after")
    def _deadline_spans_heartbeats(self) -> "Settings":
        # a deadline within two heartbeats would call a healthy child silent between two of them
        if self.ready_deadline_s < 2 * self.heartbeat_s:
            raise ValueError(f"ready_deadline_s ({self.ready_deadline_s:g}) must be at least twice "
                             f"heartbeat_s ({self.heartbeat_s:g})")
        return self

    def child_limits(self, memory_mib: int):
        from .workers.pool import ChildLimits  # here: config is imported by everything, the pool by few

        return ChildLimits(memory_bytes=memory_mib << 20, silent_s=self.ready_deadline_s,
                           memory_poll_s=self.memory_poll_s)

    @classmethod
    def from_env(cls, environ: dict[str, str] | None = None) -> "Settings":
        environ = os.environ if environ is None else environ
        values: dict[str, object] = {}
        for name in cls.model_fields:
            raw = environ.get(ENV_PREFIX + name.upper())
            if raw is None:
                continue
            values[name] = [p for p in raw.split(LIST_SEPARATORS[name]) if p] if name in LIST_SEPARATORS else raw
        return cls.model_validate(values)

    def to_env(self) -> dict[str, str]:
        """The environment that reproduces these settings in a child process."""
        env = {}
        for name, value in self.model_dump().items():
            text = LIST_SEPARATORS[name].join(value) if isinstance(value, list) else str(value)
            env[ENV_PREFIX + name.upper()] = text
        return env


@lru_cache
def get_settings() -> Settings:
    return Settings.from_env()
