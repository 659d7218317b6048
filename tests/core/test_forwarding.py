"""Calls of forwarding functions go straight to their targets (targets/forwarding.py)."""
from .conftest import kept_code

LIBRARY = """float samples(vec3 N, bool film, out vec3 albedo)
{
    albedo = N;
    return film ? 1.0 : 0.0;
}

// Dispatches to the samples: reduced by the features to a forward.
float reflected(vec3 N, out vec3 albedo)
{
    return samples(N, false, albedo);
}

float swapped(bool film, vec3 N, out vec3 albedo)
{
    return samples(N, film, albedo);
}

float lobe(vec3 N)
{
    vec3 a;
    float r = reflected(normalize(N),
                        a);
    return r + swapped(true, N, a);
}
"""


def kept(main: str) -> str:
    return kept_code(LIBRARY, main)


def test_callers_call_the_target_and_the_forward_goes():
    code = kept("float x = lobe(vec3(1.0));")
    assert "    float r = samples(normalize(N), false, a);" in code
    assert "reflected" not in code and "Dispatches" not in code


def test_a_forward_that_reorders_its_parameters_stays():
    code = kept("float x = lobe(vec3(1.0));")
    assert "float swapped(bool film, vec3 N, out vec3 albedo)" in code and "swapped(true, N, a)" in code


def test_a_forward_main_calls_stays():
    code = kept("vec3 a; float x = reflected(vec3(1.0), a) + lobe(vec3(1.0));")
    assert "float reflected(vec3 N, out vec3 albedo)" in code and "float r = reflected(" in code


def test_a_forward_with_another_type_or_qualifier_stays():
    library = LIBRARY.replace("float reflected(vec3 N, out vec3 albedo)", "float reflected(vec3 N, inout vec3 albedo)")
    assert "float r = reflected(" in kept_code(library, "float x = lobe(vec3(1.0));")
