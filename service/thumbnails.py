"""Thumbnails: a record from the generation service (and its cache), then a render job on the
configured back end. PNGs are cached too, under a digest of the graph hash and the render options."""
import asyncio
import hashlib
import json

from .cache import GuardedStore
from .cache.entries import is_png
from .errors import ServiceError
from .generation import GenerateParams, GenerationService
from .jobs import JobBackend, JobError
from .metrics import CACHE
from .models import ThumbnailRequest
from .safety import check_texture_paths


class ThumbnailService:
    def __init__(self, generation: GenerationService, jobs: JobBackend, store: GuardedStore,
                 texture_roots: list[str], retry_after_s: int = 2):
        self.generation, self.jobs, self.store = generation, jobs, store
        self.texture_roots = texture_roots
        self.retry_after_s = retry_after_s

    async def _render_request(self, req: ThumbnailRequest) -> dict:
        params = GenerateParams(target="glsl", element=req.element, interface=req.interface)
        record = json.loads(await self.generation.generate(req.document.encode(), params))
        check_texture_paths(record, self.texture_roots)
        return {"record": record, "size": req.size, "mesh": req.mesh}

    @staticmethod
    def _key(request: dict) -> str:
        options = f'{request["record"]["hash"]}:{request["size"]}:{request["mesh"]}'
        return "png:" + hashlib.sha256(options.encode()).hexdigest()

    async def thumbnail(self, req: ThumbnailRequest) -> bytes:
        request = await self._render_request(req)
        key = self._key(request)
        png = await self.store.aget(key)
        if not is_png(png):
            png = None
        CACHE.labels("thumbnail", "miss" if png is None else "hit").inc()
        if png is None:
            try:
                png = (await self.jobs.render(request)).png
            except JobError as exc:
                raise ServiceError.from_job(exc, self.retry_after_s) from None
            await asyncio.to_thread(self.store.put, key, png)
        return png

    async def submit(self, req: ThumbnailRequest) -> str:
        request = await self._render_request(req)
        try:
            return await self.jobs.submit(request)
        except JobError as exc:
            raise ServiceError.from_job(exc, self.retry_after_s) from None
