"""What every cache back end offers. Keys are namespaced by the caller (`rec:<graph hash>`,
`req:<request digest>`, `png:<digest>`); values are bytes."""
import asyncio
import json
from abc import ABC, abstractmethod


class Store(ABC):
    @abstractmethod
    def get(self, key: str) -> bytes | None: ...

    @abstractmethod
    def put(self, key: str, value: bytes) -> None: ...

    @abstractmethod
    def delete(self, key: str) -> None: ...

    @abstractmethod
    def add(self, key: str, value: bytes) -> bool:
        """Write the value only if the key holds none; whether it was written. Of several
        processes adding one key, exactly one is told True: a claim."""

    async def aadd(self, key: str, value: bytes) -> bool:
        return await asyncio.to_thread(self.add, key, value)

    async def aget(self, key: str) -> bytes | None:
        """Read from the event loop. Back ends whose reads can wait (disk, network) override this."""
        return self.get(key)

    async def aput(self, key: str, value: bytes) -> None:
        """Write from the event loop: in a thread, since a write may wait for a lock or the network."""
        await asyncio.to_thread(self.put, key, value)

    def get_json(self, key: str):
        raw = self.get(key)
        return None if raw is None else json.loads(raw)

    def put_json(self, key: str, value) -> None:
        self.put(key, json.dumps(value, separators=(",", ":")).encode())

    def close(self) -> None:
        pass
