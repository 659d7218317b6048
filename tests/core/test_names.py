"""Names out of the source (issue 23): the source names nodes, uniforms, functions and outputs by
the graph's structure, so materials built alike from differently named nodes share one source and
one topology hash; the listing maps every uniform to its element path; `names: "document"` keeps
the document's names in the source and in the topology hash."""
import re
import pytest

from shadergen.api import Generator
from shadergen.errors import ShaderGenError

GEN = Generator()


def material(shader: str, mat: str, graph: str, color: str = "0.8, 0.2, 0.1", output: str = "out",
             label: str = "Roughness") -> str:
    """A standard_surface whose base colour comes from a nodegraph used twice (so its body becomes a
    function), with every element name chosen by the caller."""
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <nodegraph name="{graph}">
    <input name="{graph}_tint" type="color3" value="{color}" />
    <multiply name="{graph}_scale" type="color3">
      <input name="in1" type="color3" interfacename="{graph}_tint" />
      <input name="in2" type="float" value="0.5" />
    </multiply>
    <output name="{output}" type="color3" nodename="{graph}_scale" />
  </nodegraph>
  <standard_surface name="{shader}" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="{graph}" output="{output}" />
    <input name="specular_roughness" type="float" value="0.3" uiname="{label}" />
  </standard_surface>
  <surfacematerial name="{mat}" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="{shader}" />
  </surfacematerial>
</materialx>"""


NAMED = {"one": dict(shader="SR_gold", mat="Gold", graph="NG_tint_a", output="tinted"),
         "two": dict(shader="SR_chrome", mat="Chrome", graph="NG_tint_b", output="result", color="0.1, 0.2, 0.9",
                     label="Rugosité")}


def uniforms(record: dict) -> dict[str, str]:
    return {v["path"]: v["name"] for v in record["blocks"]["pixel"]["PublicUniforms"]}


@pytest.mark.parametrize("interface", ["complete", "reduced"])
def test_differently_named_materials_share_source_and_topology_hash(interface):
    one, two = (GEN.prepare(material(**NAMED[k]), interface=interface).emit() for k in ("one", "two"))
    assert one["stages"] == two["stages"]
    assert one["topology_hash"] == two["topology_hash"]
    assert one["hash"] != two["hash"]
    # the listing still names each document's own elements, under the one source's uniform names
    assert uniforms(one)["NG_tint_a/NG_tint_a_tint"] == uniforms(two)["NG_tint_b/NG_tint_b_tint"]
    assert list(uniforms(one).values()) == list(uniforms(two).values())


@pytest.mark.parametrize("target", ["glsl", "essl", "wgsl"])
def test_no_element_name_reaches_the_structural_source(target):
    text = material(shader="zqshader", mat="zqmaterial", graph="zqgraph", output="zqoutput")
    record = GEN.prepare(text, target=target).emit()
    assert not any("zq" in stage for stage in record["stages"].values())
    assert re.search(r"\bu_n\d+_specular_roughness\b", record["stages"]["pixel"])
    assert "zqshader/specular_roughness" in uniforms(record)


def test_document_names_keep_the_names_in_source_and_topology_hash():
    one, two = (GEN.prepare(material(**NAMED[k]), names="document").emit() for k in ("one", "two"))
    assert "SR_gold_specular_roughness" in one["stages"]["pixel"]
    assert "SR_chrome_specular_roughness" in two["stages"]["pixel"]
    assert one["topology_hash"] != two["topology_hash"]
    structural = GEN.prepare(material(**NAMED["one"])).emit()
    assert structural["hash"] != one["hash"] and structural["topology_hash"] != one["topology_hash"]


def test_a_record_of_another_named_material_rebinds_to_what_emission_gives():
    """The service answers a known topology by rebinding its record: the listing's paths (and
    values) must be this document's, not the record's."""
    first = GEN.prepare(material(**NAMED["one"])).emit()
    other = GEN.prepare(material(**NAMED["two"]))
    rebound, emitted = other.rebind(first), other.emit()
    assert rebound is not None
    assert {**rebound, "timings_ms": None} == {**emitted, "timings_ms": None}
    ui = {v["path"]: v.get("ui") for v in rebound["blocks"]["pixel"]["PublicUniforms"]}
    assert ui["SR_chrome/specular_roughness"]["name"] == "Rugosité"  # the listing's ui hints are this document's


def test_unknown_names_option_is_an_error():
    with pytest.raises(ShaderGenError) as err:
        GEN.prepare(material(**NAMED["one"]), names="anonymous")
    assert err.value.code == "unsupported_names" and err.value.where == "names"

