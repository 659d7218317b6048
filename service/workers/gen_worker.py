"""Generation child process: one Generator (node libraries loaded once), answering
`generate` and `nodedefs` requests from its API worker.

It reads and fills the shared cache itself: the expensive step (emitting code) happens only when
the graph hash, known after `prepare`, is not in the cache, and the record goes into the store
from here, off the API's event loop. Records are stored with `"cached": true`, which is what
they are whenever they are read back.

Source is shared by topology: `top:<topology hash>` names the record of a document of that
topology, and a document that differs from it only in values gets that record's source with its
own listing values (Prepared.rebind), without emitting: an editor dragging a slider."""
import json
import sys
import threading
import time

from shadergen.api import Generator
from shadergen.errors import ShaderGenError

from ..cache import open_store
from ..cache.entries import has_no_warnings, is_graph_hash, is_record
from ..config import get_settings
from .child import serve


def _dumps(record: dict) -> bytes:
    return json.dumps(record, separators=(",", ":")).encode()


class GenerateHandler:
    def __init__(self):
        settings = get_settings()
        self.store = open_store(settings.cache, settings.cache_max_bytes)
        self.generator = Generator()
        self.topology_sharing = settings.topology_sharing
        self.include_roots = settings.include_roots

    def __call__(self, message: dict, payload: bytes) -> tuple[dict, bytes]:
        if message["op"] == "nodedefs":
            return {"ok": True}, _dumps(self.generator.nodedefs())
        return self.generate(message, payload)

    def generate(self, message: dict, payload: bytes) -> tuple[dict, bytes]:
        started = time.perf_counter()
        document_format = message.get("format", "mtlx")
        # the document is the payload: bytes, never str (the generator reads a str that does not
        # start with "<" as a file path), binary for usdz
        document = payload
        try:
            prepared = self.generator.prepare(
                document, target=message["target"], element=message["element"], interface=message["interface"],
                keep=message.get("keep", ()), values=message.get("values", "listing"),
                environment=message.get("environment"), lights=message.get("lights", True),
                names=message.get("names", "structural"), cms=message.get("cms"),
                ocio_config=message.get("ocio_config"), base_dir=None,
                allow_includes=False, include_roots=self.include_roots, document_format=document_format,
            )
            key = "rec:" + prepared.hash
            stored = self.store.get(key)
            body = self._with_own_warnings(stored, prepared.warnings) if is_record(stored, prepared.hash) else None
            if body is None:  # absent, or garbage to overwrite
                record = (self.topology_sharing and self._same_topology(prepared)) or prepared.emit(source=True)
                record["document"] = None  # uploads have no path
                self.store.put(key, _dumps({**record, "cached": True}))
                if self.topology_sharing:
                    self.store.put("top:" + prepared.topology_hash, prepared.hash.encode())
                body, cached = _dumps({**record, "cached": False}), False
            else:
                cached = True
        except ShaderGenError as exc:
            if message.get("digest"):
                # the same request is refused from the store next time (service/generation.py): a
                # refusal depends on nothing but what the digest covers
                self.store.put("err:" + message["digest"], _dumps(exc.to_dict()))
            return {"error": exc.to_dict()}, b""
        if message.get("digest") and not prepared.warnings:
            # identical requests later skip even `prepare` (see service/generation.py), answered
            # with the stored record as it is: only those without warnings, whose record is theirs
            # whichever document of the graph stored it (entries.has_no_warnings)
            self.store.put("req:" + message["digest"], prepared.hash.encode())
        return {"hash": prepared.hash, "cached": cached, "seconds": time.perf_counter() - started}, body

    @staticmethod
    def _with_own_warnings(stored: bytes, warnings: list[str]) -> bytes | None:
        """The stored record (`stored` itself when it already says so) with this document's
        warnings: records are shared by graph hash, and two documents of one graph warn of
        different things (what one upload's layers say is no other client's to read). None for
        an entry that only looks like a record."""
        if not warnings and has_no_warnings(stored):  # the common hit, answered without parsing it
            return stored
        try:
            record = json.loads(stored)
        except ValueError:
            return None
        if not isinstance(record, dict):
            return None
        if record.get("warnings") == warnings:
            return stored
        return _dumps({**record, "warnings": warnings})

    def _same_topology(self, prepared) -> dict | None:
        """The record of an earlier document of the same topology, rebound to this one's values."""
        full_hash = self.store.get("top:" + prepared.topology_hash)
        if not is_graph_hash(full_hash):
            return None
        stored = self.store.get("rec:" + full_hash.decode())
        if not is_record(stored, full_hash.decode()):
            return None
        try:
            return prepared.rebind(json.loads(stored))
        except (ValueError, KeyError, TypeError, AttributeError):  # an entry that only looks like a record: a miss
            return None


# The generator recurses along graph edges, so a long chain of nodes (a few thousand fit in the
# body limit) needs a deep stack; the time limit, not the stack, is what bounds such documents.
STACK_BYTES = 512 * 1024 * 1024  # address space reserved, not memory used
RECURSION_LIMIT = 200_000


def main() -> None:
    def work():
        handler = GenerateHandler()
        serve(handler, {"library_hash": handler.generator.library_hash})

    threading.stack_size(STACK_BYTES)
    sys.setrecursionlimit(RECURSION_LIMIT)
    thread = threading.Thread(target=work, name="generate")
    thread.start()
    thread.join()


if __name__ == "__main__":
    main()
