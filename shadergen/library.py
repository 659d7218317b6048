"""Data libraries: node definitions, implementations and their source files, indexed for resolution.

Everything a generator knows about nodes comes from `.mtlx` files (seed 1.3.2). A process loads
them once; the parsed tree is kept in an on-disk cache named by the output key (fingerprint.py:
every library file, the folder, the generator's code), so a cold process reads one JSON Lines file
instead of parsing XML. The cache names source files relative to the library folder. Documents may declare their own
nodedefs, implementations and nodegraph implementations: `Scope` layers a document over a library.
"""
import gc
import json
import os
import time
import zlib
from contextlib import contextmanager
from functools import lru_cache

from .digest import sha256
from .document import parse_document
from .element import Element
from .errors import ShaderGenError
from .fingerprint import PACKAGE, file_stamps, library_files, output_key

# Folders are plain strings here, as in fingerprint.py: a cold process does not import pathlib.
DEFAULT_LIBRARY_ROOT = os.path.join(os.path.dirname(PACKAGE), "libraries")


def library_root() -> str:
    return os.environ.get("SHADERGEN_LIBRARIES", DEFAULT_LIBRARY_ROOT)


def cache_dir() -> str:
    return os.environ.get("SHADERGEN_CACHE_DIR", os.path.join(os.path.expanduser("~"), ".cache", "shadergen"))


class Index:
    """Definitions found in one set of elements (a library, or one document)."""

    def __init__(self):
        self.nodedefs: dict[str, Element] = {}
        self.nodedefs_by_node: dict[str, list[Element]] = {}
        self.implementations: dict[str, list[Element]] = {}  # nodedef name -> implementation / nodegraph
        self.nodegraphs: dict[str, Element] = {}  # what <implementation nodegraph="..."> names
        self.geompropdefs: dict[str, Element] = {}
        self.typedefs: dict[str, Element] = {}
        self.units: dict[str, dict[str, float]] = {}  # unittype -> unit -> scale
        self.targets: dict[str, str | None] = {}  # target -> inherited target

    def add(self, root: Element) -> None:
        for e in root.children:
            cat = e.category
            if cat == "nodedef":
                self.nodedefs[e.name] = e
                node = e.get("node")
                namespace = e.inherited("namespace")  # a node of another namespace is written <ns:node>
                self.nodedefs_by_node.setdefault(f"{namespace}:{node}" if namespace else node, []).append(e)
            elif cat == "implementation" or (cat == "nodegraph" and e.get("nodedef")):
                self.implementations.setdefault(e.get("nodedef"), []).append(e)
            if cat == "nodegraph":
                self.nodegraphs[e.name] = e
            elif cat == "geompropdef":
                self.geompropdefs[e.name] = e
            elif cat == "typedef":
                self.typedefs[e.name] = e
            elif cat == "unitdef":
                units = self.units.setdefault(e.get("unittype"), {})
                for u in e.children_of("unit"):
                    units[u.name] = float(u.get("scale", "1"))
            elif cat == "targetdef":
                self.targets[e.name] = e.get("inherit")


