"""Thumbnail batches (POST /v1/thumbnails/batch): a library's documents in one request, one result
per document, PNG or error record, with progress while it runs.

The API worker that accepts a batch runs it: every document is a thumbnail order like
POST /v1/thumbnails's (generation through the cache, then a render job on the back end),
`batch_concurrency` of them at once. Its state lives in the shared store under `batch:<id>`,
rewritten as results arrive, so any API worker answers a poll; each PNG stays under its thumbnail
key (ThumbnailService). A document that fails is its own error record; the others go on.
"""
import asyncio
import json
import uuid

from .cache import CacheUnavailable, GuardedStore
from .errors import ServiceError
from .thumbnails import ThumbnailOrder, ThumbnailService


class BatchService:
    def __init__(self, thumbnails: ThumbnailService, store: GuardedStore, concurrency: int, retry_after_s: int = 2):
        self.thumbnails, self.store = thumbnails, store
        self.concurrency = concurrency
        self.retry_after_s = retry_after_s
        self._running: set[asyncio.Task] = set()  # held: the loop keeps only weak references to tasks

    async def submit(self, orders: list[ThumbnailOrder], names: list[str | None]) -> str:
        batch_id = uuid.uuid4().hex
        state = {"id": batch_id, "state": "running", "total": len(orders), "done": 0, "failed": 0,
                 "results": [{"index": i, "name": name, "element": None, "state": "queued"}
                             for i, name in enumerate(names)]}
        try:
            await self.store.aput(_key(batch_id), _dumps(state))
        except CacheUnavailable as exc:
            raise self._unavailable(exc) from None
        task = asyncio.create_task(self._run(state, orders))
        self._running.add(task)
        task.add_done_callback(self._running.discard)
        return batch_id

    async def _run(self, state: dict, orders: list[ThumbnailOrder]) -> None:
        turns = asyncio.Semaphore(self.concurrency)
        saving = asyncio.Lock()  # one writer at a time: a later state is never overwritten by an earlier one

        async def one(index: int, order: ThumbnailOrder) -> None:
            result = state["results"][index]
            async with turns:
                try:
                    result["element"], result["png_key"], _ = await self.thumbnails.stored(order)
                    result["state"] = "done"
                except ServiceError as exc:
                    _failed(result, order, exc.code, exc.message, exc.where)
                    state["failed"] += 1
                except Exception as exc:  # a bug answered for this document alone: the batch still finishes
                    _failed(result, order, "internal_error", f"{type(exc).__name__}: {exc}", None)
                    state["failed"] += 1
            state["done"] += 1
            if state["done"] == state["total"]:
                state["state"] = "done"
            async with saving:
                await self.store.aput(_key(state["id"]), _dumps(state))

        await asyncio.gather(*(one(i, order) for i, order in enumerate(orders)))

    async def status(self, batch_id: str) -> dict:
        try:
            raw = await self.store.aread(_key(batch_id))
        except CacheUnavailable as exc:
            raise self._unavailable(exc) from None
        if raw is None:
            raise ServiceError("not_found", f"no batch {batch_id} (batches are kept while the cache keeps them)")
        return json.loads(raw)

    async def png(self, batch_id: str, index: int) -> bytes:
        state = await self.status(batch_id)
        if not 0 <= index < state["total"]:
            raise ServiceError("not_found", f"batch {batch_id} has no document {index} (it has {state['total']})")
        result = state["results"][index]
        if result["state"] == "failed":
            raise ServiceError(**result["error"], element=result["element"])
        if result["state"] != "done":
            raise ServiceError("not_ready", f"document {index} of batch {batch_id} is {result['state']}", status=409)
        png = await self.store.aget(result["png_key"])
        if png is None:
            raise ServiceError("not_found", f"the thumbnail of document {index} is no longer in the cache; "
                               "submit the batch again")
        return png

    def _unavailable(self, exc: Exception) -> ServiceError:
        return ServiceError("unavailable", f"the cache is not reachable: {exc}",
                            headers={"Retry-After": str(self.retry_after_s)})


def _failed(result: dict, order: ThumbnailOrder, code: str, message: str, where: str | None) -> None:
    result.update(state="failed", element=order.params.element, error={"code": code, "message": message, "where": where})


def _key(batch_id: str) -> str:
    return "batch:" + batch_id


def _dumps(state: dict) -> bytes:
    return json.dumps(state, separators=(",", ":")).encode()
