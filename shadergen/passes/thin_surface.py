"""The seed's `thinsurface` (section 4.5) is two-sided: "If only one BSDF is connected the same BSDF
will be used on both sides." Its nodegraph picks `frontbsdf` or `backbsdf` by the side seen, and a
graph cannot tell an unconnected input from a connected one, so before expansion the unconnected
side is connected to the other side's BSDF. (EDFs are not shared: an unconnected side emits
nothing, as the seed says.) Pixar's LamaSurface is two-sided the same way: one connected material
serves both sides (its default of one "material side")."""
from ..graph import Graph

SIDES = {"thinsurface": ("frontbsdf", "backbsdf"), "LamaSurface": ("materialFront", "materialBack")}


def share_one_sided_bsdf(graph: Graph) -> int:
    """Returns how many thin surfaces had one BSDF for both sides."""
    count = 0
    for node in graph.nodes:
        sides = SIDES.get(node.category, ())
        if not sides or not all(side in node.inputs for side in sides):
            continue
        front, back = (node.inputs[side] for side in sides)
        if (front.connection is None) == (back.connection is None):
            continue
        missing, present = (front, back) if front.connection is None else (back, front)
        missing.connection = present.connection
        count += 1
    return count
