"""The element tree every layer reads: a MaterialX element with its category, attributes and name path."""
import json


class Element:
    """One MaterialX element. `category` is the XML tag (`nodedef`, `input`, `image`, ...)."""

    __slots__ = ("category", "name", "attrs", "_children", "_pending", "parent", "_by_name", "source")

    def __init__(self, category: str, attrs: dict, parent: "Element | None" = None, source: str | None = None,
                 pending: list | bytes | None = None):
        self.category = category
        self.name = attrs.get("name", "")
        self.attrs = attrs
        self._children: list[Element] | None = None if pending else []
        # Children still in their cached [category, attrs, children] form (or that list as JSON
        # text): a library holds thousands of elements and a shader reads a few dozen, so they are
        # built when first read.
        self._pending = pending
        self.parent = parent
        self._by_name: dict[str, Element] | None = None
        self.source = source

    @property
    def children(self) -> list["Element"]:
        if self._children is None:
            pending = self._pending
            if isinstance(pending, bytes):  # the library cache keeps a definition's children as JSON text
                pending = json.loads(pending)
            self._children = [Element(c, a, self, self.source, kids) for c, a, kids in pending]
            self._pending = None
        return self._children

    def get(self, key: str, default=None):
        return self.attrs.get(key, default)

    def child(self, name: str) -> "Element | None":
        if self._by_name is None:
            self._by_name = {c.name: c for c in self.children}
        return self._by_name.get(name)

    def children_of(self, *categories: str) -> list["Element"]:
        return [c for c in self.children if c.category in categories]

    def add_child(self, child: "Element", index: int | None = None) -> None:
        child.parent = self
        if index is None:
            self.children.append(child)
        else:
            self.children.insert(index, child)
        self._by_name = None

    def remove_child(self, child: "Element") -> None:
        self.children.remove(child)
        self._by_name = None

    @property
    def path(self) -> str:
        """Name path as MaterialX writes it: `graph/node/input` (the document root is not part of it)."""
        names = []
        e = self
        while e is not None and e.parent is not None:
            names.append(e.name)
            e = e.parent
        return "/".join(reversed(names))

    def inherited(self, key: str) -> str | None:
        """An attribute such as colorspace or fileprefix, looked up through the ancestors."""
        e = self
        while e is not None:
            v = e.attrs.get(key)
            if v is not None:
                return v
            e = e.parent
        return None

    def __repr__(self) -> str:
        return f"<{self.category} {self.path or self.name!r}>"
