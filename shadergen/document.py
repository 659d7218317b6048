"""MaterialX XML -> Document: a tree of elements with name paths, safely parsed.

Expat reads the XML and our Element tree is built in its callbacks (no ElementTree in between).
The parser refuses DTDs (so no entity expansion and no external entities), resolves
`xi:include` relative to the including file (or, for untrusted uploads, refuses it or reads it
only from the configured include roots, confined), and
upgrades the older syntax that real documents still use (see upgrade.py).
"""
import codecs
import os
import re

# xml.parsers.expat is this C module re-exported through two packages; importing it by its own name
# saves a cold process their import (0.4 ms)
import pyexpat as expat

from .element import Element
from .errors import ShaderGenError
from .paths import inside
from .upgrade import upgrade

# a namespaced element is named as ElementTree names it, `{uri}local`, whatever prefix the document chose
XINCLUDE = "{http://www.w3.org/2001/XInclude}include"
MAX_DOCUMENT_BYTES = 64 * 1024 * 1024
MAX_INCLUDE_DEPTH = 16
# Attributes of a document's root that its elements inherit: they move onto the elements of an
# included document, which lose that root.
SCOPED_ATTRIBUTES = ("fileprefix", "colorspace")
# MaterialX nests a handful of levels (materialx > nodegraph > node > input); a deeper document
# is refused while it is parsed, before its tree could cost time or stack
MAX_NESTING = 64


class Document:
    """A parsed document: its element tree and what reading it found. (A plain class, not a
    dataclass: see graph.py.)"""

    def __init__(self, root: Element, path: str | None = None, version: tuple[int, int] = (1, 39)):
        self.root = root
        self.path = path  # file path, when read from a file
        self.version = version
        self.warnings: list[str] = []
        # Documents translated from another format (USD): the name each element has there (a prim
        # path), and the elements that could not be translated, with why.
        self.labels: dict[str, str] = {}
        self.failures: dict[str, ShaderGenError] = {}
        # what is read of the tree once for every element asked for (api.py: the renderable
        # elements by name and path); the tree is not changed once read
        self.memo: dict = {}

    def label(self, path: str | None) -> str | None:
        """What users call the element at `path` (or inside it): its own path for MaterialX."""
        if not self.labels or path is None:
            return path
        head, tail = path, ""
        while head not in self.labels and "/" in head:
            head, last = head.rsplit("/", 1)
            tail = f"/{last}{tail}"
        return self.labels[head] + tail if head in self.labels else path

    @property
    def directory(self) -> str | None:
        return os.path.dirname(os.path.abspath(self.path)) if self.path else None

    @property
    def colorspace(self) -> str | None:
        return self.root.get("colorspace")

    def elements(self, category: str) -> list[Element]:
        return self.root.children_of(category)


# MaterialX writes a node of another MaterialX namespace as <npr:toon_shade>, a prefix that no
# xmlns attribute declares (its parser ignores XML namespaces); expat refuses an unbound prefix, so
# each one is declared on the root element and read back as the category `npr:toon_shade`.
MATERIALX_NAMESPACE_URI = "urn:shadergen:materialx-namespace:"
_PREFIXED_TAG = re.compile(rb"<([A-Za-z_][\w.-]*):[A-Za-z_]")
_DECLARED_PREFIX = re.compile(rb"xmlns:([A-Za-z_][\w.-]*)\s*=")


def _declare_namespace_prefixes(text: bytes) -> bytes:
    prefixes = set(_PREFIXED_TAG.findall(text)) - set(_DECLARED_PREFIX.findall(text)) - {b"xml", b"xmlns"}
    if not prefixes:
        return text
    uri = MATERIALX_NAMESPACE_URI.encode()
    declarations = b"".join(b' xmlns:%s="%s%s"' % (p, uri, p) for p in sorted(prefixes))
    return re.sub(rb"<materialx\b", lambda m: b"<materialx" + declarations, text, count=1)


def _qualified(name: str) -> str:
    """Expat's name for a namespaced element or attribute (`uri}local`) as we write it: `prefix:local`
    for another MaterialX namespace (the prefix read back from its URI), else `{uri}local`."""
    uri, _, local = name.rpartition("}")
    if uri.startswith(MATERIALX_NAMESPACE_URI):
        return f"{uri[len(MATERIALX_NAMESPACE_URI):]}:{local}"
    return "{" + name


# MaterialX writes the <UDIM> and <UVTILE> filename tokens unescaped inside attribute values; its
# lenient parser accepts that, expat does not, so they are escaped before parsing.
FILENAME_TOKENS = ((b"<UDIM>", b"&lt;UDIM&gt;"), (b"<UVTILE>", b"&lt;UVTILE&gt;"))


class _NestingLimit(Exception):
    pass


class _Unsafe(Exception):
    """A DTD, an entity declaration or an external entity reference, refused where expat meets it
    (the handlers defusedxml sets): no DTD means no entity can be declared, so none is expanded."""


