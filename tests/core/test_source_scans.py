"""What the generator reads from library sources with its fast scans: derivative calls (a node that
takes them runs in uniform control flow) and the parameters of a lobe's `_prepare` function."""
import pytest

from shadergen.nodes.base import takes_derivatives
from shadergen.targets.glsl import ClosureConvention


@pytest.mark.parametrize("source, expected", [
    ("vec4 c = texture(tex, uv);", True),
    ("float w = fwidth (x);", True),
    ("dFdx(p)", True),  # at the very start of the source
    ("vec2 d = dFdy(uv) + dFdx(uv);", True),
    ("vec4 c = mx_texture(tex, uv);", False),  # a longer name ending in one of them
    ("vec4 c = textureLod(tex, uv, 0.0);", False),  # explicit level of detail: no derivatives
    ("float dFdx_scale = 1.0;", False),  # a name starting with one of them, never called
    ("// texture lookups happen elsewhere", False),
])
def test_derivative_calls_are_found_as_whole_names(source, expected):
    assert takes_derivatives(source) is expected


SOURCE = """
void mx_other_prepare(float a, out OtherLobe lobe) {}
void mx_lobe(ClosureData closureData, float weight, out BSDF bsdf) {}
void  mx_lobe_prepare(ClosureData closureData,
                      float weight, out LobeState state)
{
}
void mx_lobe_prepare(float later, out Ignored state) {}
void notmx_flat_prepare(float a, out FlatState s) {}
void mx_flat_prepare(float a) {}
"""


def test_a_lobes_prepared_state_is_the_type_its_first_prepare_function_writes():
    closures = ClosureConvention()
    assert closures.prepared_state(SOURCE, "mx_lobe") == "LobeState"
    assert closures.prepared_state(SOURCE, "mx_other") == "OtherLobe"
    assert closures.prepared_state(SOURCE, "mx_flat") is None  # writes no state
    assert closures.prepared_state(SOURCE, "flat") is None  # `notmx_flat_prepare` is another name
    assert closures.prepared_state(SOURCE, "mx_missing") is None
