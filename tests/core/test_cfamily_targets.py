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