class Library(Index):
    """The loaded data libraries of a process, with the hash that names their content."""

    def __init__(self, root: str, content_hash: str, roots: list[Element],
                 output_types: dict[str, list[str | None]] | None = None):
        super().__init__()
        self.root = root
        self.content_hash = content_hash
        for r in roots:
            self.add(r)
        # nodedef -> the `type` of each output it declares (None where one has none): resolving a
        # node compares them for every definition of its category, and a definition's children
        # are decoded only when read (the on-disk cache keeps this table beside them)
        self.output_types = output_types if output_types is not None else _output_types(self.nodedefs.values())
        self.roots = roots  # one per library file
        self._root_ids = {id(r) for r in roots}
        # names a nodegraph implementation is found by (Scope.implementing_graph)
        self.graph_names = set(self.nodegraphs) | {i.get("nodegraph") for impls in self.implementations.values()
                                                   for i in impls if i.get("nodegraph")}
        # What follows from the library alone (resolved nodedefs, inherited inputs, chosen and
        # parsed implementations, expanded nodegraph bodies), kept for the life of this Library:
        # a library edit loads a new Library (a new content_hash), so it never sees these.
        # Bounded, since the keys of nodedef resolution come from documents.
        self.facts: dict = {}

    MAX_FACTS = 65536

    def fact(self, key, compute):
        """compute(), memoised for the life of this library (`key` must name only library things)."""
        facts = self.facts
        if key not in facts:
            value = compute()
            if len(facts) >= self.MAX_FACTS:
                return value
            facts[key] = value
        return facts[key]

    def code(self):
        """The library's shader code in the IR (code/library.py), read once per library."""
        from .code.externals import EXTERNALS  # code/ reads this module's library: imported when first asked
        from .code.library import CodeLibrary
        return self.fact(("code",), lambda: CodeLibrary.load(self, EXTERNALS))

    def owns(self, elem: Element) -> bool:
        """Whether `elem` is one of this library's elements (not a document's)."""
        while elem.parent is not None:
            elem = elem.parent
        return id(elem) in self._root_ids

    @classmethod
    def load(cls, root: str | os.PathLike | None = None) -> "Library":
        root = os.path.realpath(root or library_root())
        content_hash = remembered_output_key(root)
        cached = os.path.join(cache_dir(), f"library-{content_hash[:24]}.jsonl")
        with collection_paused():
            read = _read_cache(cached, root)
            if read is not None:
                return cls(root, content_hash, *read)
            # the folder is walked for its documents only when they are parsed
            library = cls(root, content_hash, [parse_document(_read_bytes(p), path=p).root
                                               for p in library_files(root) if p.endswith(".mtlx")])
            _write_cache(cached, library)
            return library

    def target_chain(self, target: str) -> list[str]:
        chain = []
        while target and target not in chain:
            chain.append(target)
            target = self.targets.get(target)
        return chain


# Files modified this recently may still change within their clock step without a new stamp.
RECENT_NS = 2_000_000_000


def remembered_output_key(root: str | os.PathLike, package: str | os.PathLike = PACKAGE) -> str:
    """fingerprint.output_key, kept in the cache folder in a file named by the stamps of the files
    it reads: a cold process stats those files instead of reading and hashing them all (a fifth of
    its time). Any edit of a library or generator file changes its stamps, hence the file looked
    for; a damaged file is recomputed and rewritten. A key is kept only when every file is older
    than RECENT_NS, so a later rewrite cannot keep an old stamp."""
    stamps, newest = file_stamps(root, package)
    path = os.path.join(cache_dir(), f"output-key-{stamps[:32]}.txt")
    try:
        with open(path, encoding="ascii") as f:
            key, check = f.read().split()
        if sha256(key.encode()).hexdigest() == check:
            return key
    except (OSError, ValueError):
        pass  # missing or damaged: computed again
    key = output_key(root, package)
    if newest < time.time_ns() - RECENT_NS:
        try:
            write_atomically(path, f"{key} {sha256(key.encode()).hexdigest()}\n".encode())
        except OSError:
            pass  # a read-only home is not fatal: the next process hashes again
    return key


def _to_json(e: Element) -> list:
    return [e.category, e.attrs, [_to_json(c) for c in e.children]]


def _definitions_to_json(root: Element, texts: list[bytes]) -> list:
    """A library file: its top-level elements, each with the index in `texts` of its children's
    JSON text (-1: none), which Element decodes when they are first read (a shader reads a few
    dozen of some 1,700 definitions)."""
    definitions = []
    for d in root.children:
        if d.children:
            texts.append(json.dumps([_to_json(c) for c in d.children], separators=(",", ":")).encode())
        definitions.append([d.category, d.attrs, len(texts) - 1 if d.children else -1])
    return [root.category, root.attrs, definitions]


def _output_types(nodedefs) -> dict[str, list[str | None]]:
    return {nd.name: [o.get("type") for o in nd.children_of("output")] for nd in nodedefs}


def _from_json(data: list, source: str | None, texts: list[bytes]) -> Element:
    category, attrs, definitions = data
    return Element(category, attrs, None, source, [[c, a, texts[k] if k >= 0 else []] for c, a, k in definitions])


def checksum(body) -> bytes:
    """What a cache file's first line holds of the rest: its CRC-32, in CHECKSUM_SIZE hex digits.
    It tells a damaged file (torn, truncated, overwritten in part: any error burst up to 32 bits,
    and all but one in 2**32 of the others) at 2.3 times sha256's speed, which a cold process paid
    on three megabytes of caches; these files are the generator's own, in its user's folder: no
    digest would keep out someone who can write there."""
    return b"%08x" % zlib.crc32(body)


CHECKSUM_SIZE = 8


