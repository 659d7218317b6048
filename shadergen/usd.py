"""USD stage (usd-core) -> Document: the UsdShade material networks of a .usda, .usdc or .usdz.

A file named by its path composes as any USD tool opens it. An upload is confined to itself
before any stage is composed (usd_confine.py): a text layer may refer to no other file, a usdz
package only to its own members, and a texture that leaves a package is refused as a texture
outside the roots is. References and payloads to MaterialX documents are composed as usdMtlx
would compose them, with our reader (usd_mtlx.py). Each material
becomes a `surfacematerial` element (see usd_network.py for the networks); the document's
`labels` give every element its prim path, which records and errors use as `element`/`where`.
"""
import os
import posixpath
import re
from contextlib import contextmanager

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
    """usd-core's errors (Tf.ErrorException) as invalid_document, at the prim they name if any;
    text of a layer that is not UTF-8 (a crate's tokens), which usd-core hands Python as it is."""
    _, Tf, _, _ = _pxr()
    try:
        yield
    except UnicodeDecodeError as exc:
        raise ShaderGenError("invalid_document", f"malformed USD: text that is not UTF-8 ({exc.reason})",
                             where) from None
    except Tf.ErrorException as exc:
        try:
            text = str(exc)
        except UnicodeDecodeError:  # the message quotes the layer's bytes, which are not UTF-8
            raise ShaderGenError("invalid_document", "malformed USD: text that is not UTF-8", where) from None
        first = text.strip().split("\n\tError in ")[0]
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


def _composed_layers(layer) -> list:
    """The layer and those it composes as usd-core would open them (a file on the command line
    composes as USD tools open it), for the MaterialX arcs in any of them; one that does not open
    is left to the stage, which reports it as a composition error."""
    Sdf, Tf, _, _ = _pxr()
    layers, todo = {layer.identifier: layer}, [layer]
    while todo:
        current = todo.pop()
        for dep in current.GetCompositionAssetDependencies():
            anchored = anchor(current, dep)
            if anchored in layers or dep.lower().endswith(".mtlx"):
                continue
            try:
                sub = Sdf.Layer.FindOrOpen(anchored)
            except Tf.ErrorException:
                sub = None
            if sub is not None:
                layers[anchored] = sub
                todo.append(sub)
    return list(layers.values())


def _open_package(package: str) -> tuple:
    """The package's root layer and every layer of it, each checked to stay inside it."""
    from .usd_confine import confine_package

    layers = confine_package(package)
    root = next((layer for layer in layers if layer.identifier == package), None)
    if root is None:
        raise ShaderGenError("invalid_document", "the package holds no USD layer", "<document>")
    return root, layers


def read_usd(path: str, library: Library) -> Document:
    Sdf, _, _, _ = _pxr()
    if not os.path.isfile(path):
        raise ShaderGenError("invalid_document", "cannot read document: no such file", path)
    absolute = os.path.abspath(path)
    if path.lower().endswith(".usdz"):
        layer, layers = _open_package(absolute)
        return _translate(layer, layers, library, path, AssetPaths(package=absolute, label=os.path.basename(path)))
    with usd_errors(path):
        layer = Sdf.Layer.FindOrOpen(absolute)
    if layer is None:
        raise ShaderGenError("invalid_document", "cannot open the USD layer", path)
    return _translate(layer, _composed_layers(layer), library, path, AssetPaths(document_dir=os.path.dirname(absolute)))


def parse_usd(data: bytes, document_format: str, library: Library) -> Document:
    """An uploaded layer (`usda` text) or package (`usdz`), confined to itself (usd_confine.py)."""
    Sdf, _, _, _ = _pxr()
    from .usd_budget import check_composed_size

    if document_format == "usda":
        from .usd_confine import confine_layer

        try:
            text = data.decode("utf-8-sig") if isinstance(data, bytes) else data
        except UnicodeDecodeError as exc:
            raise ShaderGenError("invalid_document", f"the layer is not UTF-8: {exc.reason}", f"byte {exc.start}") from None
        layer = Sdf.Layer.CreateAnonymous(".usda")

        def translate():
            with usd_errors("<document>"):
                layer.ImportFromString(text)
                confine_layer(layer)
                check_composed_size(layer, [layer])
            return _translate(layer, [layer], library, None, AssetPaths())

        return _in_public(translate, None)
    if document_format == "usdz":
        if not data.startswith(b"PK\x03\x04"):
            raise ShaderGenError("invalid_document", "the upload is not a usdz package (a zip archive)", "<document>")
        import tempfile  # here, like usd-core and the translator: a MaterialX-only process never loads them

        from .archives import check_usdz  # zipfile brings shutil and pathlib: USD uploads only

        check_usdz(data)  # stored members only, a directory that agrees with the bytes: before usd-core reads any

        with tempfile.TemporaryDirectory(prefix="shadergen-usdz-") as folder:
            package = os.path.join(folder, "upload.usdz")
            with open(package, "wb") as f:
                f.write(data)

            def translate():
                layer, layers = _open_package(package)
                with usd_errors("<document>"):
                    check_composed_size(layer, layers)
                return _translate(layer, layers, library, None, AssetPaths(package=package))

            return _in_public(translate, folder)
    raise ShaderGenError("unsupported_format", f"unknown USD format '{document_format}'", document_format)


