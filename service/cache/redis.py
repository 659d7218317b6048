"""The cache for several machines: Redis. Its size bound and LRU eviction are Redis' own
(`maxmemory` with `maxmemory-policy allkeys-lru`, as docker/compose.yaml configures it)."""
import redis
import redis.asyncio

from .base import Store

PREFIX = "shadergen:cache:"
# a Redis that hangs must cost a request this much at most: then the request goes on uncached
TIMEOUTS = {"socket_timeout": 2.0, "socket_connect_timeout": 2.0}


class RedisStore(Store):
    def __init__(self, url: str):
        self.url = url
        self._sync = redis.Redis.from_url(url, **TIMEOUTS)
        self._async: redis.asyncio.Redis | None = None  # made in the event loop that uses it

    def get(self, key: str) -> bytes | None:
        return self._sync.get(PREFIX + key)

    async def aget(self, key: str) -> bytes | None:
        if self._async is None:
            self._async = redis.asyncio.Redis.from_url(self.url, **TIMEOUTS)
        return await self._async.get(PREFIX + key)

    def put(self, key: str, value: bytes) -> None:
        self._sync.set(PREFIX + key, value)

    def delete(self, key: str) -> None:
        self._sync.delete(PREFIX + key)

    def add(self, key: str, value: bytes) -> bool:
        return bool(self._sync.set(PREFIX + key, value, nx=True))

    def close(self) -> None:
        self._sync.close()

    async def aclose(self) -> None:
        if self._async is not None:
            await self._async.aclose()
            self._async = None
