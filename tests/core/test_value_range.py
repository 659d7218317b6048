"""Values beyond what a shader's 32-bit types hold are refused as `invalid_value` naming the input
(a float past float32's largest, an integer past int32), in MaterialX and in USD; values at the
edges of the range generate in every target and interface, compile with each target's checker,
and list as strict JSON. Folding never writes a literal a checker refuses: a float product past
float32 or an integer sum past int32 is left to the GPU."""
import json

import pytest

from name_cases import ShaderChecker
from shadergen.types import FLOAT32_MAX

from .conftest import doc

TARGETS = ("glsl", "essl", "wgsl")
INTERFACES = ("complete", "reduced", "specialized")


@pytest.fixture(scope="module")
def checker():
    from required_tools import missing
    return ShaderChecker(on_missing=missing)


def graph(float_value="0.5", color="0.1, 0.2, 0.3", integer="1") -> str:
    return doc('<nodegraph name="g">'
               f'<multiply name="f" type="float"><input name="in1" type="float" value="{float_value}"/>'
               '<input name="in2" type="float" value="0.5"/></multiply>'
               f'<multiply name="c" type="color3"><input name="in1" type="color3" value="{color}"/>'
               '<input name="in2" type="float" nodename="f"/></multiply>'
               f'<add name="i" type="integer"><input name="in1" type="integer" value="{integer}"/>'
               '<input name="in2" type="integer" value="0"/></add>'
               '<convert name="fi" type="float"><input name="in" type="integer" nodename="i"/></convert>'
               '<add name="out_color" type="color3"><input name="in1" type="color3" nodename="c"/>'
               '<input name="in2" type="float" nodename="fi"/></add>'
               '<output name="out" type="color3" nodename="out_color"/></nodegraph>')


@pytest.mark.parametrize("interface", INTERFACES)
@pytest.mark.parametrize("values,where", [
    ({"float_value": "1e39"}, "g/f/in1"), ({"float_value": "-3.4028236e38"}, "g/f/in1"),
    ({"color": "0, 1e39, 0"}, "g/c/in1"), ({"integer": "2147483648"}, "g/i/in1"),
    ({"integer": "-2147483649"}, "g/i/in1")])
def test_values_beyond_32_bits_are_refused_naming_the_input(gen, values, where, interface):
    for target in TARGETS:
        records = list(gen.records(graph(**values), target=target, interface=interface))
        assert len(records) == 1 and records[0]["error"]["code"] == "invalid_value", records[0]
        assert records[0]["error"]["where"] == where
        assert "32-bit" in records[0]["error"]["message"]


def test_values_at_the_edges_of_32_bits_compile_everywhere_and_list_as_json(gen, checker):
    edges = [graph(repr(FLOAT32_MAX), "3.4028235e38, -3.4028235e38, 1e-45", "2147483647"),
             graph("-3.4028235e38", "1e-50, 0, 0", "-2147483648")]
    records = [(f"edges {k}", r) for k, text in enumerate(edges) for t in TARGETS for i in INTERFACES
               for r in gen.records(text, target=t, interface=i)]
    assert not checker.problems(records)
    for _, record in records:
        json.dumps(record, allow_nan=False)  # no NaN or Infinity tokens in the listings
    listed = {v["path"]: v["value"] for v in records[0][1]["blocks"]["pixel"]["PublicUniforms"]}
    assert listed["g/i/in1"] == 2147483647 and listed["g/f/in1"] == FLOAT32_MAX


def test_folding_leaves_what_overflows_32_bits_to_the_gpu(gen, checker):
    """1e30 * 1e30 is inf on a GPU (WGSL refuses such a constant expression); 2e9 + 2e9 wraps:
    neither is folded into a literal."""
    text = doc('<nodegraph name="g">'
               '<multiply name="f" type="float"><input name="in1" type="float" value="1e30"/>'
               '<input name="in2" type="float" value="1e30"/></multiply>'
               '<add name="i" type="integer"><input name="in1" type="integer" value="2000000000"/>'
               '<input name="in2" type="integer" value="2000000000"/></add>'
               '<convert name="fi" type="float"><input name="in" type="integer" nodename="i"/></convert>'
               '<add name="sum" type="float"><input name="in1" type="float" nodename="f"/>'
               '<input name="in2" type="float" nodename="fi"/></add>'
               '<output name="out" type="float" nodename="sum"/></nodegraph>')
    records = [("fold", r) for t in TARGETS for r in gen.records(text, target=t, interface="specialized")]
    assert not checker.problems(records)
    for _, record in records:
        assert "4000000000" not in record["stages"]["pixel"]
        assert "e60" not in record["stages"]["pixel"]


def _usd_layer(attribute: str, type_name: str, value) -> bytes:
    from pxr import Sdf, Usd, UsdShade

    stage = Usd.Stage.CreateInMemory()
    material = UsdShade.Material.Define(stage, "/World/Mat")
    surface = UsdShade.Shader.Define(stage, "/World/Mat/Surface")
    surface.CreateIdAttr("UsdPreviewSurface")
    surface.CreateInput(attribute, getattr(Sdf.ValueTypeNames, type_name)).Set(value)
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    return stage.GetRootLayer().ExportToString().encode()


@pytest.mark.parametrize("attribute,type_name,value", [("roughness", "Double", 1e39),
                                                      ("useSpecularWorkflow", "Int64", 2**40)])
def test_usd_values_beyond_32_bits_are_refused_naming_the_attribute(gen, attribute, type_name, value):
    records = list(gen.records(_usd_layer(attribute, type_name, value), document_format="usda", interface="specialized"))
    assert len(records) == 1 and records[0]["error"]["code"] == "invalid_value", records[0]
    assert records[0]["error"]["where"] == f"/World/Mat/Surface.inputs:{attribute}"
