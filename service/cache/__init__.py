"""The shared cache: bytes under string keys, one store for every process of the service.

Values are JSON or raw bytes (PNG), never pickles, so a shared store cannot become a way to run
code in another process. `open_store(url)` picks the back end from the configured URL."""
from .base import Store
from .guard import CacheUnavailable, GuardedStore
from .sqlite import SQLiteStore


def open_store(url: str, max_bytes: int) -> GuardedStore:
    """The configured back end, guarded: its failures are misses, never errors of a request."""
    if url.startswith(("redis://", "rediss://", "unix://")):
        from .redis import RedisStore  # only needed when configured

        return GuardedStore(RedisStore(url))
    path = url.removeprefix("sqlite:///") if url.startswith("sqlite:///") else url
    return GuardedStore(SQLiteStore(path, max_bytes=max_bytes))


__all__ = ["CacheUnavailable", "GuardedStore", "Store", "SQLiteStore", "open_store"]
