"""Names never break code: whatever a document names its elements (Unicode, reserved words of any
target, names that collide once cleaned, long names), every record generates and compiles with its
target's checker (glslangValidator for GLSL and ESSL, wgpu for WGSL). The cases are
tests/name_cases.py's, from a fixed seed; `bench/fuzz.py --kind names` runs more of them. Generated
with `names: "document"`, the only names that bring the document's names into the source."""
import glob

import pytest

from name_cases import ShaderChecker, generate_records, name_cases
from shadergen.code import ir
from shadergen.code.check import flat_items
from shadergen.library import default_library
from shadergen.targets.names import RESERVED, RESERVED_PREFIXES, identifier

from .conftest import doc

SEED = 21
CASES = 160  # MaterialX and USD in turn; about 0.25 s each with its 6 to 12 records compiled
BATCH = 10  # cases compiled per glslangValidator run


@pytest.fixture(scope="module")
def checker():
    from required_tools import missing
    return ShaderChecker(on_missing=missing)


# every case in four targets, Vulkan's SPIR-V validated too: more than the suite's 300 s on a busy 2-core machine
@pytest.mark.timeout(1200)
def test_every_record_of_random_names_generates_and_compiles(gen, checker):
    cases = list(name_cases(SEED, CASES))
    assert {c.format for c in cases} == {"mtlx", "usda"}
    problems, records = [], 0
    for start in range(0, len(cases), BATCH):
        batch = [r for case in cases[start:start + BATCH] for r in generate_records(gen, case)]
        records += len(batch)
        problems += checker.problems(batch)
    assert records >= 2 * 6 * CASES // 2
    assert not problems, f"{len(problems)} of {records} records failed:\n" + "\n".join(p[:300] for p in problems[:10])


def test_a_unicode_prim_name_is_spelled_by_its_code_points(gen, checker):
    """The issue's case: a prim named Ω材質 became a GLSL identifier as it was."""
    from pxr import Sdf, Usd, UsdShade

    stage = Usd.Stage.CreateInMemory()
    material = UsdShade.Material.Define(stage, "/World/Ω材質")
    surface = UsdShade.Shader.Define(stage, "/World/Ω材質/Surface")
    surface.CreateIdAttr("UsdPreviewSurface")
    surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.25)
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    layer = stage.GetRootLayer().ExportToString().encode()
    records = [("Ω材質", r) for t in ("glsl", "essl", "wgsl")
               for r in gen.records(layer, target=t, document_format="usda", names="document")]
    assert not checker.problems(records)
    listing = {v["path"]: v["name"] for v in records[0][1]["blocks"]["pixel"]["PublicUniforms"]}
    assert listing["/World/Ω材質/Surface.inputs:roughness"] == "World_u03A9_u6750_u8CEA_Surface_roughness"
    for _, record in records:
        assert all(source.isascii() for source in record["stages"].values())


def test_names_that_collide_once_cleaned_stay_apart_and_bind_by_the_listing(gen):
    text = doc('<nodegraph name="g"><input name="x" type="float" value="1"/>'
               '<add name="a-b" type="float"><input name="in1" type="float" interfacename="x"/></add>'
               '<add name="a_b" type="float"><input name="in1" type="float" nodename="a-b"/></add>'
               '<add name="a.b" type="float"><input name="in1" type="float" nodename="a_b"/></add>'
               '<output name="out" type="float" nodename="a.b"/></nodegraph>')
    names = {}
    for target in ("glsl", "essl", "wgsl"):
        rec = gen.prepare(text, target=target, names="document").emit()
        names[target] = {v["path"]: v["name"] for v in rec["blocks"]["pixel"]["PublicUniforms"]}
    assert names["glsl"] == names["essl"] == names["wgsl"]  # one spelling in every target
    in2 = [names["glsl"][f"g/{n}/in2"] for n in ("a-b", "a_b", "a.b")]
    assert in2 == ["a_b_in2", "a_b_in21", "a_b_in22"]


def test_a_uniform_named_like_a_library_variable_is_not_read_inside_the_library(gen, checker):
    """WGSL reads uniforms through their buffer by name wherever the name stands: a uniform `a_in`
    (node `a`, input `in`) was read inside the noise library's `mx_hn_final(a_in: u32, ...)`, the
    copy of its parameter `a` (now `a__in`); a uniform `edge_color` (node `edge`, input `color`)
    would be read for the parameter `edge_color` of mx_artistic_ior."""
    text = doc('<nodegraph name="g"><absval name="a" type="float"><input name="in" type="float" value="0.5"/></absval>'
               '<noise2d name="nz" type="float"/>'
               '<add name="s" type="float"><input name="in1" type="float" nodename="a"/>'
               '<input name="in2" type="float" nodename="nz"/></add>'
               '<output name="out" type="float" nodename="s"/></nodegraph>')
    records = [("a_in", r) for t in ("glsl", "essl", "wgsl") for r in gen.records(text, target=t, names="document")]
    assert not checker.problems(records)
    names = {v["path"]: v["name"] for v in records[-1][1]["blocks"]["pixel"]["PublicUniforms"]}
    assert names["g/a/in"] == "a_in"
    text = doc('<oren_nayar_diffuse_bsdf name="edge" type="BSDF"/><artistic_ior name="ai" type="multioutput"/>'
               '<conductor_bsdf name="metal" type="BSDF"><input name="ior" type="color3" nodename="ai" output="ior"/>'
               '<input name="extinction" type="color3" nodename="ai" output="extinction"/></conductor_bsdf>'
               '<mix name="m" type="BSDF"><input name="fg" type="BSDF" nodename="edge"/>'
               '<input name="bg" type="BSDF" nodename="metal"/></mix>'
               '<surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="m"/></surface>'
               '<surfacematerial name="mat" type="material">'
               '<input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>')
    record = gen.prepare(text, target="wgsl", names="document").emit()
    assert not checker.problems([("edge_color", record)])
    assert "mx_artistic_ior" in record["stages"]["pixel"]
    names = {v["path"]: v["name"] for v in record["blocks"]["pixel"]["PublicUniforms"]}
    assert names["edge/color"] == "edge_color1"


@pytest.mark.parametrize("wanted,spelled", [
    ("SR_carpaint_base_color", "SR_carpaint_base_color"),  # the common case is untouched
    ("Ω材質", "_u03A9_u6750_u8CEA"), ("node_Ω", "node_u03A9"), ("a-b", "a_b"), ("a.b c", "a_b_c"),
    ("2nd", "v_2nd"), ("a__b", "a_b"), ("__", "v"), ("-", "v")])
def test_identifiers(wanted, spelled):
    assert identifier(wanted) == spelled


def test_long_names_are_cut_with_a_hash_of_the_whole():
    a, b = identifier("x" * 2000), identifier("x" * 1999 + "y")
    assert a != b and len(a) <= 96 and len(b) <= 96 and a[:80] == b[:80]


def test_every_global_name_of_the_libraries_is_kept_from_documents():
    """A document name equal to a library function, struct, constant or global (or one of the
    prelude's closure structs) would shadow it."""
    missing, seen = set(), 0
    for module in default_library().code().modules.values():
        for item in flat_items(module.items):
            if isinstance(item, (ir.Function, ir.Struct, ir.Constant, ir.Global)):
                seen += 1
                if item.name not in RESERVED and not item.name.startswith(RESERVED_PREFIXES):
                    missing.add(item.name)
    assert seen > 300 and not missing, sorted(missing)
