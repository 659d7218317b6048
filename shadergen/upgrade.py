"""Upgrade documents written for MaterialX 1.38 (and the 1.37 forms still in use) to 1.39.

Each rule is a small function over the element tree; `upgrade` applies the rules a document's
version needs, recursively through node graphs, and records what it changed as warnings.
"""
from .element import Element

SWIZZLE_TYPES = {"r": 0, "x": 0, "g": 1, "y": 1, "b": 2, "z": 2, "a": 3, "w": 3}


def _walk(elem: Element):
    yield elem
    for c in elem.children:
        yield from _walk(c)


def _normalmap(node: Element) -> bool:
    """1.39 removed normalmap's `space` input and the generic ND_normalmap."""
    if node.category != "normalmap":
        return False
    changed = False
    if node.get("nodedef") == "ND_normalmap":
        del node.attrs["nodedef"]
        changed = True
    space = node.child("space")
    if space is not None:
        node.remove_child(space)
        changed = True
    return changed


def _swizzle(node: Element) -> bool:
    """1.39 removed `swizzle`: one channel becomes `extract`, several become a `combineN` of extracts
    (constants for the 0/1 channel letters)."""
    if node.category != "swizzle":
        return False
    channels_input = node.child("channels")
    channels = channels_input.get("value", "") if channels_input is not None else ""
    source = node.child("in")
    node.attrs.pop("nodedef", None)
    if channels_input is not None:
        node.remove_child(channels_input)
    if len(channels) <= 1:
        node.category = "extract"
        node.add_child(Element("input", {"name": "index", "type": "integer",
                                         "value": str(SWIZZLE_TYPES.get(channels or "r", 0))}))
        if source is not None:
            source.attrs.pop("nodedef", None)
        return True
    parent = node.parent
    node.category = f"combine{len(channels)}"
    if source is not None:
        node.remove_child(source)
        source.attrs.pop("nodedef", None)
    for i, ch in enumerate(channels):
        inp = Element("input", {"name": f"in{i + 1}", "type": "float"})
        if ch in "01":
            inp.attrs["value"] = ch + ".0"
        elif source is not None:
            extract = Element("extract", {"name": f"{node.name}_{ch}{i}", "type": "float"})
            moved = Element("input", {k: v for k, v in source.attrs.items() if k != "name"} | {"name": "in"})
            extract.add_child(moved)
            extract.add_child(Element("input", {"name": "index", "type": "integer",
                                                "value": str(SWIZZLE_TYPES.get(ch, 0))}))
            parent.add_child(extract, parent.children.index(node))
            inp.attrs["nodename"] = extract.name
        node.add_child(inp)
    return True


RULES_BEFORE_1_39 = (_normalmap, _swizzle)


def upgrade(doc) -> None:
    if doc.version >= (1, 39):
        return
    for elem in list(_walk(doc.root)):
        for rule in RULES_BEFORE_1_39:
            if rule(elem):
                doc.warnings.append(f"upgraded {elem.path} to MaterialX 1.39 ({rule.__name__.strip('_')})")
    doc.root.attrs["version"] = "1.39"
