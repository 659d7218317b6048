"""References and payloads to MaterialX documents, composed as USD's MaterialX file-format plugin
(usdMtlx) composes them. The usd-core wheel lacks that plugin, so such an arc composes nothing
there: each one is taken out of its layer before the stage is composed, and its document is read
with our MaterialX reader instead.

usdMtlx presents a document as a layer whose default prim `/MaterialX` holds each material at
`/MaterialX/Materials/<name>`. An arc whose target is prim path P (the default prim when it names
none) makes the referencing prim stand for the materials at or below P: itself for
`</MaterialX/Materials/Wood>`, `<prim>/Materials/Wood` for the default prim. Each such material
becomes a surfacematerial named by that prim path, over the document's shaders and node graphs,
which join the translated document once per document, under their own names (with the document's
folder as their fileprefix, relative to the layer's folder or the package's root).
"""
import os
import posixpath
from typing import NamedTuple

from .document import SCOPED_ATTRIBUTES, Document, parse_document, read_document
from .element import Element
from .errors import ShaderGenError
from .usd import _pxr, anchor

DEFAULT_PRIM = "/MaterialX"
MATERIALS = "/MaterialX/Materials/"
ARC_FIELDS = ("references", "payload")
LIST_FIELDS = ("prependedItems", "appendedItems", "addedItems", "deletedItems", "orderedItems")


class MtlxArc(NamedTuple):
    document: str  # the document's path anchored to the layer that names it
    target: str  # the prim path of the arc in usdMtlx's layout


def _is_mtlx(item) -> bool:
    return item.assetPath.lower().endswith(".mtlx")


def _without_mtlx(op):
    """The list op with its MaterialX items removed (every list of it, deleted items too)."""
    if op.isExplicit:
        return type(op).CreateExplicit([i for i in op.explicitItems if not _is_mtlx(i)])
    new = type(op)()
    for field in LIST_FIELDS:
        setattr(new, field, [i for i in getattr(op, field) if not _is_mtlx(i)])
    return new


def take_mtlx_arcs(layers) -> dict[tuple[str, str], list[MtlxArc]]:
    """Removes the MaterialX references and payloads from the layers' prim specs (variants too);
    the arcs each spec held, keyed by (layer identifier, spec path)."""
    arcs: dict[tuple[str, str], list[MtlxArc]] = {}
    for layer in layers:
        specs = []
        layer.Traverse(layer.pseudoRoot.path, lambda path: specs.append(path)
                       if path.IsPrimPath() or path.IsPrimVariantSelectionPath() else None)
        for path in specs:
            spec = layer.GetPrimAtPath(path)
            if spec is None:  # a variant set's own path (`{look=}`): its variants are visited as prims
                continue
            for field in ARC_FIELDS:
                op = spec.GetInfo(field) if spec.HasInfo(field) else None
                items = [i for i in op.GetAddedOrExplicitItems() if _is_mtlx(i)] if op else []
                if not items:
                    continue
                arcs.setdefault((layer.identifier, str(path)), []).extend(
                    MtlxArc(anchor(layer, i.assetPath), str(i.primPath) if i.primPath else DEFAULT_PRIM)
                    for i in items)
                spec.SetInfo(field, _without_mtlx(op))
    return arcs


def arcs_of(prim, arcs: dict) -> list[MtlxArc]:
    """The MaterialX arcs a composed prim's specs held, strongest first."""
    return [a for spec in prim.GetPrimStack() for a in arcs.get((spec.layer.identifier, str(spec.path)), ())]


def read_mtlx(anchored: str) -> Document:
    """A document beside a file is read as a file (its includes with it); a package member is
    read through usd-core's resolver, which reads it from the package, and may include nothing."""
    _pxr()
    from pxr import Ar

    if not Ar.IsPackageRelativePath(anchored):
        return read_document(anchored)
    member = Ar.SplitPackageRelativePathOuter(anchored)[1]
    asset = Ar.GetResolver().OpenAsset(Ar.ResolvedPath(anchored))
    if asset is None:
        raise ShaderGenError("invalid_document", f"the package holds no '{member}'", member)
    return parse_document(bytes(asset.GetBuffer()), path=None, allow_includes=False)


class MtlxMaterials:
    """The materials of MaterialX arcs, added to the translated document's root."""

    def __init__(self, root: Element, translator, document_dir: str | None):
        self.root, self.translator = root, translator
        self.document_dir = document_dir  # the folder filenames are relative to (None: a package's root)
        self.documents: dict[str, dict[str, Element]] = {}  # anchored path -> its materials by name

    def materials(self, prim, arcs: list[MtlxArc]) -> list[tuple[str, Element]]:
        """(composed prim path, surfacematerial) for each material the prim's arcs name."""
        prim_path = str(prim.GetPath())
        found = []
        for arc in arcs:
            for name, material in self._document(arc.document).items():
                source = MATERIALS + name
                if source == arc.target:
                    found.append((prim_path, material))
                elif source.startswith(arc.target.rstrip("/") + "/"):
                    found.append((prim_path + source[len(arc.target.rstrip("/")):], material))
        if not found:
            named = ", ".join(f"{a.target} of '{a.document.rsplit('[', 1)[-1].rstrip(']')}'" for a in arcs)
            raise ShaderGenError("invalid_document", f"the MaterialX reference names no material ({named})", prim_path)
        return [(path, self._material(path, material)) for path, material in found]

    def _material(self, prim_path: str, source: Element) -> Element:
        name = self.translator.unique_name(prim_path)
        material = Element("surfacematerial", {**source.attrs, "name": name})
        for child in source.children:
            material.add_child(Element(child.category, dict(child.attrs)))
        return material

    def _document(self, anchored: str) -> dict[str, Element]:
        """The document's materials; its other elements join the root on first use."""
        if anchored in self.documents:
            return self.documents[anchored]
        doc = read_mtlx(anchored)
        folder = self._folder(anchored)
        materials = {}
        for child in list(doc.root.children):
            if child.category == "surfacematerial" or child.get("type") == "material":
                materials[child.name] = child
                continue
            if child.name in self.translator.names:
                raise ShaderGenError("invalid_document", f"element '{child.name}' of the MaterialX document is also "
                                     "an element of the translated scene", child.name)
            for key in SCOPED_ATTRIBUTES:  # what the document's root said still holds for its elements
                if doc.root.get(key) is not None and child.get(key) is None:
                    child.attrs[key] = doc.root.get(key)
            if folder:
                child.attrs["fileprefix"] = folder + child.get("fileprefix", "")
            self.translator.names.add(child.name)
            self.root.add_child(child)
        self.documents[anchored] = materials
        return materials

    def _folder(self, anchored: str) -> str:
        """The document's folder as a fileprefix (`materials/`): its filenames are relative to it,
        the translated document's to the layer's folder or the package's root."""
        from pxr import Ar

        if Ar.IsPackageRelativePath(anchored):
            folder = posixpath.dirname(Ar.SplitPackageRelativePathOuter(anchored)[1])
        else:
            folder = os.path.relpath(os.path.dirname(anchored), self.document_dir or os.path.dirname(anchored))
        return "" if folder in ("", ".") else folder.replace(os.sep, "/") + "/"
