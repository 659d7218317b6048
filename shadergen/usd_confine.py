"""Uploads confined by construction: no file outside an upload is opened, whatever field names it.

Before any stage is composed, every layer of the upload is opened with Sdf alone (which reads
that one layer and nothing it names) and every asset path in it is listed by usd-core's own
enumeration, `UsdUtils.ModifyAssetPaths`: sublayers, references, payloads, value clips with their
manifests and templates, asset-valued attributes and metadata, in variants too. A field it lists
that this module has never heard of is confined all the same: the one kind of path let through
as written is the value of an asset-typed attribute (a texture), which usd-core never opens
(resolving it is at most a stat); what the translator does with those is usd.py's `AssetPaths`.
Expressions (`...`) are evaluated by that enumeration; a layer that defines expression variables
is refused, since the path its expressions name would depend on where it is composed.
Every other path must lie inside the upload: an uploaded layer has no inside, so it may name no
other file; a package's paths must be members of it (nested packages included), and a
search-relative one (`x`, not `./x`) an existing member, since usd-core looks such a path up in
its working directory when it is not beside its layer. Every layer member of a package
is checked, not only the ones the root names: a clip template expands to members that no field
names. A refusal names the path as written and is decided before anything outside is touched,
so its answer is the same whether that file exists or not.
"""
import posixpath

from .errors import ShaderGenError
from .usd import _pxr, anchor, usd_errors

ASSET_TYPES = ("asset", "asset[]")
# Every layer member of a package is opened and walked before the stage composes (about 0.7 ms
# each, empty): a package of 15,000 empty layers held a generator child for its whole time limit.
# Field packages hold a handful; this many costs under a second.
MAX_PACKAGE_LAYERS = 1000
FORMAT_ARGS = ":SDF_FORMAT_ARGS:"


def _asset_attributes(layer) -> list:
    """The paths of the layer's asset-typed attribute specs, in every prim and variant. A path the
    layer lists without a spec (a corrupt crate's child) is refused here: usd-core's own walks of
    the layer, ModifyAssetPaths among them, abort the process on it."""
    found, missing = [], []

    def visit(path):
        spec_path = path.IsPrimPath() or path.IsPrimVariantSelectionPath() or path.IsPrimPropertyPath()
        # (a connection's target is no spec of its own; an empty path is a child with no name)
        if path.isEmpty or spec_path and layer.GetObjectAtPath(path) is None:
            missing.append(path)
        spec = layer.GetAttributeAtPath(path) if path.IsPropertyPath() else None
        if spec is not None and str(spec.typeName) in ASSET_TYPES:
            found.append(path)

    layer.Traverse(layer.pseudoRoot.path, visit)
    if missing:
        where = str(missing[0]) or "<document>"
        raise ShaderGenError("invalid_document", f"malformed USD: the layer names {where} but holds no spec there",
                             where)
    return found


def _values(layer, attributes: list) -> set[str]:
    """The asset paths these attributes hold as values (default and time samples)."""
    Sdf, _, _, _ = _pxr()
    found = set()
    for path in attributes:
        spec = layer.GetAttributeAtPath(path)
        values = [spec.default] if spec.HasDefaultValue() else []
        values += [layer.QueryTimeSample(path, t) for t in layer.ListTimeSamplesForPath(path)]
        for value in values:  # anything but an asset path or an array of them (a block) names no path
            assets = [value] if isinstance(value, Sdf.AssetPath) else value if isinstance(value, Sdf.AssetPathArray) \
                else []
            found.update(asset.path for asset in assets if asset.path)
    return found


def _listed_paths(layer) -> set[str]:
    """Every asset path usd-core lists in the layer (each unique path once), expressions evaluated."""
    from pxr import UsdUtils

    listed = set()

    def note(path: str) -> str:
        listed.add(path)
        return path

    UsdUtils.ModifyAssetPaths(layer, note)
    return listed


def opened_paths(layer) -> list[str]:
    """The layer's asset paths that usd-core may open: every one it lists but texture values.
    Those are told apart on a copy of the layer whose asset attributes hold no value, since usd-core
    lists each unique path once: a reference to a texture's own path is listed by the copy."""
    Sdf, _, _, _ = _pxr()
    if layer.HasExpressionVariables():  # an expression's path then depends on where it is composed
        raise ShaderGenError("path_not_allowed", "a layer of the upload defines expression variables, which make "
                             "asset paths that only composition decides", "<document>")
    attributes = _asset_attributes(layer)
    copy = Sdf.Layer.CreateAnonymous(".usda")
    copy.TransferContent(layer)
    for path in attributes:
        spec = copy.GetAttributeAtPath(path)
        spec.ClearDefaultValue()
        for t in copy.ListTimeSamplesForPath(path):
            copy.EraseTimeSample(path, t)
    values = _values(layer, attributes)
    return sorted(_listed_paths(copy) | {p for p in values if not _inert(p)})


