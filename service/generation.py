"""Generation behind the cache: plain functions over a Store and a generation ProcessPool.

Two cache levels, both in the shared store:
- `rec:<graph hash>`: the record. The graph hash (from the generator's `prepare`) ignores XML
  formatting, element order and unused nodes, so equivalent documents share one entry.
- `req:<request digest>`: the graph hash a byte-identical request resolved to. Digest of the
  document bytes, the parameters and the generator's output key (shadergen/fingerprint.py: the
  library files, their folder and the generator's code, as the generator process reports it); a
  repeated request is answered from the store without even parsing the XML, which is what keeps
  cached requests in the millisecond range. Only a request whose answer has no warnings gets one:
  a record is stored once per graph, with the warnings of the document that stored it, which are
  no other document's (the generator gives each request its own: gen_worker.py).
"""
import hashlib
import json
import os
from dataclasses import dataclass

from shadergen.cms import OCIO_CONFIG_ENV

from .cache import CacheUnavailable, GuardedStore
from .cache.entries import has_no_warnings, is_graph_hash, is_record, refusal
from .errors import ServiceError
from .metrics import CACHE, GENERATE_SECONDS
from .safety import check_document
from .workers.pool import JobTimeout, PoolError, ProcessPool, QueueFull, WorkerCrashed

INCLUDE = b"include"  # an xi:include element, however its namespace prefix is spelled
RECORD_HITS = CACHE.labels("record", "hit")  # resolved once: this is on every cached request


@dataclass(frozen=True)
class GenerateParams:
    target: str = "glsl"
    element: str | None = None
    interface: str = "complete"
    source: bool = True
    document_format: str = "mtlx"  # or a USD upload: usda (text) or usdz (a package)
    keep: tuple[str, ...] = ()  # inputs left live by `specialized`
    values: str = "listing"  # or "source": the document's values written into the initializers
    environment: str | None = None  # the environment lighting only (fis | prefilter | hybrid), for a thumbnail
    lights: bool = True  # False for a thumbnail, which draws no light rig: no light loop is written
    names: str = "structural"  # or "document": the document's element names in the source (shadergen/naming.py)
    cms: str | None = None  # colour management: builtin | ocio (shadergen/cms/)
    ocio_config: str | None = None  # an ocio:// built-in config; None: the server's SHADERGEN_OCIO_CONFIG


def request_digest(output_key: str, params: GenerateParams, document: bytes) -> str:
    """`output_key`: fingerprint.output_key of the generator that answers (its `library_hash`)."""
    h = hashlib.sha256()
    for part in (output_key, params.target, params.element or "", params.interface, params.document_format,
                 params.values, params.environment or "", "lights" if params.lights else "unlit", params.names,
                 params.cms or "", config_identity(params), *sorted(set(params.keep))):
        h.update(part.encode() + b"\0")
    h.update(document)
    return h.hexdigest()


def config_identity(params: GenerateParams) -> str:
    """What names the OCIO config a request is generated with, for its digest: the built-in
    config's name, or the server's config file by its path and version (a file edited in place is
    another config: the digest must not answer with the record of its old content)."""
    spec = params.ocio_config or (os.environ.get(OCIO_CONFIG_ENV, "") if params.cms == "ocio" else "")
    if not spec or spec.startswith("ocio://"):
        return spec
    try:
        st = os.stat(spec)
    except OSError:
        return spec  # the generator refuses it
    return f"{os.path.realpath(spec)} {st.st_mtime_ns} {st.st_size}"


def check_config(params: GenerateParams) -> None:
    """A request may name OCIO's built-in configs only: never a file of the server's."""
    if params.ocio_config and not params.ocio_config.startswith("ocio://"):
        raise ServiceError("invalid_request", "ocio_config must be one of OCIO's built-in configs (ocio://NAME); "
                           "the server's own config is used when it is absent", where="ocio_config")


def checked(raw_document: bytes, params: GenerateParams) -> bytes:
    """The document as the generator takes it: XML passes the upload checks first (bytes: the
    generator reads a str as a path); a USD upload is checked by the generator's USD reader."""
    return check_document(raw_document).encode() if params.document_format == "mtlx" else raw_document


def without_source(record_json: bytes) -> bytes:
    """The listing-only form of a record (`"source": false`), as the generator writes it."""
    record = json.loads(record_json)
    record["stages"] = {name: None for name in record.get("stages", {})}
    return json.dumps(record, separators=(",", ":")).encode()