# usd-core names an anonymous layer (an uploaded text layer, every stage's session layer) by its
# address, `anon:0x55d0c3a4b2c0:.usda`, and an object by a pointer, `<0x55d0c3a4b2c0>`
_ADDRESS = re.compile(r"0x[0-9a-fA-F]+")


def public_text(text: str, folder: str | None) -> str:
    """A text of usd-core's about an upload as a client may read it: no address of the server's
    process (which would show where its heap lies) and no server folder (a package's temporary
    folder, `/tmp/shadergen-usdz-x/upload.usdz[scene.usda]:2:5`, is `upload.usdz[scene.usda]:2:5`)."""
    if folder:
        text = text.replace(folder + os.sep, "")
    return _ADDRESS.sub("0x", text)


def _in_public(translate, folder: str | None) -> Document:
    """The document `translate` makes of an upload, or its refusal, with every text that leaves
    the reader (the error, warnings, each failed material) in public_text: one exit that no
    message of usd-core's passes by, whichever step made it."""
    try:
        doc = translate()
    except ShaderGenError as exc:
        raise _public_error(exc, folder) from None
    doc.warnings[:] = [public_text(w, folder) for w in doc.warnings]
    for exc in doc.failures.values():
        _public_error(exc, folder)
    return doc


def _public_error(exc: ShaderGenError, folder: str | None) -> ShaderGenError:
    exc.message = public_text(exc.message, folder)
    exc.where = public_text(exc.where, folder) if exc.where else exc.where
    return exc


# usd-core reports an error per composed prim that meets it: one cycle under a prim referenced
# 64 times gave 128 errors of 79 kB from a 2 kB layer. The first few say what is wrong.
MAX_COMPOSITION_WARNINGS = 10


def _composition_warnings(errors: list) -> list[str]:
    warnings = [f"USD composition: {e}" for e in errors[:MAX_COMPOSITION_WARNINGS]]
    if len(errors) > MAX_COMPOSITION_WARNINGS:
        warnings.append(f"USD composition: {len(errors) - MAX_COMPOSITION_WARNINGS} more errors not listed")
    return warnings


def _translate(layer, layers: list, library: Library, path: str | None, assets: AssetPaths) -> Document:
    """The stage of `layer` as a document; `layers` (every layer it composes that was opened
    before it) lose their MaterialX arcs to usd_mtlx.py first, and stay alive while it composes."""
    from .usd_mtlx import MtlxMaterials, arcs_of, take_mtlx_arcs
    from .usd_network import NetworkTranslator

    _, _, Usd, UsdShade = _pxr()
    with usd_errors(path or "<document>"):
        mtlx_arcs = take_mtlx_arcs(layers)
        stage = Usd.Stage.Open(layer)
    root = Element("materialx", {"version": "1.39", "colorspace": WORKING_COLORSPACE}, None, path)
    doc = Document(root=root, path=path)
    doc.warnings.extend(_composition_warnings(stage.GetCompositionErrors()))
    translator = NetworkTranslator(Scope(library, None), root, assets, doc.warnings)
    mtlx = MtlxMaterials(root, translator, assets.document_dir)
    with usd_errors(path or "<document>"):  # a crate is read as the stage is walked: it may be corrupt there
        prims = list(stage.Traverse())
    for prim in prims:
        arcs = arcs_of(prim, mtlx_arcs) if mtlx_arcs else []
        if arcs:
            _add_materials(doc, str(prim.GetPath()), lambda: mtlx.materials(prim, arcs), translator)
        elif prim.IsA(UsdShade.Material):
            name = translator.unique_name(str(prim.GetPath()))
            _add_materials(doc, str(prim.GetPath()),
                           lambda: [(str(prim.GetPath()), translator.material(UsdShade.Material(prim), name))],
                           translator, name)
    doc.labels.update(translator.labels)
    return doc


def _add_materials(doc: Document, where: str, translate, translator, name: str | None = None) -> None:
    """The materials `translate` makes for one prim, each labelled by its prim path; when it fails,
    one failed material in its place, so that one bad material does not hide the others."""
    try:
        with usd_errors(where):
            materials = translate()
    except ShaderGenError as exc:
        name = name or translator.unique_name(where)
        materials = [(where, Element("surfacematerial", {"name": name, "type": "material"}))]
        doc.failures[name] = exc
    for prim_path, material in materials:
        doc.root.add_child(material)
        doc.labels[material.name] = prim_path
