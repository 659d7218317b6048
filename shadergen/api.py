"""The library's front door: documents in, contract records out.

    gen = Generator()                                   # loads the libraries once per process
    for p in gen.prepare_all(text, target="glsl"):      # graphs built, hashes known, nothing emitted
        record = p.emit()                               # the JSON record of ../DESIGN.md

`prepare` is separate from `emit` so a cache can be asked by hash before any code is written.
Errors are ShaderGenError everywhere; `records` turns them into error records for the CLI.
"""
import functools
import gc
import json
import math
import os
import time

from .cms import system_for
from .digest import graph_digest
from .document import Document, parse_document, read_document
from .element import Element
from .errors import ShaderGenError
from .features import ENVIRONMENTS
from .generator import EmitContext, emit_shader, image_fallback, listing_value
from .graph import GraphBuilder, Output
from .passes import Options, prepare
from .hashing import graph_hashes
from .library import Library, Scope, default_library
from .naming import NAMES
from .targets import target_class, target_for
from .types import value_to_json
from .usd import is_usd_path, parse_usd, read_usd

INTERFACES = ("complete", "reduced", "specialized")
VALUES = ("listing", "source")  # where the document's values of the uniforms are written
SHADER_CATEGORIES_SKIPPED = ("nodedef", "implementation", "nodegraph", "input", "output", "typedef", "geompropdef",
                             "unitdef", "unittypedef", "targetdef", "look", "collection", "geominfo", "propertyset",
                             "variantset", "backdrop", "token", "attributedef", "materialassign", "lookgroup")


def renderable_elements(doc: Document, scope: Scope) -> list[Element]:
    """MaterialX's findRenderableElements: the material nodes; without any, every output of a
    node graph (definitions' graphs included) and then the document's own outputs."""
    nodes = [e for e in doc.root.children if e.category not in SHADER_CATEGORIES_SKIPPED]

    def output_type(e: Element) -> str:
        return e.get("type", "")

    materials = [e for e in nodes if output_type(e) == "material"]
    if materials:
        return materials
    closures = ("BSDF", "EDF", "VDF", "lightshader")  # what a surface reads, not what a pixel shows
    outputs = [o for g in doc.root.children_of("nodegraph") for o in g.children_of("output")
               if o.get("type") not in closures]
    return outputs + [o for o in doc.root.children_of("output") if o.get("type") not in closures]


def document_scope(doc: Document, library) -> Scope:
    """The definitions `doc` sees with `library`, read once per document and library: a client
    asks for a document's elements one at a time, and what the scope memoises for a document that
    defines nodes of its own (each nodegraph body it uses, built once) serves every element."""
    key = ("scope", library)
    scope = doc.memo.get(key)
    if scope is None:
        scope = doc.memo[key] = Scope(library, doc.root)
    return scope


def _named_renderable(doc: Document, scope: Scope, element: str) -> list[Element]:
    """The renderable elements `element` names (what `_names` answers for each), in order. A
    client asks for the elements of a document one at a time, so a document without labels is read
    once into an index by name and path (a scan per element made a document of n outputs cost n^2)."""
    if doc.labels:
        return [e for e in renderable_elements(doc, scope) if _names(e, element, doc)]
    index = doc.memo.get("renderable")
    if index is None:
        index = doc.memo["renderable"] = {}
        for e in renderable_elements(doc, scope):
            index.setdefault(e.name, []).append(e)
            path = e.path
            if path != e.name:
                index.setdefault(path, []).append(e)
    return list(index.get(element, ()))


def _names(e: Element, element: str, doc: Document) -> bool:
    """Whether `element` names `e`: its name, its path or its label. A document of many outputs is
    asked for each of them in turn, so paths are walked only where the name could end one."""
    if element == e.name:
        return True
    if not doc.labels and not element.endswith(e.name):
        return False
    path = e.path
    return element == path or element == doc.label(path)


