"""What the generator reads from library sources with its fast scans: derivative calls (a node that
takes them runs in uniform control flow), the parameters of a lobe's `_prepare` function, the names
an item of a library section calls (dead members) and a call's arguments (forwarding)."""
import pytest

from shadergen.nodes.base import takes_derivatives
from shadergen.targets.deadfields import called_names
from shadergen.targets.forwarding import _split as split_arguments
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


@pytest.mark.parametrize("code, expected", [
    ("f(x) + g (y)", {"f", "g"}),
    ("return mx_eval\n    (a, b);", {"mx_eval"}),  # blanks and a line break before the `(`
    ("lobe.prepare(x) + _k(1)", {"prepare", "_k"}),
    ("float y = 2e(1) + (a) * ((b));", set()),  # a word starting with a digit is no name; bare parentheses
    ("vec3 c = mx_fresnel(ior(x), t[i](0));", {"mx_fresnel", "ior"}),
])
def test_called_names_are_whole_words_before_a_parenthesis(code, expected):
    assert called_names(code) == expected


@pytest.mark.parametrize("arguments, expected", [
    ("in float a, out vec3 b", ["in float a", "out vec3 b"]),
    ("a, f(b, c[1, 2]), (d,\n   e)", ["a", "f(b, c[1, 2])", "(d, e)"]),
    ("x, , y", ["x", "y"]),
    ("  ", []),
])
def test_arguments_split_at_commas_outside_parentheses_and_brackets(arguments, expected):
    assert split_arguments(arguments) == expected
