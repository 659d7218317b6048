"""`shadergen render --batch DIR_OR_LIST -o OUTDIR`: a library's thumbnails in one command.

One generator and one renderer for the whole batch: the library is loaded once, and a compiled
program serves every material of its topology (value-free `complete` source and structural names:
a new material of a known topology is a bind and a draw). The generator runs in a child process
a few documents ahead of the drawing, so that a material costs about its frame rather than its
generation plus its frame. Every material gets one line in OUTDIR/results.jsonl, its PNG's path
or its error record; a broken document is an error record beside the others' thumbnails, never the
end of the batch.
"""
import itertools
import json
import os
import sys
import time
from collections import deque

from shadergen.errors import ShaderGenError

from .errors import RenderError
from .imageio import write_image

DOCUMENT_SUFFIXES = (".mtlx", ".usda", ".usd", ".usdc", ".usdz")
RESULTS = "results.jsonl"
# documents generated ahead of the one being drawn: enough to keep the generator busy while a frame
# is drawn, few enough that their records hold little memory
AHEAD = 2


def batch_documents(spec: str) -> tuple[str, list[str]]:
    """(the folder the documents' output names are relative to, the documents): every document
    under a folder (recursively, sorted), or the paths a list file names one per line (relative to
    its folder; blank lines and lines starting with # skipped)."""
    if os.path.isdir(spec):
        found = [os.path.join(folder, name) for folder, _, names in os.walk(spec) for name in names
                 if name.lower().endswith(DOCUMENT_SUFFIXES)]
        if not found:
            raise RenderError("invalid_request", f"no documents ({', '.join(DOCUMENT_SUFFIXES)}) under {spec}", spec)
        return spec, sorted(found)
    try:
        with open(spec, encoding="utf-8") as f:
            lines = [line.strip() for line in f]
    except (OSError, UnicodeDecodeError) as exc:
        raise RenderError("invalid_request", f"cannot read the batch list {spec}: "
                          f"{getattr(exc, 'strerror', None) or exc}", spec) from None
    root = os.path.dirname(os.path.abspath(spec))
    paths = [os.path.join(root, line) for line in lines if line and not line.startswith("#")]
    if not paths:
        raise RenderError("invalid_request", f"the batch list {spec} names no documents", spec)
    return root, paths


def output_name(root: str, document: str, element: str | None) -> str:
    """The PNG's path under OUTDIR: the document's path from `root` without its suffix, then the
    element (`/` spelled `_`): documents of one name in different folders keep apart."""
    relative = os.path.relpath(os.path.abspath(document), os.path.abspath(root))
    if relative.startswith(os.pardir):  # a list may name documents outside its folder
        relative = os.path.basename(document)
    stem = os.path.splitext(relative)[0]
    return os.path.join(stem, f"{(element or 'shader').replace('/', '_')}.png")


class Progress:
    """A bar on a terminal (rewritten in place), else a line at every tenth of the batch."""

    def __init__(self, total: int, stream=None):
        self.total, self.done = total, 0
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.started = time.perf_counter()

    def step(self, label: str, errors: int, compiled: int) -> None:
        self.done += 1
        counts = f"{self.done}/{self.total} documents, {errors} errors, {compiled} programs compiled"
        if self.tty:
            filled = 30 * self.done // self.total
            self.stream.write(f"\r[{'#' * filled}{'.' * (30 - filled)}] {counts} {label[-30:]:30}")
            if self.done == self.total:
                self.stream.write("\n")
            self.stream.flush()
        elif self.done * 10 // self.total != (self.done - 1) * 10 // self.total:
            self.stream.write(f"shadergen render: {counts}\n")

    def seconds(self) -> float:
        return time.perf_counter() - self.started


