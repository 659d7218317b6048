"""Light rigs: a MaterialX document of lightshader nodes (directional_light, point_light,
spot_light, ...) as the u_numActiveLightSources / u_lightData[] uniforms of MaterialX's GLSL.

Each light's `type` is the id the shader's light dispatch compares against. Our records list those
ids (the `enum`/`enumvalues` of LightData's `type` member); for other shaders it is the id
MaterialX's light handler gives: 1, 2, ... in order of first appearance in the rig, which must then
be the rig the shader was generated with. A shader generated without lights ignores them.
Inputs the node does not set take their nodedef's default from the data libraries.
"""
import functools
import os
from dataclasses import dataclass
from pathlib import Path

from defusedxml import DefusedXmlException, ElementTree

from .errors import RenderError
from .values import numbers

LIBRARY_DIR = Path(__file__).resolve().parents[2] / "libraries"


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
            return dict(zip(ui["enum"].split(","), (int(v) for v in ui["enumvalues"].split(","))))
    return None


def load_lights(path: str, library_dir: Path = LIBRARY_DIR, type_ids: dict[str, int] | None = None) -> list[Light]:
    try:
        root = ElementTree.parse(path).getroot()
    except (OSError, ElementTree.ParseError, DefusedXmlException) as exc:
        raise RenderError("invalid_lights", f"cannot read light rig {path}: {exc}", path) from exc
    defaults = _light_defaults(str(library_dir))
    ids: dict[str, int] = {}
    lights = []
    for node in root:
        if node.get("type") != "lightshader":
            continue
        category = node.tag
        if type_ids is not None and category not in type_ids:
            raise RenderError("invalid_lights", f"the shader has no {category} lights", node.get("name"))
        ids.setdefault(category, type_ids[category] if type_ids is not None else len(ids) + 1)
        inputs = dict(defaults.get(category, {}))
        for inp in node.findall("input"):
            value = numbers(inp.get("type", ""), inp.get("value"))
            if value is None:
                raise RenderError("invalid_lights", f"light input {inp.get('name')} has no constant value "
                                  "(connected light inputs are not supported)", f"{node.get('name')}/{inp.get('name')}")
            inputs[inp.get("name")] = value
        lights.append(Light(node.get("name", category), category, ids[category], inputs))
    if not lights:
        raise RenderError("invalid_lights", "the light rig has no lightshader nodes", path)
    return lights


@functools.lru_cache(maxsize=4)
def _light_defaults(library_dir: str) -> dict[str, dict[str, list[float]]]:
    """category -> {input: default numbers} of every nodedef with a lightshader output."""
    found: dict[str, dict[str, list[float]]] = {}
    for folder, _, files in os.walk(library_dir):
        for file in sorted(f for f in files if f.endswith(".mtlx")):
            try:
                root = ElementTree.parse(os.path.join(folder, file)).getroot()
            except (OSError, ElementTree.ParseError, DefusedXmlException):
                continue  # the generator reports broken libraries; lights only lose defaults
            for nodedef in root.iter("nodedef"):
                if any(o.get("type") == "lightshader" for o in nodedef.findall("output")):
                    found[nodedef.get("node")] = {
                        i.get("name"): value for i in nodedef.findall("input")
                        if (value := numbers(i.get("type", ""), i.get("value"))) is not None}
    return found


def light_uniforms(lights: list[Light]) -> dict[str, list[float]]:
    """Uniform name -> numbers for the whole rig."""
    uniforms = {"u_numActiveLightSources": [float(len(lights))]}
    for i, light in enumerate(lights):
        uniforms[f"u_lightData[{i}].type"] = [float(light.type_id)]
        for name, value in light.inputs.items():
            uniforms[f"u_lightData[{i}].{name}"] = value
    return uniforms
