"""USD stage (usd-core) -> Document: the UsdShade material networks of a .usda, .usdc or .usdz.

A file named by its path composes as any USD tool opens it. An upload is confined to itself: a
text layer may refer to no other file, a usdz package only to layers inside the package, and an
asset path that leaves a package is refused as a texture outside the roots is. Each material
becomes a `surfacematerial` element (see usd_network.py for the networks); the document's
`labels` give every element its prim path, which records and errors use as `element`/`where`.
"""
import os
import posixpath
import re
from contextlib import contextmanager

from .archives import check_usdz
from .document import Document
from .element import Element
from .errors import ShaderGenError
from .library import Library, Scope

USD_SUFFIXES = (".usda", ".usdc", ".usd", ".usdz")
UPLOAD_FORMATS = ("usda", "usdz")
# UsdPreviewSurface values are linear Rec.709, the working space our colour transforms target.
WORKING_COLORSPACE = "lin_rec709"


def is_usd_path(path: str) -> bool:
    return path.lower().endswith(USD_SUFFIXES)


def _pxr():
    try:
        from pxr import Sdf, Tf, Usd, UsdShade
    except ImportError:
        raise ShaderGenError("unsupported_format", "reading USD needs usd-core: pip install 'shadergen[usd]'") from None
    return Sdf, Tf, Usd, UsdShade


@contextmanager
def usd_errors(where: str):
    """usd-core's errors (Tf.ErrorException) as invalid_document, at the prim they name if any."""
    _, Tf, _, _ = _pxr()
    try:
        yield
    except Tf.ErrorException as exc:
        first = str(exc).strip().split("\n\tError in ")[0]
        message = first.split(" : '", 1)[-1].rstrip("'").strip()
        prim = re.search(r"in <(/[^>]+)>", message)
        raise ShaderGenError("invalid_document", f"malformed USD: {message}", prim.group(1) if prim else where) from None


def anchor(layer, asset: str) -> str:
    """An asset path made absolute against the layer that wrote it. USD leaves a search-relative
    path (`tex.png`, not `./tex.png`) that it cannot find as written; it is anchored as if it
    were `./tex.png`, so it names one place, inside the layer's folder or package."""
    anchored = layer.ComputeAbsolutePath(asset)
    if os.path.isabs(anchored) or "://" in asset:
        return anchored
    return layer.ComputeAbsolutePath("./" + asset)


def package_member(anchored: str, package: str) -> str | None:
    """The member path of `package[member]`, or None for a path that is not inside the package."""
    if not (anchored.startswith(package + "[") and anchored.endswith("]")):
        return None
    member = anchored[len(package) + 1:-1]
    normal = posixpath.normpath(member)
    return None if posixpath.isabs(member) or normal == ".." or normal.startswith("../") else member


class AssetPaths:
    """Filename values for asset paths. In a package: the member, named `label[member]` when the
    package is a file beside the document (the renderer reads members), bare for an upload.
    In a file: relative to the document's folder when inside it. In an uploaded layer: as written."""

    def __init__(self, document_dir: str | None = None, package: str | None = None, label: str | None = None):
        self.document_dir, self.package, self.label = document_dir, package, label

    def __call__(self, attr, value, where: str) -> str:
        _, _, Usd, _ = _pxr()
        authored = value.path
        if not authored or "<UDIM>" in authored or (self.document_dir is None and self.package is None):
            return authored
        stack = attr.GetPropertyStack(Usd.TimeCode.Default())
        anchored = anchor(stack[0].layer, authored) if stack else authored
        if self.package is not None:
            member = package_member(anchored, self.package)
            if member is None:
                raise ShaderGenError("path_not_allowed", f"asset '{authored}' leaves the usdz package", where)
            return f"{self.label}[{member}]" if self.label else member
        if not os.path.isabs(anchored):
            return authored  # a URI or a resolver's own identifier: as written
        inside = os.path.commonpath([anchored, self.document_dir]) == self.document_dir
        return os.path.relpath(anchored, self.document_dir) if inside else anchored