def collection_deferred(method):
    """`method` with the cyclic garbage collector paused while it runs (and collecting after it, as
    it would have): preparing and emitting an element build thousands of containers (graph nodes
    and their ports, IR nodes) that stay alive until its record is written, and the collector's
    default threshold rescanned them every 700 allocations, a fifth of a warm request's time (the
    commit that added this has the figures). Nothing is frozen and no collection is forced: the
    collector's own schedule resumes at the first allocation after it (the caller's), so a
    request's cyclic garbage (the graph) is still collected, and older generations when they are
    due (a forced young collection here would put off the older ones indefinitely in a loop of
    requests)."""
    @functools.wraps(method)
    def deferred(*args, **kwargs):
        enabled = gc.isenabled()
        gc.disable()
        try:
            return method(*args, **kwargs)
        finally:
            if enabled:
                gc.enable()
    return deferred


# What generating one element can raise: its own errors, and gaps in our code that a document
# reached, which still become a record (never a traceback).
ELEMENT_FAILURES = (ShaderGenError, RecursionError, ValueError, TypeError, KeyError, AttributeError, IndexError)


def element_error(exc: Exception, where: str | None, doc: Document) -> ShaderGenError:
    """The error record of an element (`where`: its name as users know it); element paths the
    error names become the document's labels for them (prim paths, for USD)."""
    if isinstance(exc, ShaderGenError):
        err = exc
        err.where = doc.label(err.where)
    elif isinstance(exc, RecursionError):  # a chain deeper than Python's stack: a document limit, not a crash
        err = ShaderGenError("too_large", "the graph's chain of connections is too deep to generate", where)
    else:
        err = ShaderGenError("internal_error", f"generation failed: {type(exc).__name__}: {exc}", where)
    err.element = where
    return err


class Prepared:
    """One renderable element with its graph built and its hash known; `emit` writes the code.
    (A plain class, not a dataclass: see graph.py.)"""

    def __init__(self, generator: "Generator", document: Document, element: str, target: str, interface: str,
                 hash: str, topology_hash: str, graph, scope: Scope, warnings: list[str], prepare_ms: float,
                 names: str = "structural", working_colorspace: str | None = None):
        self.generator = generator
        self.document = document
        self.element = element
        self.target = target
        self.interface = interface
        self.hash = hash
        self.topology_hash = topology_hash  # the hash without the values a value-free source leaves to the listing
        self.graph = graph
        self.scope = scope
        self.warnings = warnings
        self.prepare_ms = prepare_ms
        self.names = names  # what the source calls the document's elements (naming.py)
        # with OCIO, the space the shader's colours are in: a viewer shows them through the
        # config's display and view from it (cms/ocio.py display_encoder)
        self.working_colorspace = working_colorspace

    @collection_deferred
    def emit(self, source: bool = True) -> dict:
        t0 = time.perf_counter()
        ctx = EmitContext(target_for(self.target), self.scope, self.graph.values_in_source, self.names)
        stages = emit_shader(ctx, self.graph)
        blocks = {name: st.listing() for name, st in ctx.stages.items()}
        layout = ctx.target.layout(ctx)
        # what a target compiles its stages to (vulkan: SPIR-V), for a record with its source
        compiled = getattr(ctx.target, "compiled", None)
        binaries = compiled(stages) if compiled is not None and source else {}
        if self.document.labels:  # variables name their inputs as the source document does
            for variable in (v for block in blocks.values() for vs in block.values() for v in vs):
                variable["path"] = self.document.label(variable["path"])
        ms = (time.perf_counter() - t0) * 1e3 + self.prepare_ms
        return {
            "document": self.document.path, "element": self.element, "target": self.target,
            "interface": self.interface, "hash": self.hash, "topology_hash": self.topology_hash,
            "cached": False,
            "stages": stages if source else {k: None for k in stages},
            "blocks": blocks,
            "timings_ms": {"generate": round(ms, 3)}, "passes": self.graph.passes, "warnings": self.warnings,
        } | ({"layout": layout} if layout is not None else {}) \
          | ({"environment": self.graph.environment} if self.graph.environment is not None else {}) \
          | ({"lights": False} if not self.graph.lights else {}) \
          | ({"luts": ctx.luts} if ctx.luts else {}) | self._working() | binaries

    def _working(self) -> dict:
        return {"working_colorspace": self.working_colorspace} if self.working_colorspace else {}

    def rebind(self, record: dict) -> dict | None:
        """This element's record made from `record`, an earlier one of the same topology hash,
        without emitting: the source is the same and only the listing's values and paths are this
        document's (structural names: the same topology may be named otherwise). None when the
        shortcut does not apply (values in the source, labels)."""
        if self.graph.values_in_source or self.document.labels or record.get("topology_hash") != self.topology_hash:
            return None
        t0 = time.perf_counter()
        public = [dict(v) for v in record["blocks"]["pixel"]["PublicUniforms"]]
        if len(public) != len(self.graph.interface):
            return None
        for variable, port in zip(public, self.graph.interface):  # the listing is in interface order
            # what the listing says of this document's uniform and its source does not (hashing.py)
            variable.update(value=value_to_json(listing_value(port, port.value)), path=port.path,
                            unit=port.meta.get("unit"), colorspace=port.meta.get("colorspace"))
            variable.pop("ui", None)
            if port.meta.get("ui"):
                variable["ui"] = dict(port.meta["ui"])
            if port.type == "filename":
                variable.pop("fallback", None)
                if image_fallback(port) is not None:
                    variable["fallback"] = value_to_json(image_fallback(port))
        ms = (time.perf_counter() - t0) * 1e3 + self.prepare_ms
        blocks = dict(record["blocks"], pixel=dict(record["blocks"]["pixel"], PublicUniforms=public))
        return dict(record, document=self.document.path, element=self.element, hash=self.hash, cached=False,
                    blocks=blocks, timings_ms={"generate": round(ms, 3)}, warnings=self.warnings) | self._working()


