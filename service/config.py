"""Service settings, read from SHADERGEN_* environment variables when first asked for (never at
import time), so tests and `shadergen serve` can set the environment before the app starts."""
import os
from functools import lru_cache
from pathlib import Path

from pydantic import BaseModel, Field

ENV_PREFIX = "SHADERGEN_"


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
    render_queue_size: int = 16
    render_timeout_s: float = 60.0
    # set by `shadergen serve` so every API worker shares one local render pool
    render_socket: str = ""
    generate_processes: int = 1
    generate_queue_size: int = 64
    generate_timeout_s: float = 10.0
    max_body_bytes: int = 2 * 1024 * 1024
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
    retry_after_s: int = 2

    @classmethod
    def from_env(cls, environ: dict[str, str] | None = None) -> "Settings":
        environ = os.environ if environ is None else environ
        values: dict[str, object] = {}
        for name in cls.model_fields:
            raw = environ.get(ENV_PREFIX + name.upper())
            if raw is None:
                continue
            values[name] = [p for p in raw.split(os.pathsep) if p] if name == "texture_roots" else raw
        return cls.model_validate(values)

    def to_env(self) -> dict[str, str]:
        """The environment that reproduces these settings in a child process."""
        env = {}
        for name, value in self.model_dump().items():
            env[ENV_PREFIX + name.upper()] = os.pathsep.join(value) if isinstance(value, list) else str(value)
        return env


@lru_cache
def get_settings() -> Settings:
    return Settings.from_env()
