"""What the source calls the things a document names: nodes (their outputs' variables and the
uniforms of their inputs), nodegraph functions and the shader's outputs.

`structural` (the default) names them by the graph's structure: a node by its place in the
topological order (`n12`, so its base_color uniform is `u_n12_base_color`), a function by the order
it is written in, the shader's outputs `out`, `out1`... in the graph's order. Materials that differ only in their
element names then share one source, and clients bind uniforms by the listing, which maps every
uniform to its element path. `document` keeps the document's element names in the source, for
clients that bind by name; the topology hash then covers the names (hashing.py).
"""
NAMES = ("structural", "document")


class SourceNames:
    """One per shader. Labels are handed out in the order things are first named: the generator
    names the graph's nodes first, in topological order, so a node's label is its position there;
    nodes named later (the node a nodegraph's socket stood for, a function's body) take the next
    labels, in the order emission reaches them, which the structure alone decides."""

    __slots__ = ("document", "labels", "counts")

    def __init__(self, names: str):
        self.document = names == "document"
        self.labels: dict[tuple[str, int], str] = {}  # (kind, id(thing)) -> its label
        self.counts: dict[str, int] = {}  # kind -> labels handed out

    def _label(self, kind: str, thing: object) -> str:
        key = (kind, id(thing))
        if key not in self.labels:
            n = self.counts.get(kind, 0)
            self.labels[key] = f"{kind}{n}"
            self.counts[kind] = n + 1
        return self.labels[key]

    def node(self, node) -> str:
        """The stem of a node's variables (`<stem>_<output>`)."""
        return node.name if self.document else self._label("n", node)

    def uniform(self, port) -> str:
        """A public input's uniform, before the namer makes it unique: `<node>_<input>`."""
        if self.document:
            return f"{port.owner.name}_{port.name}"
        return f"u_{self._label('n', port.owner)}_{port.name}"

    def function(self, function) -> str:
        """A nodegraph body written as a function."""
        return function.name if self.document else self._label("graph", function)

    def output(self, name: str) -> str:
        """A shader output: `out` (the namer numbers the second and later ones), or its name."""
        return name if self.document else "out"