class GenerationService:
    def __init__(self, pool: ProcessPool, store: GuardedStore, retry_after_s: int = 2, include_roots=()):
        self.pool = pool
        self.store = store
        self.include_roots = list(include_roots)
        self.retry_after_s = retry_after_s
        self._nodedefs: bytes | None = None

    @property
    def library_hash(self) -> str:
        return self.pool.hello["library_hash"]

    async def generate(self, raw_document: bytes, params: GenerateParams) -> bytes:
        """The record as JSON bytes; raises ServiceError (a 4xx for anything the client sent)."""
        check_config(params)
        document = checked(raw_document, params)
        # a document that includes files from the include roots is not answered by the digest of
        # its bytes, which does not cover what it includes: it is generated every time (its
        # record is still shared by its graph hash)
        digest = None if self.include_roots and INCLUDE in document else \
            request_digest(self.library_hash, params, document)
        record = await self._cached(digest) if digest else None
        if record is None:
            if digest:
                await self._refused_before(digest, params)
            record = await self._generate(document, params, digest)
        return record if params.source else without_source(record)

    async def _cached(self, digest: str) -> bytes | None:
        """A sound record for the request, else None: a failed lookup or a value that is not
        what its key promises is a miss, which the generator answers and overwrites."""
        graph_hash = await self.store.aget("req:" + digest)
        if not is_graph_hash(graph_hash):
            return None
        record = await self.store.aget("rec:" + graph_hash.decode())
        # (a `req:` entry is written for answers without warnings; a record with some is another
        # document's of the same graph, stored after this one's was evicted)
        if not is_record(record, graph_hash.decode()) or not has_no_warnings(record):
            return None
        RECORD_HITS.inc()
        return record

    async def _refused_before(self, digest: str, params: GenerateParams) -> None:
        """Raise the generator's refusal of a byte-identical request, if it refused one before:
        a client that repeats an expensive bad document costs a lookup, not a generation."""
        error = refusal(await self.store.aget("err:" + digest))
        if error is not None:
            CACHE.labels("refusal", "hit").inc()
            raise ServiceError.from_generator(error, element=params.element, target=params.target)

    async def _generate(self, document: bytes, params: GenerateParams, digest: str | None) -> bytes:
        # the document travels as the frame's payload: bytes as they are (binary for usdz), and no
        # JSON escaping of a large XML text on either side
        request = {"op": "generate", "format": params.document_format, "target": params.target,
                   "element": params.element, "interface": params.interface, "keep": list(params.keep),
                   "values": params.values, "environment": params.environment, "lights": params.lights,
                   "names": params.names, "cms": params.cms, "ocio_config": params.ocio_config,
                   "digest": digest}
        context = {"element": params.element, "target": params.target}
        try:
            reply, record = await self.pool.run(request, document)
        except QueueFull as exc:
            raise ServiceError("queue_full", f"generation queue full: {exc}", **context,
                               headers={"Retry-After": str(self.retry_after_s)}) from None
        except JobTimeout as exc:
            raise ServiceError("timeout", f"generation stopped: {exc}", **context) from None
        except WorkerCrashed as exc:
            raise ServiceError("worker_crashed", f"generation failed: {exc}", **context) from None
        except PoolError as exc:
            raise ServiceError("unavailable", f"generation failed: {exc}", **context,
                               headers={"Retry-After": str(self.retry_after_s)}) from None
        if "error" in reply:
            raise ServiceError.from_generator(reply["error"], **context)
        CACHE.labels("record", "hit" if reply["cached"] else "miss").inc()
        if not reply["cached"]:
            GENERATE_SECONDS.observe(reply["seconds"])
        return record

    async def record(self, graph_hash: str) -> bytes | None:
        """The cached record, None if there is none; 503 when the cache cannot be asked."""
        try:
            record = await self.store.aread("rec:" + graph_hash)
        except CacheUnavailable as exc:
            raise ServiceError("unavailable", f"the cache is not reachable: {exc}",
                               headers={"Retry-After": str(self.retry_after_s)}) from None
        return record if is_record(record, graph_hash) else None

    async def nodedefs(self) -> bytes:
        # the library is fixed for the life of the process: ask the generator once
        if self._nodedefs is None:
            _, self._nodedefs = await self.pool.run({"op": "nodedefs"})
        return self._nodedefs
