"""A cache that fails is a cache that missed. Every back-end error (a truncated SQLite file, a
Redis that went away, a value that is not what it claims to be) is counted, logged at most once
per interval, and turned into a miss (reads) or a skipped write, so a request is answered fresh
instead of failing. The back end heals itself: SQLite reopens or rebuilds its file, the Redis
client reconnects. Callers that must tell "absent" from "unknown" (GET /v1/shaders) use `aread`."""
import logging
import time

from ..metrics import CACHE_ERRORS
from .base import Store

log = logging.getLogger(__name__)

LOG_INTERVAL_S = 10.0  # one warning per interval: a dead cache must not flood the log on every request


class CacheUnavailable(Exception):
    pass


class GuardedStore(Store):
    def __init__(self, inner: Store):
        self.inner = inner
        self.name = type(inner).__name__
        self.last_error: str | None = None
        self._logged_at = 0.0

    def _failed(self, op: str, exc: Exception) -> None:
        CACHE_ERRORS.labels(op).inc()
        self.last_error = f"{type(exc).__name__}: {exc}"
        now = time.monotonic()
        if now - self._logged_at >= LOG_INTERVAL_S:
            self._logged_at = now
            log.warning("cache %s failed, answering without the cache: %s", op, self.last_error)

    def get(self, key: str) -> bytes | None:
        try:
            return self.inner.get(key)
        except Exception as exc:
            self._failed("get", exc)
            return None

    async def aread(self, key: str) -> bytes | None:
        """Like aget, but an error is CacheUnavailable rather than a miss."""
        try:
            value = await self.inner.aget(key)
        except Exception as exc:
            self._failed("get", exc)
            raise CacheUnavailable(self.last_error) from None
        self.last_error = None
        return value

    async def aget(self, key: str) -> bytes | None:
        try:
            return await self.aread(key)
        except CacheUnavailable:
            return None

    def put(self, key: str, value: bytes) -> None:
        try:
            self.inner.put(key, value)
        except Exception as exc:
            self._failed("put", exc)

    async def aput(self, key: str, value: bytes) -> None:
        try:
            await self.inner.aput(key, value)
        except Exception as exc:
            self._failed("put", exc)

    def add(self, key: str, value: bytes) -> bool:
        """A claim that cannot be written is not held."""
        try:
            return self.inner.add(key, value)
        except Exception as exc:
            self._failed("put", exc)
            return False

    async def aadd(self, key: str, value: bytes) -> bool:
        try:
            return await self.inner.aadd(key, value)
        except Exception as exc:
            self._failed("put", exc)
            return False

    def delete(self, key: str) -> None:
        try:
            self.inner.delete(key)
        except Exception as exc:
            self._failed("delete", exc)

    def close(self) -> None:
        try:
            self.inner.close()
        except Exception as exc:
            self._failed("close", exc)

    async def aclose(self) -> None:
        close = getattr(self.inner, "aclose", None)
        if close is not None:
            await close()