def _confinable(path: str) -> bool:
    """Not an expression (which names a path only once evaluated against variables) and without
    file format arguments: a path that names one place as written."""
    return not path.startswith("`") and FORMAT_ARGS not in path


def _inert(path: str) -> bool:
    """A value usd-core resolves without opening anything: resolving `a.usdz[b]` opens a.usdz."""
    from pxr import Ar

    return _confinable(path) and not Ar.IsPackageRelativePath(path)


def confine_layer(layer) -> None:
    """An uploaded layer has no inside: it may name no file but the textures of its attributes."""
    opened = opened_paths(layer)
    if opened:
        raise ShaderGenError("include_refused", f"an uploaded layer may not refer to other files ('{opened[0]}')",
                             opened[0])


def inside(anchored: str, package: str) -> bool:
    """Whether an anchored path is a member of `package` (at any depth of nested packages)."""
    from pxr import Ar

    outer, inner = Ar.SplitPackageRelativePathOuter(anchored)
    if outer != package or not inner:
        return False
    while inner:
        member, inner = Ar.SplitPackageRelativePathOuter(inner)
        normal = posixpath.normpath(member)
        if posixpath.isabs(member) or normal == ".." or normal.startswith("../") or "://" in member:
            return False
    return True


def _search_relative(path: str) -> bool:
    """`x/y`, which usd-core looks up in its working directory when no member of that name is
    beside the layer (`./x/y` is looked up beside the layer only)."""
    return not path.startswith(("./", "../", "/"))


def _is_layer(path: str) -> bool:
    """Whether a path (the innermost member of a package-relative one) is in a layer format."""
    Sdf, _, _, _ = _pxr()
    from pxr import Ar

    innermost = Ar.SplitPackageRelativePathInner(path)[1] if Ar.IsPackageRelativePath(path) else path
    extension = posixpath.splitext(innermost)[1][1:].lower()
    # (a name without one, `LICENSE`, is none: asked for the empty extension, usd-core raises)
    return bool(extension) and Sdf.FileFormat.FindByExtension(extension) is not None


def _members(package: str) -> list[str]:
    """Every member of the package and of the packages inside it, as package-relative paths."""
    Sdf, _, _, _ = _pxr()
    from pxr import Ar

    found, todo = [], [package]
    while todo:
        current = todo.pop()
        with usd_errors("<document>"):
            archive = Sdf.ZipFile.Open(current)
        if archive is None:
            raise ShaderGenError("invalid_document", "a usdz package of the upload is not a zip archive", "<document>")
        for name in archive.GetFileNames():
            found.append(Ar.JoinPackageRelativePath([current, name]))
            if name.lower().endswith(".usdz"):
                todo.append(found[-1])
    return found


def confine_package(package: str) -> list:
    """Open and check every layer of the package. Returns the layers, which must stay alive while
    the stage composes them, so that it composes them as checked rather than reading them again."""
    Sdf, _, _, _ = _pxr()
    members = _members(package)
    layers: dict[str, object] = {}
    layer_members = [m for m in members if _is_layer(m)]
    if len(layer_members) > MAX_PACKAGE_LAYERS:
        raise ShaderGenError("too_large", f"the package holds {len(layer_members)} layers, more than the "
                             f"{MAX_PACKAGE_LAYERS} a package may hold", "<document>")
    todo = [package] + layer_members
    while todo:
        identifier = todo.pop()
        if identifier in layers:
            continue
        with usd_errors("<document>"):
            layer = Sdf.Layer.FindOrOpen(identifier)
        if layer is None:
            continue  # a member named but missing: the stage reports it as a composition error
        layers[identifier] = layer
        with usd_errors("<document>"):  # reading a crate's values may find it corrupt
            opened = opened_paths(layer)
        for path in opened:
            anchored = anchor(layer, path)
            if not _confinable(path) or not inside(anchored, package):
                raise ShaderGenError("path_not_allowed", f"'{path}' leaves the usdz package", path)
            if _search_relative(path) and (anchored not in members or "#" in path):
                raise ShaderGenError("path_not_allowed", f"'{path}' names no member of the usdz package (a search "
                                     "path is looked up outside it; './' names a path beside its layer)", path)
            if _is_layer(anchored):
                todo.append(anchored)
    return list(layers.values())