def _refuse(kind: str):
    def handler(*_):
        raise _Unsafe(kind)
    return handler


# expat's handler -> the refusal it raises (named as defusedxml names them: error messages keep the names)
_REFUSALS = {"StartDoctypeDeclHandler": _refuse("DTDForbidden"),
             "EntityDeclHandler": _refuse("EntitiesForbidden"),
             "UnparsedEntityDeclHandler": _refuse("EntitiesForbidden"),
             "ExternalEntityRefHandler": _refuse("ExternalReferenceForbidden")}


class _ElementBuilder:
    """Our Element tree, built in expat's callbacks. Text, comments and processing instructions
    carry nothing MaterialX reads, so they have no handler (expat still checks they are well formed)."""

    __slots__ = ("source", "open", "root")

    def __init__(self, source: str | None):
        self.source = source
        self.open: list[Element] = []  # the elements started and not yet ended, outermost first
        self.root: Element | None = None

    def start(self, name: str, attrs: dict) -> None:
        if len(self.open) == MAX_NESTING:  # refused while parsing, before the tree could cost time or stack
            raise _NestingLimit
        if "}" in name:
            name = _qualified(name)
        if any("}" in key for key in attrs):  # a namespaced attribute (xml:space), renamed in its place
            attrs = {(_qualified(key) if "}" in key else key): value for key, value in attrs.items()}
        parent = self.open[-1] if self.open else None
        elem = Element(name, attrs, parent, self.source)
        if parent is None:
            self.root = elem
        else:
            parent.children.append(elem)
        self.open.append(elem)

    def end(self, _name: str) -> None:
        self.open.pop()


