"""The HLSL and Slang targets (shadergen/targets/cfamily): their checker refuses bad code with a
location, and the printer writes what the languages lack as they need it."""
import pytest

from required_tools import require_module

require_module("slangpy", "pip install -e '.[slang]'")

from shadergen.api import DocumentFile  # noqa: E402
from shadergen.targets.slang import check  # noqa: E402
from tests.golden.cases import DOCUMENTS  # noqa: E402


@pytest.mark.parametrize("target", ["hlsl", "slang"])
def test_a_shader_the_compiler_refuses_is_reported_with_its_line(gen, target):
    source = gen.prepare(DocumentFile(str(DOCUMENTS["marble_checker"])), target=target).emit()["stages"]["pixel"]
    assert check.errors({"good": ("pixel", source)}) == {}
    lines = source.splitlines()
    at = next(i for i, line in enumerate(lines) if "floor(" in line)
    lines[at] = lines[at].replace("floor(", "floor_undefined(", 1)
    found = check.errors({"bad": ("pixel", "\n".join(lines))})
    assert "E30015" in found["bad"] and f"at line {at + 1}, column" in found["bad"], found


def test_a_module_without_its_stage_entry_point_is_refused():
    found = check.errors({"no entry": ("vertex", "float f(float x) { return x; }")})
    assert "vertexMain" in found["no entry"]


def test_matrix_products_are_written_for_transposed_matrices(gen):
    # HLSL and Slang keep each IR (column-major) matrix as its transpose: M * v is mul(v, M)
    vertex = gen.prepare(DocumentFile(str(DOCUMENTS["marble_checker"])), target="hlsl").emit()["stages"]["vertex"]
    assert "mul(float4(vin.i_position, 1.0), u_worldMatrix)" in vertex
    assert "row_major float4x4 u_worldMatrix;" in vertex


# -- MSL: cross-checked against naga's MSL of our WGSL ---------------------------------------------
@pytest.fixture(scope="module")
def naga():
    from required_tools import tool_path
    return tool_path("naga")


def golden_pairs():
    from tests.golden.cases import STAGES, VARIANTS, golden_path
    for name in DOCUMENTS:
        for variant in VARIANTS:
            for stage in STAGES:
                yield (f"{name}.{variant} {stage}", stage, golden_path(name, variant, "msl", stage).read_text(),
                       golden_path(name, variant, "wgsl", stage).read_text())


def test_every_msl_golden_declares_what_naga_declares_for_the_wgsl_golden(naga):
    from shadergen.targets.msl import check as msl
    pairs = list(golden_pairs())
    assert msl.errors({label: (stage, ours) for label, stage, ours, _ in pairs},
                      {label: wgsl for label, _, _, wgsl in pairs}) == {}


@pytest.mark.parametrize("change,expected", [
    (("float u_n2_in2;", "int u_n2_in2;"), "PixelUniforms members"),  # a member's type
    (("packed_float3 u_n0_in;", "float3 u_n0_in;"), "PixelUniforms members"),  # its offsets after it
    (("float2 texcoord_0 [[user(locn1)]]", "float2 texcoord_1 [[user(locn1)]]"), "stage inputs"),
    (("fragment float4 fragmentMain", "fragment float4 fragment_main"), "entry point"),
])
def test_an_msl_shader_that_differs_from_naga_is_refused(naga, change, expected):
    from shadergen.targets.msl import check as msl
    from tests.golden.cases import golden_path
    ours = golden_path("marble_checker", "complete", "msl", "pixel").read_text()
    assert change[0] in ours
    wgsl = golden_path("marble_checker", "complete", "wgsl", "pixel").read_text()
    found = msl.errors({"changed": ("pixel", ours.replace(change[0], change[1]))}, {"changed": wgsl})
    assert expected in found.get("changed", ""), found