class DocumentFile(os.PathLike):
    """A document's path on disk, for `Generator.load` and `records` (where a str is the document
    itself): pathlib.Path serves as well, but a cold `shadergen generate` does not import pathlib."""

    __slots__ = ("path",)

    def __init__(self, path: str):
        self.path = path

    def __fspath__(self) -> str:
        return self.path


class Generator:
    def __init__(self, library: Library | None = None):
        self.library = library or default_library()

    @property
    def library_hash(self) -> str:
        return self.library.content_hash

    # -- documents ----------------------------------------------------------------------------
    def load(self, source: str | bytes | os.PathLike, *, base_dir: str | None = None,
             allow_includes: bool = True, document_format: str = "mtlx", include_roots=()) -> Document:
        """A path (os.PathLike) is read from disk, as USD when its suffix says so; str or bytes
        are the document itself (MaterialX XML, or a USD upload of `document_format` usda/usdz),
        never a path, and XML may include other files only relative to an explicit `base_dir`,
        or else only from `include_roots` (document.IncludeRoots: confined, as the service's)."""
        if isinstance(source, os.PathLike):
            path = os.fspath(source)
            if is_usd_path(path):
                return read_usd(path, self.library)
            return read_document(path, allow_includes=allow_includes)
        if document_format != "mtlx":
            return parse_usd(source, document_format, self.library)
        return parse_document(source, base_dir=base_dir, allow_includes=allow_includes and base_dir is not None,
                              include_roots=include_roots)

    def prepare_all(self, source, *, target: str = "glsl", element: str | None = None, all: bool = True,
                    interface: str = "complete", keep=(), values: str = "listing", environment: str | None = None,
                    lights: bool = True, names: str = "structural", cms: str | None = None,
                    ocio_config: str | None = None, base_dir: str | None = None, allow_includes: bool = True,
                    document_format: str = "mtlx", include_roots=(),
                    texture_width: float | None = None) -> list["Prepared | ShaderGenError"]:
        """Prepare every renderable element (or the named one). Element failures are returned in
        place, so one bad material does not hide the others. `keep`: document inputs (`node/input`)
        that stay live uniforms in the `specialized` interface. `values`: "listing" (uniforms initialised
        to nodedef values, the document's values only in the listing) or "source" (written into the
        initializers too). `environment`: "fis", "prefilter" or "hybrid" writes only that way of
        lighting by the environment (a renderer then needs no MX_ENV_* macros of its own); None writes all.
        `lights`: False for a renderer that draws no light rig (thumbnails): no light loop is written,
        and the record says `"lights": false`. `names`: "structural" (the source names nodes and
        uniforms by the graph's structure, `u_n12_base_color`: materials that differ only in their
        element names share one source and topology hash; bind by the listing's paths) or
        "document" (by the document's element names, as a client binding by name needs).
        `cms`: the colour management system, builtin (the default) or ocio, with `ocio_config` a
        config's path or `ocio://NAME` (default $SHADERGEN_OCIO_CONFIG, else OCIO's CG config);
        a config alone means ocio (cms/__init__.py). `texture_width` (target osl): the filter width
        every texture() call asks of OIIO ("width"; None: OIIO's default, the lookup's own footprint
        over the mipmaps; 0: one lookup of the base level, as the GL renderer reads an image bound
        without mipmaps, bench/osl_agreement.py's like-for-like reads)."""
        target_for(target)  # unknown targets fail before any work
        if texture_width is not None and (target != "osl" or type(texture_width) not in (int, float)
                                          or not 0 <= texture_width < math.inf):
            raise ShaderGenError("unsupported_texture_width", "texture_width is a finite width >= 0 of the osl "
                                 f"target's texture() calls (got {texture_width!r} for target '{target}')",
                                 "texture_width")
        system = system_for(cms, ocio_config)
        if values not in VALUES:
            raise ShaderGenError("unsupported_values", f"unknown values '{values}'; supported: " + ", ".join(VALUES),
                                 "values")
        if environment is not None and environment not in ENVIRONMENTS:
            raise ShaderGenError("unsupported_environment", f"unknown environment '{environment}'; supported: "
                                 + ", ".join(ENVIRONMENTS), "environment")
        if names not in NAMES:
            raise ShaderGenError("unsupported_names", f"unknown names '{names}'; supported: " + ", ".join(NAMES),
                                 "names")
        if interface not in INTERFACES:
            raise ShaderGenError("unsupported_interface", f"unknown interface '{interface}'; supported: "
                                 + ", ".join(INTERFACES), interface)
        doc = source if isinstance(source, Document) else self.load(
            source, base_dir=base_dir, allow_includes=allow_includes, document_format=document_format,
            include_roots=include_roots)
        scope = document_scope(doc, self.library)
        if element:
            elems = _named_renderable(doc, scope, element) or self._named(doc, element)
        else:
            elems = renderable_elements(doc, scope)
            if not all:
                elems = elems[:1]
        options = Options(interface, frozenset(keep), values, environment, bool(lights), texture_width)
        out = []
        for e in elems:
            try:
                if e.path in doc.failures:
                    raise doc.failures[e.path]
                out.append(self._prepare(doc, scope, e, target, options, names, system))
            except ELEMENT_FAILURES as exc:
                out.append(element_error(exc, doc.label(e.path), doc))
        return out

    def prepare(self, source, **kw) -> Prepared:
        """The first (or the named) renderable element; raises its error."""
        kw.setdefault("all", False)
        results = self.prepare_all(source, **kw)
        if not results:
            raise ShaderGenError("no_renderable_element", "the document has no renderable element", None)
        if isinstance(results[0], ShaderGenError):
            raise results[0]
        return results[0]

    def records(self, source, **kw):
        """Contract records (or error records) for each element: what the CLI prints."""
        target, interface = kw.get("target", "glsl"), kw.get("interface", "complete")
        path = os.fspath(source) if isinstance(source, os.PathLike) else None
        base = {"document": path, "target": target, "interface": interface}
        try:
            prepared = self.prepare_all(source, **kw)
            if not prepared:
                raise ShaderGenError("no_renderable_element", "the document has no renderable element", path)
        except ShaderGenError as e:
            yield dict(base, element=None, error=e.to_dict())
            return
        for p in prepared:
            if isinstance(p, ShaderGenError):
                yield dict(base, element=getattr(p, "element", None), error=p.to_dict())
                continue
            try:
                yield p.emit()
            except ELEMENT_FAILURES as exc:
                yield dict(base, element=p.element, error=element_error(exc, p.element, p.document).to_dict())

    def nodedefs(self) -> list[dict]:
        out = []
        for nd in self.library.nodedefs.values():
            out.append({
                "name": nd.name, "node": nd.get("node"), "nodegroup": nd.get("nodegroup"),
                "inputs": [{k: v for k, v in i.attrs.items()} for i in nd.children_of("input")],
                "outputs": [{k: v for k, v in o.attrs.items()} for o in nd.children_of("output")],
            })
        return out

    # -- internals -----------------------------------------------------------------------------
    @staticmethod
    def _named(doc: Document, element: str) -> list[Element]:
        e = doc.root
        for part in element.split("/"):
            e = e.child(part) if e is not None else None
        if e is None:
            raise ShaderGenError("unknown_element", f"no element '{element}' in the document", element)
        return [e]

    @collection_deferred
    def _prepare(self, doc: Document, scope: Scope, elem: Element, target: str, options: Options,
                 names: str, system) -> Prepared:
        t0 = time.perf_counter()
        shading_language = target_for(target)
        builder = GraphBuilder(scope, shading_language.library, doc.root, cms=system)
        root = None
        if elem.category == "output":
            src = builder.source_of(elem)
            if not isinstance(src, Output):
                raise ShaderGenError("invalid_document", f"output '{elem.name}' is not connected", elem.path)
            outputs = {elem.name: src}
        elif elem.category in ("nodegraph",):
            outputs = {}
            for o in elem.children_of("output"):
                src = builder.source_of(o)
                if isinstance(src, Output):
                    outputs[o.name] = src
        else:
            root = builder.node_for(elem)
            outputs = {name: out for name, out in root.outputs.items()}
        graph = prepare(builder, outputs, root, options)
        local = {id(i) for impls in scope.local.implementations.values() for i in impls}
        local |= {id(g) for g in scope.local.nodegraphs.values()}  # named by <implementation nodegraph=>
        working = doc.colorspace if system.name == "ocio" else None
        # with OCIO the record names its working space (a viewer's display transform starts there):
        # two documents of the same graph in different working spaces are different records
        cms = system.identity if working is None else f"{system.identity} working {working}"
        key = dict(element=doc.label(elem.path), target=target, interface=options.interface,
                   library_hash=self.library.content_hash, local_ids=local, names=names, cms=cms,
                   ui_in_source=getattr(target_class(target), "writes_ui", False))
        h, topology = graph_hashes(graph, **key)
        if doc.labels:  # records name elements and inputs by the labels (prim paths): they key the record too
            h, topology = (graph_digest(json.dumps([k, doc.labels], sort_keys=True).encode()).hexdigest()
                           for k in (h, topology))
        return Prepared(self, doc, doc.label(elem.path), target, options.interface, h, topology, graph, scope,
                        doc.warnings + graph.warnings, (time.perf_counter() - t0) * 1e3, names, working)


_default: Generator | None = None


def default_generator() -> Generator:
    global _default
    if _default is None:
        _default = Generator()
    return _default


def generate_file(path: str, *, target: str = "glsl", element: str | None = None, all: bool = False,
                  interface: str = "complete", keep=(), environment: str | None = None,
                  lights: bool = True, cms: str | None = None, ocio_config: str | None = None) -> list[dict]:
    """Records for a document file (used by the renderer's CLI)."""
    return list(default_generator().records(DocumentFile(path), target=target, element=element, all=all,
                                            interface=interface, keep=keep, environment=environment,
                                            lights=lights, cms=cms, ocio_config=ocio_config))