# the encoding named by an XML declaration at the start of ASCII-compatible bytes
_DECLARED_ENCODING = re.compile(rb"""^\s*<\?xml\s[^>]*?\bencoding\s*=\s*["']([^"']*)["']""")
_BOMS = ((codecs.BOM_UTF32_LE, "utf-32"), (codecs.BOM_UTF32_BE, "utf-32"), (codecs.BOM_UTF8, "utf-8-sig"),
         (codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16"))
_UTF8_NAMES = ("utf-8", "utf8")


def _utf8(text: str | bytes, where: str) -> bytes:
    """The document as UTF-8 bytes whose declaration (if any) says so. Expat reads only UTF-8,
    UTF-16 and single-byte encodings itself; any other encoding Python knows (utf-32, shift_jis,
    ...) is decoded here, and one it does not know is an invalid document, not a crash."""
    if isinstance(text, bytes):
        encoding = next((name for bom, name in _BOMS if text.startswith(bom)), None)
        if encoding is None:
            declared = _DECLARED_ENCODING.match(text[:1024])
            encoding = declared.group(1).decode("ascii", "replace").lower() if declared else "utf-8"
            if encoding in _UTF8_NAMES:
                return text  # the common case, left to expat as it is
        try:
            text = text.decode(encoding)
        except LookupError:
            raise ShaderGenError("invalid_document", f"unknown encoding {encoding!r} in the XML declaration",
                                 f"{where}:1:1") from None
        except UnicodeDecodeError as e:
            raise ShaderGenError("invalid_document", f"the document is not valid {encoding}: {e.reason}",
                                 f"{where}: byte {e.start}") from None
    # the text is decoded now: what its declaration names no longer applies
    text = re.sub(r"""^(\ufeff?\s*<\?xml\s[^>]*?\bencoding\s*=\s*)(["'])[^"']*\2""", r"\1\2utf-8\2", text, count=1)
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError as e:
        raise ShaderGenError("invalid_document", f"the document contains an unpaired surrogate ({e.reason})",
                             f"{where}: character {e.start}") from None


def _parse_text(text: str | bytes, where: str, source: str | None) -> Element:
    if len(text) > MAX_DOCUMENT_BYTES:
        raise ShaderGenError("too_large", f"document is larger than {MAX_DOCUMENT_BYTES} bytes", where)
    text = _utf8(text, where)
    for raw, escaped in FILENAME_TOKENS:
        text = text.replace(raw, escaped)
    text = _declare_namespace_prefixes(text)
    parser = expat.ParserCreate(namespace_separator="}")
    builder = _ElementBuilder(source)
    parser.StartElementHandler = builder.start
    parser.EndElementHandler = builder.end
    for handler, refusal in _REFUSALS.items():
        setattr(parser, handler, refusal)
    try:
        parser.Parse(text, True)
    except _Unsafe as e:
        raise ShaderGenError("unsafe_xml", f"refused unsafe XML ({e}): DTDs and entities are not allowed",
                             where) from None
    except _NestingLimit:
        line, col = parser.CurrentLineNumber, parser.CurrentColumnNumber
        raise ShaderGenError("invalid_document", f"elements nested deeper than {MAX_NESTING} levels",
                             f"{where}:{line}:{col}") from None
    except expat.ExpatError as e:
        raise ShaderGenError("invalid_document", f"malformed XML: {e}", f"{where}:{e.lineno}:{e.offset}") from None
    return builder.root


class IncludeRoots:
    """Where an upload's `xi:include` may read from: files under these folders only, each href
    relative (to the root, or to the folder of the file that includes it) and confined to the
    root it was found in, as a texture is confined to the texture roots. An included file's
    relative `fileprefix` is made absolute: its textures are where its own folder says, whatever
    folder the upload has (it has none)."""

    def __init__(self, roots):
        self.roots = [os.path.realpath(r) for r in roots]

    def resolve(self, href: str, from_dir: str | None) -> str:
        if os.path.isabs(href) or "://" in href or "\x00" in href or "\\" in href:
            raise ShaderGenError("include_refused", f"xi:include of '{href}': only relative paths inside the "
                                 "include roots may be included", href)
        leaves = False
        for root in (r for r in self.roots if from_dir is None or inside(from_dir, r)):
            named = os.path.join(from_dir or root, href)
            real = os.path.realpath(named)
            if inside(real, root):
                if os.path.isfile(real):
                    return real
            elif os.path.lexists(named) or not inside(os.path.normpath(named), root):
                leaves = True  # by its name, or through a link
        if leaves:
            raise ShaderGenError("include_refused", f"xi:include of '{href}' leaves the include roots", href)
        raise ShaderGenError("invalid_document", f"cannot read included file '{href}': not in the include roots",
                             href)


def _expand_includes(root: Element, base_dir: str | None, allow: bool, seen: tuple[str, ...],
                     roots: IncludeRoots | None = None) -> None:
    for inc in [c for c in root.children if c.category == XINCLUDE]:
        href = inc.get("href", "")
        if allow and base_dir is not None:
            path = os.path.normpath(os.path.join(base_dir, href))
        elif roots is not None:
            path = roots.resolve(href, base_dir)
        else:
            raise ShaderGenError("include_refused", f"xi:include of '{href}' is not allowed here", href)
        if path in seen or len(seen) > MAX_INCLUDE_DEPTH:
            raise ShaderGenError("invalid_document", f"recursive xi:include of '{href}'", href)
        try:
            with open(path, "rb") as f:
                text = f.read()
        except OSError as e:
            raise ShaderGenError("invalid_document", f"cannot read included file '{href}': {e.strerror}", href) from None
        included = _parse_text(text, path, path)
        if roots is not None and not allow:
            _absolute_fileprefix(included, os.path.dirname(path))
        _expand_includes(included, os.path.dirname(path), allow, seen + (path,), roots)
        index = root.children.index(inc)
        root.remove_child(inc)
        for offset, child in enumerate(included.children):
            for key in SCOPED_ATTRIBUTES:  # what the included root said still holds for its elements
                if included.get(key) is not None and child.get(key) is None:
                    child.attrs[key] = included.get(key)
            root.add_child(child, index + offset)


def _absolute_fileprefix(included: Element, folder: str) -> None:
    """A relative fileprefix of a file included from the roots, made absolute from its folder
    (on any of its elements: the root's is inherited, and so is a nodegraph's)."""
    pending = [included]
    while pending:
        element = pending.pop()
        prefix = element.get("fileprefix")
        if prefix and not os.path.isabs(prefix) and "://" not in prefix:
            element.attrs["fileprefix"] = os.path.join(os.path.normpath(os.path.join(folder, prefix)), "")
        pending.extend(element.children)


def parse_document(text: str | bytes, *, path: str | None = None, base_dir: str | None = None,
                   allow_includes: bool = True, include_roots=()) -> Document:
    """Parse MaterialX XML text. `base_dir` resolves includes (defaults to the file's folder);
    an upload (no includes allowed) may still include files under `include_roots`, confined."""
    where = path or "<document>"
    root = _parse_text(text, where, path)
    if root.category != "materialx":
        raise ShaderGenError("invalid_document", f"root element is <{root.category}>, expected <materialx>", where)
    if base_dir is None and path:
        base_dir = os.path.dirname(os.path.abspath(path))
    _expand_includes(root, base_dir, allow_includes, (os.path.abspath(path),) if path else (),
                     IncludeRoots(include_roots) if include_roots else None)
    doc = Document(root=root, path=path, version=_version(root.get("version", "1.39")))
    upgrade(doc)
    return doc


def read_document(path: str, *, allow_includes: bool = True) -> Document:
    try:
        with open(path, "rb") as f:
            text = f.read()
    except OSError as e:
        raise ShaderGenError("invalid_document", f"cannot read document: {e.strerror}", path) from None
    return parse_document(text, path=path, allow_includes=allow_includes)


def _version(text: str) -> tuple[int, int]:
    try:
        major, minor = text.split(".")[:2]
        return int(major), int(minor)
    except ValueError:
        return (1, 39)
