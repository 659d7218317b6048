"""What the generator reads from library code, now from its typed IR (shadergen/code/facts.py)
rather than by scanning text: derivative calls (a node that takes them runs in uniform control
flow), the state a lobe's `_prepare` function writes, the functions an item calls (reach, dead
members) and a call's arguments (forwarding)."""
import pytest

from shadergen.code import ir
from shadergen.code.check import flat_items
from shadergen.code.facts import facts, prepared_state, uses_derivatives
from shadergen.code.parse import parse_expression

from .conftest import checked_code, library_implementation as implementation

HELPERS = """vec4 mx_texture(sampler2D tex, vec2 uv)
{
    return vec4(uv, 0.0, 1.0);
}

vec4 lookup(sampler2D tex, vec2 uv)
{
    return texture(tex, uv);
}
"""


def function_of(source: str, name: str) -> ir.Function:
    items, _ = checked_code(source, "")
    return next(i for i in flat_items(items) if isinstance(i, ir.Function) and i.name == name)


@pytest.mark.parametrize("body, expected", [
    ("vec4 c = texture(tex, uv);", True),
    ("float w = fwidth (x);", True),
    ("dFdx(p);", True),  # a call as a statement
    ("vec2 d = dFdy(uv) + dFdx(uv);", True),
    ("vec4 c = mx_texture(tex, uv);", False),  # a longer name ending in one of them
    ("vec4 c = textureLod(tex, uv, 0.0);", False),  # explicit level of detail: no derivatives
    ("float dFdx_scale = 1.0;", False),  # a name starting with one of them, never called
    ("// texture lookups happen elsewhere", False),
    ("vec4 c = lookup(tex, uv);", True),  # through a function it calls
])
def test_derivative_calls_are_found_as_calls_of_the_builtins(body, expected):
    source = HELPERS + f"void f(sampler2D tex, vec2 uv, float x, vec3 p)\n{{\n    {body}\n}}\n"
    assert uses_derivatives(function_of(source, "f")) is expected


def test_a_library_implementation_knows_whether_it_takes_derivatives():
    assert implementation("ND_image_color3").uses_derivatives  # an implicit-lod lookup
    assert not implementation("ND_noise2d_float").uses_derivatives


SOURCE = """struct OtherLobe { float a; };
struct LobeState { float a; };
struct Ignored { float a; };
struct FlatState { float a; };
void mx_other_prepare(float a, out OtherLobe lobe) {}
void mx_other(float a) {}
void mx_lobe(ClosureData closureData, float weight, out BSDF bsdf) {}
void  mx_lobe_prepare(ClosureData closureData,
                      float weight, out LobeState state)
{
}
void mx_lobe_prepare(float later, out Ignored state) {}
void notmx_flat_prepare(float a, out FlatState s) {}
void flat(float a) {}
void mx_flat_prepare(float a) {}
void mx_flat(float a) {}
void mx_missing(float a) {}
"""
PRELUDE = "struct ClosureData { int closureType; };\nstruct BSDF { vec3 response; vec3 throughput; };\n"


class Definitions:
    """The functions of checked items by name, in source order (what prepared_state asks a library)."""

    def __init__(self, items):
        self.items = flat_items(items)

    def functions(self, name):
        return [i for i in self.items if isinstance(i, ir.Function) and i.name == name]


def test_a_lobes_prepared_state_is_the_type_its_first_prepare_function_writes():
    items, _ = checked_code(PRELUDE + SOURCE, "")
    definitions = Definitions(items)

    def state(name):
        return prepared_state(definitions.functions(name)[0], definitions)

    assert state("mx_lobe") == "LobeState"
    assert state("mx_other") == "OtherLobe"
    assert state("mx_flat") is None  # writes no state
    assert state("flat") is None  # `notmx_flat_prepare` is another name
    assert state("mx_missing") is None


def test_the_librarys_lobes_with_a_prepare_function_know_its_state():
    assert implementation("ND_dielectric_bsdf").prepared_state == "SpecularLobe"
    assert implementation("ND_conductor_bsdf").prepared_state == "SpecularLobe"
    assert implementation("ND_oren_nayar_diffuse_bsdf").prepared_state is None


CALLEES = """float f(float x) { return x; }
float g(float x) { return x; }
float f(vec2 x) { return x.x; }
float mx_eval(float a, float b) { return a + b; }
float ior(float x) { return x; }
float mx_fresnel(float a, float b) { return a * b; }
"""


@pytest.mark.parametrize("code, expected", [
    ("f(x) + g (y)", {"f(float)", "g(float)"}),
    ("mx_eval\n    (x, y)", {"mx_eval(float,float)"}),  # blanks and a line break before the `(`
    ("f(vec2(x, y)) + f(x)", {"f(vec2)", "f(float)"}),  # each overload by its arguments' types
    ("2e1 + (x) * ((y))", set()),  # a number; bare parentheses
    ("mx_fresnel(ior(x), t[1].x)", {"mx_fresnel(float,float)", "ior(float)"}),
])
def test_the_calls_an_item_makes_are_its_resolved_callees(code, expected):
    source = CALLEES + f"float h(float x, float y, vec3 t[2])\n{{\n    return {code};\n}}\n"
    assert set(facts(function_of(source, "h")).calls) == expected


@pytest.mark.parametrize("arguments, count", [
    ("a, f(b, c[1]), (d +\n   e)", 3),
    ("a", 1),
    ("", 0),
])
def test_arguments_split_at_commas_outside_parentheses_and_brackets(arguments, count):
    call = parse_expression(f"mx_call({arguments})", "test")
    assert isinstance(call, ir.Call) and len(call.args) == count
