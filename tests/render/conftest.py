"""Fixtures of the renderer tests: hand-written records (data/records.json + GLSL files beside it)
and one Renderer for the whole session, since a process has one GL context."""
import copy
import json
from pathlib import Path

import pytest

from shadergen.render import Renderer

DATA = Path(__file__).parent / "data"
_SPECS = json.loads((DATA / "records.json").read_text())


def record(name: str) -> dict:
    """A fresh record of the contract for fixture `name`."""
    spec = copy.deepcopy(_SPECS[name])
    return {"document": None, "element": name, "target": "glsl", "interface": "complete", "hash": None,
            "stages": {"vertex": (DATA / spec["vertex"]).read_text(), "pixel": (DATA / spec["pixel"]).read_text()},
            "blocks": {"vertex": {"PrivateUniforms": [], "AppData": []},
                       "pixel": {"PublicUniforms": spec["pixel_uniforms"], "PrivateUniforms": [], "Outputs": []}}}


def set_value(rec: dict, name: str, value) -> dict:
    for variable in rec["blocks"]["pixel"]["PublicUniforms"]:
        if variable["name"] == name:
            variable["value"] = value
            return rec
    raise KeyError(name)


@pytest.fixture(scope="session")
def renderer() -> Renderer:
    return Renderer(search_paths=[])
