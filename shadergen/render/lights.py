"""Light rigs: a MaterialX document of lightshader nodes (directional_light, point_light,
spot_light, ...) as the u_numActiveLightSources / u_lightData[] uniforms of MaterialX's GLSL.

Each light's `type` is the id the shader's light dispatch compares against. Our records list those
ids (the `enum`/`enumvalues` of LightData's `type` member); for other shaders it is the id
MaterialX's light handler gives: 1, 2, ... in order of first appearance in the rig, which must then
be the rig the shader was generated with. A shader generated without lights ignores them.
Inputs the node does not set take their nodedef's default, read through `document` and
`library` like every other definition (includes, inheritance, the library's disk cache).
"""
from dataclasses import dataclass

from ..document import read_document
from ..element import Element
from ..errors import ShaderGenError
from ..library import Library, Scope, default_library
from .errors import RenderError
from .values import numbers


@dataclass
class Light:
    name: str
    category: str                    # node name of the nodedef: directional_light, ...
    type_id: int
    inputs: dict[str, list[float]]   # LightData member -> its numbers


def light_type_ids(record: dict) -> dict[str, int] | None:
    """category -> id, when the record lists its shader's light dispatch; None otherwise."""
    for var in ((record.get("blocks") or {}).get("pixel") or {}).get("LightData") or []:
        ui = var.get("ui") or {}
        if var.get("name") == "type" and ui.get("enum") and ui.get("enumvalues"):
            return dict(zip(ui["enum"], ui["enumvalues"]))
    return None


def load_lights(path: str, library: Library | None = None, type_ids: dict[str, int] | None = None) -> list[Light]:
    """The rig's lights, read like any document (includes, upgrades, its own nodedefs) over the
    data libraries (default: the generator's)."""
    try:
        doc = read_document(str(path))
        lights = _lights(doc.root, Scope(library or default_library(), doc.root), type_ids)
    except ShaderGenError as exc:
        raise RenderError("invalid_lights", f"cannot read light rig {path}: {exc.message}", exc.where or str(path)) \
            from None
    if not lights:
        raise RenderError("invalid_lights", "the light rig has no lightshader nodes", str(path))
    return lights


def _lights(root: Element, scope: Scope, type_ids: dict[str, int] | None) -> list[Light]:
    ids: dict[str, int] = {}
    lights = []
    for node in root.children:
        if node.get("type") != "lightshader":
            continue
        category = node.category
        if type_ids is not None and category not in type_ids:
            raise RenderError("invalid_lights", f"the shader has no {category} lights", node.path)
        ids.setdefault(category, type_ids[category] if type_ids is not None else len(ids) + 1)
        inputs = _defaults(scope, node)
        for inp in node.children_of("input"):
            value = numbers(inp.get("type", ""), inp.get("value"))
            if value is None:
                raise RenderError("invalid_lights", f"light input {inp.name} has no constant value "
                                  "(connected light inputs are not supported)", inp.path)
            inputs[inp.name] = value
        lights.append(Light(node.name or category, category, ids[category], inputs))
    return lights


def _defaults(scope: Scope, node: Element) -> dict[str, list[float]]:
    """Input -> default numbers from the light's nodedef (inherited inputs included)."""
    nodedef = scope.nodedef(node.get("nodedef")) if node.get("nodedef") else next(
        (nd for nd in scope.nodedefs_for(node.category)
         if any(o.get("type") == "lightshader" for o in scope.nodedef_outputs(nd))), None)
    if nodedef is None:
        return {}
    return {i.name: value for i in scope.nodedef_inputs(nodedef)
            if (value := numbers(i.get("type", ""), i.get("value"))) is not None}


def light_uniforms(lights: list[Light]) -> dict[str, list[float]]:
    """Uniform name -> numbers for the whole rig."""
    uniforms = {"u_numActiveLightSources": [float(len(lights))]}
    for i, light in enumerate(lights):
        uniforms[f"u_lightData[{i}].type"] = [float(light.type_id)]
        for name, value in light.inputs.items():
            uniforms[f"u_lightData[{i}].{name}"] = value
    return uniforms
