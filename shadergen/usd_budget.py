"""What composing an upload would cost, counted before usd-core composes it.

Every composition arc copies its target's namespace under the prim that names it, so a layer of
a few kilobytes can describe exponentially many prims: twenty prims, each with two children that
reference the one before, compose to about two million, and a 2.4 kB layer held a generator child
for minutes. The layers themselves are small (the upload's size is bounded); what they expand to
is counted here from their specs alone (Sdf, which composes nothing), as an upper bound: every
spec of a prim in every layer of its layer stack, each reference, payload, inherit and
specialize adding its target's prims, the largest variant of each variant set. An upload over
MAX_COMPOSED_PRIMS is refused (too_large) before the stage is opened.
"""
from .errors import ShaderGenError
from .usd import anchor

# usd-core composes about 10,000 prims a second on a loaded 2-core machine (measured: 98,286
# prims of nested references in 9.5 s), and a generator child has 10 s for a whole document.
MAX_COMPOSED_PRIMS = 20_000


def check_composed_size(root, layers: list) -> None:
    """Refuse (too_large) an upload whose stage would hold more than MAX_COMPOSED_PRIMS prims."""
    try:
        count = ComposedSize(layers, MAX_COMPOSED_PRIMS).of_stack(root)
    except (OverLimit, RecursionError):  # RecursionError: namespace or arcs nested deeper than Python recurses
        count = None
    if count is None or count > MAX_COMPOSED_PRIMS:
        described = f"up to {count} prims" if count else f"more than {MAX_COMPOSED_PRIMS} prims"
        raise ShaderGenError("too_large", f"composing the upload would give its stage {described}, over the "
                             f"{MAX_COMPOSED_PRIMS} an upload may compose to", "<document>")


class OverLimit(Exception):
    """More prims were counted one by one than the limit: the stage has at least as many."""


class ComposedSize:
    """Upper bounds of the prims that specs compose to, over the upload's opened `layers` (a layer
    they name that is not among them composes nothing: the stage reports it as an error).

    A prim's count is kept and reused wherever its prim is composed again, except a count made
    while a cycle of arcs was cut above it (usd-core cuts a cycle where it closes, so the same
    prim composed from elsewhere holds more): that one is counted again in each place, one prim
    at a time, and counting more than `limit` prims that way raises OverLimit, since each is a
    prim of the stage. The walk is so bounded by the specs and the limit, whatever the arcs."""

    def __init__(self, layers: list, limit: int):
        self.layers = {layer.identifier: layer for layer in layers}
        self.limit = limit
        self.known: dict[tuple[str, str], int] = {}
        self.depth: dict[tuple[str, str], int] = {}  # the prims being counted, by how deep in the walk
        self.cut = 0  # the shallowest depth a cycle closed at, below the prim being counted
        self.counted = 0

    def of_stack(self, root) -> int:
        """The prims of the stage whose root layer is `root` (its pseudo-root not counted)."""
        stack = self.stack(root)
        roots = {str(prim.path) for layer in stack for prim in layer.rootPrims}
        return sum(self.of_path(stack, path) for path in sorted(roots))

    def stack(self, layer) -> list:
        """The layer and its sublayers, strongest first, as far as they were opened."""
        found, todo = [], [layer]
        while todo:
            current = todo.pop(0)
            if current in found:
                continue
            found.append(current)
            todo.extend(filter(None, (self.layers.get(anchor(current, sub)) for sub in current.subLayerPaths)))
        return found

    def of_path(self, stack: list, path: str) -> int:
        """The prims that the specs at `path` in the layer stack compose to (the prim itself included)."""
        key = (stack[0].identifier, path)
        if key in self.known:
            return self.known[key]
        if key in self.depth:  # a cycle closes here: usd-core composes this arc no further
            self.cut = min(self.cut, self.depth[key])
            return 1
        self.counted += 1
        if self.counted > self.limit:
            raise OverLimit
        depth = self.depth[key] = len(self.depth)
        cut_above, self.cut = self.cut, depth
        specs = [spec for layer in stack if (spec := layer.GetPrimAtPath(path)) is not None]
        count = 1 + sum(self.brought(stack, spec) for spec in specs)
        children = {str(child.path) for spec in specs for child in spec.nameChildren}  # merged across the stack
        count += sum(self.of_path(stack, child) for child in sorted(children))
        if self.cut >= depth:  # no cycle was cut above this prim: its count holds wherever it is composed
            self.known[key] = count
        self.cut = min(cut_above, self.cut)
        del self.depth[key]
        return count

    def brought(self, stack: list, spec) -> int:
        """The prims a spec's arcs and variants add below its prim: each arc's target's, and the
        largest variant of each variant set (only one is selected)."""
        count = sum(self.of_path(target, path) - 1 for target, path in self.arc_targets(stack, spec))
        for variant_set in spec.variantSets.values():
            count += max((self.of_variant(stack, v.primSpec) for v in variant_set.variants.values()), default=0)
        return count

    def of_variant(self, stack: list, spec) -> int:
        return self.brought(stack, spec) + sum(self.of_path(stack, str(child.path)) for child in spec.nameChildren)

    def arc_targets(self, stack: list, spec):
        """(layer stack, prim path) of each reference, payload, inherit and specialize of the spec."""
        for arcs in (spec.referenceList, spec.payloadList):
            for arc in arcs.GetAddedOrExplicitItems():
                target = stack
                if arc.assetPath:
                    layer = self.layers.get(anchor(spec.layer, arc.assetPath))
                    if layer is None:
                        continue  # not opened (missing): nothing composes from it
                    target = self.stack(layer)
                default = target[0].defaultPrim
                path = str(arc.primPath) if not arc.primPath.isEmpty else default and f"/{default}"
                if path:
                    yield target, path
        for arcs in (spec.inheritPathList, spec.specializesList):
            for path in arcs.GetAddedOrExplicitItems():
                yield stack, str(path.MakeAbsolutePath(spec.path))