# The cache file is JSON Lines: the checksum of the lines after it, as a JSON string; the index
# (every library file with its top-level elements); the nodedefs' output types
# (Library.output_types); then each definition's children, one JSON text a line (compact JSON has no raw newline). Children kept as text apart from the index cost
# a cold process a quarter of what decoding them as JSON strings inside it did (no escapes to
# undo). The checksum is checked before anything is read, so a damaged file is rebuilt instead of
# failing when a definition's children are decoded later.
_BODY_START = len('""\n') + CHECKSUM_SIZE


def _read_bytes(path: str) -> bytes:
    with open(path, "rb") as f:
        return f.read()


def _read_cache(path: str, root: str) -> tuple[list[Element], dict[str, list[str | None]]] | None:
    """(library roots, output types), or None."""
    try:
        data = _read_bytes(path)
        if data[1:_BODY_START - 2] != checksum(memoryview(data)[_BODY_START:]):
            return None
        _, index, types, *texts = data.split(b"\n")  # (one copy of the 700 kB, the lines)
        roots = [_from_json(d, os.path.join(root, src), texts) for src, d in json.loads(index)]
        return roots, json.loads(types)
    except (OSError, ValueError, TypeError, IndexError):
        return None  # missing or corrupt: rebuilt from the .mtlx files


def _write_cache(path: str, library: Library) -> None:
    texts: list[bytes] = []
    index = [[os.path.relpath(r.source, library.root), _definitions_to_json(r, texts)] for r in library.roots]
    body = b"\n".join([json.dumps(index, separators=(",", ":")).encode(),
                       json.dumps(library.output_types, separators=(",", ":")).encode(), b"\n".join(texts)])
    try:
        write_atomically(path, b'"' + checksum(body) + b'"\n' + body)
    except OSError:
        pass  # a read-only home is not fatal: the next process parses again


def write_atomically(path: str | os.PathLike, data: bytes) -> None:
    """`data` as the file `path` (its folder made if need be), written beside it and then renamed:
    concurrent processes never read half a file."""
    path = os.fspath(path)
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    tmp = f"{os.path.splitext(path)[0]}.{os.getpid()}.tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)


def write_checked(path: str, body: bytes) -> None:
    """`body` written atomically after its checksum (read_checked's format); a read-only home is
    not fatal: the next process computes it again."""
    try:
        write_atomically(path, checksum(body) + b"\n" + body)
    except OSError:
        pass


def read_checked(path: str) -> memoryview | None:
    """What write_checked wrote (a view of the file's bytes: not copied), or None (missing, or
    damaged: the checksum does not match)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None
    digest, body = data[:CHECKSUM_SIZE], memoryview(data)[CHECKSUM_SIZE + 1:]
    if data[CHECKSUM_SIZE:CHECKSUM_SIZE + 1] != b"\n" or checksum(body) != digest:
        return None
    return body


@contextmanager
def collection_paused():
    """The cyclic garbage collector paused: a library is tens of thousands of new containers and
    no cycles, which the collector would otherwise rescan every few hundred allocations (a cold
    `generate` of carpaint ran half of its collections while loading the library). What is alive
    when it resumes is frozen (gc.freeze: moved where collections never scan), or the first
    collection after the load would scan all of it (a tenth of a cold `generate`) and every full
    one after that again; reference counting still frees any of it that is dropped."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if enabled:
            gc.enable()


@lru_cache(maxsize=None)
def default_library() -> Library:
    return Library.load()


def read_source(path: str) -> str:
    with open(path, encoding="utf-8") as f:
        return f.read()


