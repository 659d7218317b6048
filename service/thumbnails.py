"""Thumbnails: a record from the generation service (and its cache), then a render job on the
configured back end. PNGs are cached too, under a digest of the graph hash and the render options
(and of the package, for a usdz upload, whose textures come from inside it)."""
import base64
import hashlib
import json
from dataclasses import dataclass, replace

from .cache import GuardedStore
from .cache.entries import is_png
from .errors import ServiceError
from .generation import GenerateParams, GenerationService
from .jobs import JobBackend, JobError
from .metrics import CACHE
from .safety import check_texture_paths


@dataclass(frozen=True)
class ThumbnailOrder:
    """What to render: the document as uploaded, how to generate it, and the render options."""
    document: bytes
    params: GenerateParams
    size: int = 256
    mesh: str = "sphere"
    env_method: str = "fis"


class ThumbnailService:
    def __init__(self, generation: GenerationService, jobs: JobBackend, store: GuardedStore,
                 texture_roots: list[str], retry_after_s: int = 2):
        self.generation, self.jobs, self.store = generation, jobs, store
        self.texture_roots = texture_roots
        self.retry_after_s = retry_after_s

    async def _render_request(self, order: ThumbnailOrder) -> dict:
        # the shader holds only the lighting it is drawn with: this environment method, no light rig
        params = replace(order.params, environment=order.env_method, lights=False)
        record = json.loads(await self.generation.generate(order.document, params))
        request = {"record": record, "size": order.size, "mesh": order.mesh, "env_method": order.env_method}
        if order.params.document_format == "usdz":
            # the record's textures are members of the package (the translation refuses any that
            # leave it): the job carries the package and reads them there, never in the roots
            request["package"] = base64.b64encode(order.document).decode()
        else:
            check_texture_paths(record, self.texture_roots)
        return request

    @staticmethod
    def _key(request: dict) -> str:
        options = (f'{request["record"]["hash"]}:{request["size"]}:{request["mesh"]}:{request["env_method"]}:'
                   f'{request.get("package", "")}')
        return "png:" + hashlib.sha256(options.encode()).hexdigest()

    async def thumbnail(self, order: ThumbnailOrder) -> bytes:
        return (await self.stored(order))[2]

    async def stored(self, order: ThumbnailOrder) -> tuple[str, str, bytes]:
        """(the element drawn, the PNG's key in the store, the PNG), rendered unless the store has it."""
        request = await self._render_request(order)
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
            await self.store.aput(key, png)
        return request["record"]["element"], key, png

    async def submit(self, order: ThumbnailOrder) -> str:
        request = await self._render_request(order)
        try:
            return await self.jobs.submit(request)
        except JobError as exc:
            raise ServiceError.from_job(exc, self.retry_after_s) from None
