"""Thumbnails: a record from the generation service (and its cache), then a render job on the
configured back end. PNGs are cached too, under a digest of the graph hash and the render options
(and of the package, for a usdz upload, whose textures come from inside it)."""
import base64
import hashlib
import json
from dataclasses import dataclass, replace

from shadergen.cms import display_encoder
from shadergen.errors import ShaderGenError

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
    view: str | None = None  # with cms ocio: the config's view the PNG shows (None: its default)


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
        display = self._display(order, record)
        if display is not None:
            request["display"] = display
        if order.params.document_format == "usdz":
            # the record's textures are members of the package (the translation refuses any that
            # leave it): the job carries the package and reads them there, never in the roots
            request["package"] = base64.b64encode(order.document).decode()
        else:
            check_texture_paths(record, self.texture_roots)
        return request

    @staticmethod
    def _display(order: ThumbnailOrder, record: dict) -> dict | None:
        """How the PNG shows an OCIO record: its working space through the config's default display
        and the order's view (the config's default view unless named), as `shadergen render --cms
        ocio` does; None (sRGB of linear Rec.709) with the built-in system. Checked here, so that
        an unknown view is refused before any job is queued."""
        ocio = order.params.cms == "ocio" or (order.params.cms is None and order.params.ocio_config)
        if not ocio:
            if order.view is not None:
                raise ServiceError("invalid_option", "a view is a colour-managed viewer's: it needs cms ocio",
                                   "view")
            return None
        display = {"ocio_config": order.params.ocio_config, "working": record.get("working_colorspace"),
                   "view": order.view}
        try:
            display_encoder(display)
        except ShaderGenError as exc:
            raise ServiceError(exc.code, exc.message, exc.where) from None
        return display

    @staticmethod
    def _key(request: dict) -> str:
        # the display encoding is the PNG's and not the shader's: two documents may share a record
        # hash (no colour transforms) and differ in their working space
        options = (f'{request["record"]["hash"]}:{request["size"]}:{request["mesh"]}:{request["env_method"]}:'
                   f'{request.get("package", "")}')
        if "display" in request:
            options += ":" + json.dumps(request["display"], sort_keys=True)
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
