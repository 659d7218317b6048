"""The shared cache: bytes under string keys, one store for every process of the service.

Values are JSON or raw bytes (PNG), never pickles, so a shared store cannot become a way to run
code in another process. `open_store(url)` picks the back end from the configured URL."""
from .base import Store
from .sqlite import SQLiteStore


def open_store(url: str, max_bytes: int) -> Store:
    if url.startswith(("redis://", "rediss://", "unix://")):
        from .redis import RedisStore  # only needed when configured

        return RedisStore(url)
    path = url.removeprefix("sqlite:///") if url.startswith("sqlite:///") else url
    return SQLiteStore(path, max_bytes=max_bytes)


__all__ = ["Store", "SQLiteStore", "open_store"]
