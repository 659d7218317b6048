"""Seed node names (libraries/shaderx) that 1.39 also defines: the authored inputs decide which
definition a node gets, as in MaterialX (a definition declaring every authored input wins)."""
import pytest

from shadergen.document import parse_document
from shadergen.graph import GraphBuilder
from shadergen.library import Scope, default_library

from .conftest import doc


def resolved(node_xml: str) -> str:
    root = parse_document(doc(node_xml)).root
    builder = GraphBuilder(Scope(default_library(), root), "genglsl", root)
    return builder.resolve_nodedef(root.children[-1]).name


@pytest.mark.parametrize("node_xml,nodedef", [
    ('<light name="n" type="lightshader"><input name="intensity" type="color3" value="1, 0.5, 0.2"/></light>', "ND_light_color3"),
    ('<light name="n" type="lightshader"><input name="intensity" type="float" value="2"/></light>', "ND_light"),
    ('<roughness_dual name="n" type="vector2"><input name="roughnessX" type="float" value="0.3"/></roughness_dual>',
     "ND_roughness_dual_xy"),
    ('<roughness_dual name="n" type="vector2"><input name="roughness" type="vector2" value="0.3, 0.1"/></roughness_dual>',
     "ND_roughness_dual"),
    # seed names whose seed inputs the 1.39 definitions already declare
    ('<surface name="n" type="surfaceshader"><input name="opacity" type="float" value="0.5"/></surface>', "ND_surface"),
    ('<volume name="n" type="volumeshader"/>', "ND_volume"),
    ('<displacement name="n" type="displacementshader"><input name="displacement" type="vector3" value="0, 0, 1"/>'
     '<input name="scale" type="float" value="0.1"/></displacement>', "ND_displacement_vector3"),
    ('<roughness_anisotropy name="n" type="vector2"><input name="anisotropy" type="float" value="0.5"/></roughness_anisotropy>',
     "ND_roughness_anisotropy"),
    ('<glossiness_anisotropy name="n" type="vector2"><input name="glossiness" type="float" value="0.5"/></glossiness_anisotropy>',
     "ND_glossiness_anisotropy"),
    ('<blackbody name="n" type="color3"><input name="temperature" type="float" value="3000"/></blackbody>', "ND_blackbody"),
])
def test_authored_inputs_choose_the_definition(node_xml, nodedef):
    assert resolved(node_xml) == nodedef


def test_measured_edf_by_its_seed_name_generates(gen):
    record = gen.prepare(doc(
        '<measurededf name="e" type="EDF"><input name="color" type="color3" value="1, 0.9, 0.8"/></measurededf>'
        '<surface name="s" type="surfaceshader"><input name="edf" type="EDF" nodename="e"/></surface>'
        '<surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/></surfacematerial>'
    )).emit()
    assert "error" not in record, record.get("error")
    assert "mx_measured_edf" in record["stages"]["pixel"]