def _confine_to_package(layer, package: str) -> None:
    """Every layer the package's root layer composes (sublayers, references, payloads) must lie
    inside the package; checked before the stage opens any of them."""
    Sdf, _, _, _ = _pxr()
    todo, seen = [layer], set()
    while todo:
        current = todo.pop()
        for dep in current.GetCompositionAssetDependencies():
            anchored = anchor(current, dep)
            if package_member(anchored, package) is None:
                raise ShaderGenError("path_not_allowed", f"layer '{dep}' leaves the usdz package", dep)
            if anchored not in seen:
                seen.add(anchored)
                with usd_errors(dep):
                    sub = Sdf.Layer.FindOrOpen(anchored)
                if sub is not None:
                    todo.append(sub)


def read_usd(path: str, library: Library) -> Document:
    Sdf, _, _, _ = _pxr()
    if not os.path.isfile(path):
        raise ShaderGenError("invalid_document", "cannot read document: no such file", path)
    with usd_errors(path):
        layer = Sdf.Layer.FindOrOpen(os.path.abspath(path))
    if layer is None:
        raise ShaderGenError("invalid_document", "cannot open the USD layer", path)
    absolute = os.path.abspath(path)
    if path.lower().endswith(".usdz"):
        _confine_to_package(layer, absolute)
        assets = AssetPaths(package=absolute, label=os.path.basename(path))
    else:
        assets = AssetPaths(document_dir=os.path.dirname(absolute))
    return _translate(layer, library, path, assets)


def parse_usd(data: bytes, document_format: str, library: Library) -> Document:
    """An uploaded layer (`usda` text) or package (`usdz`), confined to itself."""
    Sdf, _, _, _ = _pxr()
    if document_format == "usda":
        try:
            text = data.decode("utf-8-sig") if isinstance(data, bytes) else data
        except UnicodeDecodeError as exc:
            raise ShaderGenError("invalid_document", f"the layer is not UTF-8: {exc.reason}", f"byte {exc.start}") from None
        layer = Sdf.Layer.CreateAnonymous(".usda")
        with usd_errors("<document>"):
            layer.ImportFromString(text)
        deps = layer.GetCompositionAssetDependencies()
        if deps:
            raise ShaderGenError("include_refused", f"an uploaded layer may not refer to other files ('{deps[0]}')",
                                 deps[0])
        return _translate(layer, library, None, AssetPaths())
    if document_format == "usdz":
        if not data.startswith(b"PK\x03\x04"):
            raise ShaderGenError("invalid_document", "the upload is not a usdz package (a zip archive)", "<document>")
        check_usdz(data)  # stored members only, a directory that agrees with the bytes: before usd-core reads any
        import tempfile  # here, like usd-core and the translator: a MaterialX-only process never loads them

        with tempfile.TemporaryDirectory(prefix="shadergen-usdz-") as folder:
            package = os.path.join(folder, "upload.usdz")
            with open(package, "wb") as f:
                f.write(data)
            with usd_errors("<document>"):
                layer = Sdf.Layer.FindOrOpen(package)
            if layer is None:
                raise ShaderGenError("invalid_document", "the package holds no USD layer", "<document>")
            _confine_to_package(layer, package)
            return _translate(layer, library, None, AssetPaths(package=package))
    raise ShaderGenError("unsupported_format", f"unknown USD format '{document_format}'", document_format)


def _translate(layer, library: Library, path: str | None, assets: AssetPaths) -> Document:
    from .usd_network import NetworkTranslator

    _, _, Usd, UsdShade = _pxr()
    with usd_errors(path or "<document>"):
        stage = Usd.Stage.Open(layer)
    root = Element("materialx", {"version": "1.39", "colorspace": WORKING_COLORSPACE}, None, path)
    doc = Document(root=root, path=path)
    doc.warnings.extend(f"USD composition: {e}" for e in stage.GetCompositionErrors())
    translator = NetworkTranslator(Scope(library, None), root, assets, doc.warnings)
    for prim in stage.Traverse():
        if not prim.IsA(UsdShade.Material):
            continue
        name = translator.unique_name(str(prim.GetPath()))
        try:
            with usd_errors(str(prim.GetPath())):
                material = translator.material(UsdShade.Material(prim), name)
        except ShaderGenError as exc:  # one bad material does not hide the others
            material = Element("surfacematerial", {"name": name, "type": "material"})
            doc.failures[name] = exc
        root.add_child(material)
        doc.labels[name] = str(prim.GetPath())
    doc.labels.update(translator.labels)
    return doc
