"""Thumbnail batches (POST /v1/thumbnails/batch): a library's documents in one request, one result
per document, PNG or error record, with progress while it runs.

The API worker that accepts a batch runs it: every document is a thumbnail order like
POST /v1/thumbnails's (generation through the cache, then a render job on the back end),
`batch_concurrency` of them at once. Its state lives in the shared store under `batch:<id>`,
rewritten as results arrive, so any API worker answers a poll; each PNG stays under its thumbnail
key (ThumbnailService). A document that fails is its own error record; the others go on.

An API worker may die mid-batch (uvicorn starts another in its place): the runner holds a lease
on the batch, renewed while it runs, and its orders are stored beside the state. A poll that finds
a running batch whose lease ran out claims it (one claim per lapsed lease, through the store's
atomic add, so one worker alone takes it over) and runs the documents that have no result yet;
those done keep theirs. A runner that finds its batch claimed by another stops.
"""
import asyncio
import dataclasses
import json
import time
import uuid

from .cache import CacheUnavailable, GuardedStore
from .errors import ServiceError
from .generation import GenerateParams
from .thumbnails import ThumbnailOrder, ThumbnailService

FINISHED = ("done", "failed")
# The state is written at most this often while documents finish, and when the last one does. A
# write is the whole state (a 500-document batch's is ~90 kB, read back first to check the lease),
# so writing it per document made a batch cost the square of its size. A runner that dies between
# writes leaves those documents to the one that takes over: their PNGs are stored, so they are
# cache hits there.
PROGRESS_INTERVAL_S = 0.25


class _Superseded(Exception):
    """Another API worker has taken the batch over."""


class BatchService:
    def __init__(self, thumbnails: ThumbnailService, store: GuardedStore, concurrency: int, retry_after_s: int = 2,
                 lease_s: float = 15.0):
        self.thumbnails, self.store = thumbnails, store
        self.concurrency = concurrency
        self.retry_after_s = retry_after_s
        self.lease_s = lease_s  # a runner silent this long is taken for dead
        self._running: set[asyncio.Task] = set()  # held: the loop keeps only weak references to tasks

    async def submit(self, orders: list[ThumbnailOrder], names: list[str | None]) -> str:
        batch_id = uuid.uuid4().hex
        state = {"id": batch_id, "state": "running", "total": len(orders), "done": 0, "failed": 0,
                 "lease": self._lease(),
                 "results": [{"index": i, "name": name, "element": None, "state": "queued"}
                             for i, name in enumerate(names)]}
        try:
            await self.store.aput(_orders_key(batch_id), _dumps([_order_json(o) for o in orders]))
            await self.store.aput(_key(batch_id), _dumps(state))
        except CacheUnavailable as exc:
            raise self._unavailable(exc) from None
        self._start(state, orders)
        return batch_id

    def _lease(self) -> dict:
        return {"owner": uuid.uuid4().hex, "until": time.time() + self.lease_s}

    def _start(self, state: dict, orders: list[ThumbnailOrder]) -> None:
        task = asyncio.create_task(self._run(state, orders))
        self._running.add(task)
        task.add_done_callback(self._running.discard)

    async def _run(self, state: dict, orders: list[ThumbnailOrder]) -> None:
        turns = asyncio.Semaphore(self.concurrency)
        saving = asyncio.Lock()  # one writer at a time: a later state is never overwritten by an earlier one

        saved = time.monotonic()

        async def save() -> None:
            nonlocal saved
            async with saving:
                saved = time.monotonic()
                await self._save(state)

        async def renew() -> None:  # the lease outlives a document that takes longer than it
            while True:
                await asyncio.sleep(self.lease_s / 3)
                await save()

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
                await save()
            elif time.monotonic() - saved >= PROGRESS_INTERVAL_S:
                await save()

        renewing = asyncio.create_task(renew())
        try:
            async with asyncio.TaskGroup() as group:  # superseded, the rest of the documents are cancelled
                for index, order in enumerate(orders):
                    if state["results"][index]["state"] not in FINISHED:
                        group.create_task(one(index, order))
        except* _Superseded:
            pass
        finally:
            renewing.cancel()

    async def _save(self, state: dict) -> None:
        """Writes the state with its lease renewed, unless another worker has claimed the batch."""
        stored = await self.store.aget(_key(state["id"]))
        if stored is not None and json.loads(stored)["lease"]["owner"] != state["lease"]["owner"]:
            raise _Superseded
        state["lease"]["until"] = time.time() + self.lease_s
        await self.store.aput(_key(state["id"]), _dumps(state))

    async def status(self, batch_id: str) -> dict:
        try:
            raw = await self.store.aread(_key(batch_id))
        except CacheUnavailable as exc:
            raise self._unavailable(exc) from None
        if raw is None:
            raise ServiceError("not_found", f"no batch {batch_id} (batches are kept while the cache keeps them)")
        state = json.loads(raw)
        if state["state"] == "running" and state["lease"]["until"] < time.time():
            await self._take_over(state)
        return state

    async def _take_over(self, state: dict) -> None:
        """Runs a batch whose runner's lease lapsed (its API worker died) from where it stopped."""
        lapsed = state["lease"]
        if not await self.store.aadd(f"{_key(state['id'])}:claim:{lapsed['owner']}", b"1"):
            return  # another worker's poll claimed it first
        raw = await self.store.aget(_orders_key(state["id"]))
        state["lease"] = self._lease()
        if raw is None:  # evicted with the cache's oldest entries: what was not done cannot be redone
            for result in state["results"]:
                if result["state"] not in FINISHED:
                    result.update(state="failed", error={"code": "unavailable", "message": "the batch's API worker "
                                                         "stopped and its documents are no longer in the cache; "
                                                         "submit them again", "where": None})
                    state["failed"] += 1
                    state["done"] += 1
            state["state"] = "done"
            await self.store.aput(_key(state["id"]), _dumps(state))
            return
        await self.store.aput(_key(state["id"]), _dumps(state))
        self._start(state, [_order_from_json(o) for o in json.loads(raw)])

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


def _orders_key(batch_id: str) -> str:
    return f"batch:{batch_id}:orders"


def _order_json(order: ThumbnailOrder) -> dict:
    # a batch's documents are MaterialX text (models.BatchDocument)
    return dict(dataclasses.asdict(order), document=order.document.decode(), params=dataclasses.asdict(order.params))


def _order_from_json(data: dict) -> ThumbnailOrder:
    params = dict(data["params"], keep=tuple(data["params"]["keep"]))
    return ThumbnailOrder(**dict(data, document=data["document"].encode(), params=GenerateParams(**params)))


def _dumps(state: dict) -> bytes:
    return json.dumps(state, separators=(",", ":")).encode()