def run_batch(args, renderer, env, target: str) -> int:
    """Thumbnails of every material of every document of `args.batch` under `args.output`."""
    if args.exr or args.npy or not args.output:
        raise RenderError("invalid_request", "--batch writes PNGs under -o OUTDIR (no --exr or --npy)")
    root, documents = batch_documents(args.batch)
    encoder = display_encoders(args)
    os.makedirs(args.output, exist_ok=True)
    options = dict(target=target, all=True, interface=args.interface or "complete", environment=args.env_method,
                   lights=bool(args.lights), cms=args.cms, ocio_config=args.ocio_config)
    progress = Progress(len(documents))
    counts = {"materials": 0, "thumbnails": 0, "errors": 0}
    written: set[str] = set()
    with open(os.path.join(args.output, RESULTS), "w", encoding="utf-8") as results:
        for document, records in generated_ahead(documents, options):
            for record in records:
                result = _thumbnail(record, document, root, args, renderer, env, written, encoder)
                counts["materials"] += 1
                counts["errors" if "error" in result else "thumbnails"] += 1
                results.write(json.dumps(result) + "\n")
                if args.json:
                    print(json.dumps(result))
            progress.step(os.path.basename(document), counts["errors"], renderer.program_counts["compiled"])
    programs = renderer.program_counts
    print(f"shadergen render: {len(documents)} documents, {counts['materials']} materials: {counts['thumbnails']} "
          f"thumbnails, {counts['errors']} errors; {programs['compiled']} programs compiled, {programs['reused']} "
          f"reused; {progress.seconds():.1f} s; results in {os.path.join(args.output, RESULTS)}", file=sys.stderr)
    return 0 if counts["errors"] == 0 else 1


def generated_ahead(documents: list[str], options: dict):
    """(document, its records) in the documents' order, each generated in a child process while
    this one draws the documents before it. Should the child die, the documents not yet generated
    are generated here: a batch loses nothing to it."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    # spawned, not forked: this process holds a GL context, which a fork would share
    pool = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn"))

    def submitted(document: str):
        """The child's future of the document's records; None once the child is gone."""
        try:
            return pool.submit(document_records, document, options)
        except BrokenProcessPool:
            return None

    queued = iter(documents)
    pending = deque((d, submitted(d)) for d in itertools.islice(queued, AHEAD))
    try:
        while pending:
            document, future = pending.popleft()
            following = next(queued, None)
            if following is not None:
                pending.append((following, submitted(following)))
            try:
                records = future.result() if future is not None else None
            except BrokenProcessPool:
                records = None
            yield document, document_records(document, options) if records is None else records
    finally:
        pool.shutdown(cancel_futures=True)


def document_records(document: str, options: dict) -> list[dict]:
    """One record per material of the document (error records included); a document the generator
    could not even start on is one error record, not a traceback."""
    from shadergen.api import DocumentFile, default_generator

    try:
        return list(default_generator().records(DocumentFile(document), **options))
    except Exception as exc:
        return [{"document": document, "element": None,
                 "error": {"code": "internal_error", "message": f"{type(exc).__name__}: {exc}", "where": None}}]


def display_encoders(args):
    """fn(record) -> the PNG's encoding of that record (None: sRGB of linear Rec.709): with --cms
    ocio, the record's working space through the config's display and --view. An unknown view
    fails here, before anything is drawn. A single render's PNG is encoded the same way (cli.py)."""
    from shadergen.cms import system_for

    try:
        system = system_for(args.cms, args.ocio_config)
        if system.name == "builtin":
            if args.view:
                raise RenderError("invalid_option", "--view is a colour-managed viewer's: it needs --cms ocio", "view")
            return lambda record: None
        system.display_encoder(None, view=args.view)
    except ShaderGenError as e:
        raise RenderError(e.code, e.message, e.where) from None
    return lambda record: system.display_encoder(record.get("working_colorspace"), view=args.view)


def _thumbnail(record: dict, document: str, root: str, args, renderer, env, written: set[str], encoder) -> dict:
    result = {"document": document, "element": record.get("element")}
    if "error" in record:
        return dict(result, error=record["error"])
    path = os.path.join(args.output, output_name(root, document, record["element"]))
    if path in written:
        return dict(result, error={"code": "output_collision", "message": f"{path} was already written in this batch",
                                   "where": path})
    try:
        drawn = renderer.render(record, size=args.size, mesh=args.mesh, env=env, env_samples=args.env_samples,
                                env_method=args.env_method, lights=args.lights, supersample=args.ss,
                                document_dir=os.path.dirname(os.path.abspath(document)))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        write_image(path, drawn.rgba, background=args.background, encode=encoder(record))
    except ShaderGenError as exc:  # a render's, or the record's working space unknown to the config
        return dict(result, error=exc.to_dict())
    except Exception as exc:  # one material's failure is its record; the batch goes on
        return dict(result, error={"code": "internal_error", "message": f"{type(exc).__name__}: {exc}",
                                   "where": record.get("element")})
    written.add(path)
    return dict(result, png=path, program_reused=drawn.program_reused, timings_ms=drawn.timings_ms,
                warnings=drawn.warnings)