class Scope:
    """Definitions visible while generating one document: the document's own first, then the library's."""

    def __init__(self, library: Library, document_root: Element | None):
        self.library = library
        self.local = Index()
        if document_root is not None:
            self.local.add(document_root)
        self.layers = (self.local, library)
        local = self.local
        self.document_facts: dict = {}
        # The library's facts hold for a document that defines nothing of its own; its plain
        # nodegraphs matter only if an <implementation nodegraph="..."> could find one by name.
        self.library_only = not (local.nodedefs or local.implementations or local.geompropdefs or local.typedefs
                                 or local.units or local.targets or library.graph_names & local.nodegraphs.keys())

    def library_fact(self, key, compute):
        """compute(), memoised in the library when the document defines nothing that could change
        it, else for this document (a body its own definitions use thousands of times is built once)."""
        if self.library_only:
            return self.library.fact(key, compute)
        if key not in self.document_facts:
            self.document_facts[key] = compute()
        return self.document_facts[key]

    def _first(self, table: str, name: str) -> Element | None:
        """The document's definition of that name, else the library's."""
        for layer in self.layers:
            found = getattr(layer, table).get(name)
            if found is not None:
                return found
        return None

    def nodedef(self, name: str) -> Element | None:
        return self._first("nodedefs", name)

    def nodedefs_for(self, node: str) -> list[Element]:
        out = []
        for layer in self.layers:
            out.extend(layer.nodedefs_by_node.get(node, ()))
        return out

    def geompropdef(self, name: str) -> Element | None:
        return self._first("geompropdefs", name)

    def unit_scale(self, unittype: str, unit: str) -> float | None:
        for layer in self.layers:
            scale = layer.units.get(unittype, {}).get(unit)
            if scale is not None:
                return scale
        return None

    def nodegraph(self, name: str) -> Element | None:
        return self._first("nodegraphs", name)

    def inheritance(self, nodedef: Element) -> list[Element]:
        """The nodedef, its parent, its grandparent...: every inherited fact is read along this
        chain, so a loop in it is found here, once, before any work depends on it."""
        chain = [nodedef]
        while chain[-1].get("inherit"):
            parent_name = chain[-1].get("inherit")
            parent = self.nodedef(parent_name)
            if parent is None:
                raise ShaderGenError("unknown_nodedef", f"nodedef '{chain[-1].name}' inherits unknown '{parent_name}'",
                                     chain[-1].name)
            if any(nd is parent for nd in chain):
                names = [nd.name for nd in chain[chain.index(parent):]] + [parent.name]
                raise ShaderGenError("cycle", "nodedef inheritance loops: " + " -> ".join(names), nodedef.name)
            chain.append(parent)
        return chain

    def implementation(self, nodedef: Element, target: str) -> Element | None:
        """The implementation of a nodedef for a target (or a target it inherits from); a nodegraph
        implementation (a nodegraph naming the nodedef, or an <implementation nodegraph="...">)
        serves every target. Follows nodedef inheritance when the nodedef has none."""
        return self.library_fact(("implementation", nodedef.name, target),
                                 lambda: self._implementation(nodedef, target))

    def _implementation(self, nodedef: Element, target: str) -> Element | None:
        chain = self.library.target_chain(target)
        for nd in self.inheritance(nodedef):
            for t in chain:
                for layer in self.layers:
                    for impl in layer.implementations.get(nd.name, ()):
                        if impl.category == "implementation" and impl.get("target", t) == t:
                            return self.implementing_graph(impl) if impl.get("nodegraph") else impl
            for layer in self.layers:
                for impl in layer.implementations.get(nd.name, ()):
                    if impl.category == "nodegraph":
                        return impl
        return None

    def implementing_graph(self, impl: Element) -> Element:
        graph = self.nodegraph(impl.get("nodegraph"))
        if graph is None:
            raise ShaderGenError("unknown_implementation", f"implementation '{impl.name}' names nodegraph "
                                 f"'{impl.get('nodegraph')}', which does not exist", impl.path or impl.name)
        return graph

    def nodedef_outputs(self, nodedef: Element) -> list[Element]:
        """Outputs of a nodedef; a nodedef that declares none has its parent's."""
        for nd in self.inheritance(nodedef):
            outputs = nd.children_of("output")
            if outputs:
                return outputs
        return []

    def nodedef_output_types(self, nodedef: Element) -> list[str | None]:
        """The `type` of each output of a nodedef (None where one has none), as nodedef_outputs
        finds them, without decoding a library definition's children (Library.output_types)."""
        for nd in self.inheritance(nodedef):
            own = self.library.nodedefs.get(nd.name) is nd
            types = self.library.output_types[nd.name] if own else [o.get("type") for o in nd.children_of("output")]
            if types:
                return types
        return []

    def nodedef_inputs(self, nodedef: Element) -> list[Element]:
        """Inputs of a nodedef including inherited ones (the child's override the parent's)."""
        return self.library_fact(("inputs", nodedef.name), lambda: self._nodedef_inputs(nodedef))

    def _nodedef_inputs(self, nodedef: Element) -> list[Element]:
        inputs: list[Element] = []
        for nd in reversed(self.inheritance(nodedef)):
            own = nd.children_of("input", "parameter", "token")
            names = {i.name for i in own}
            inputs = [i for i in inputs if i.name not in names] + own
        return inputs
