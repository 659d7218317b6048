"""Calls of forwarding functions go straight to their targets (the forward pass,
shadergen/code/passes/forward.py), in every target."""
import re

import pytest

from .conftest import kept_code, material

CONDUCTOR = material('<conductor_bsdf name="b" type="BSDF"/>')

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


@pytest.mark.parametrize("target", ["glsl", "essl", "wgsl"])
def test_the_librarys_forwarders_are_called_straight_in_every_target(gen, target):
    """Without a thin film the environment a lobe reflects is its samples: the specialized shader
    calls mx_environment_samples and mx_fresnel_eval_film straight; where the film is a uniform
    (complete), mx_environment_reflected dispatches at run time and stays."""
    specialized = gen.prepare(CONDUCTOR, interface="specialized", environment="fis", target=target).emit()
    pixel = specialized["stages"]["pixel"]
    assert "mx_environment_samples(" in pixel and "mx_environment_reflected(" not in pixel
    assert "mx_fresnel_eval_film(" in pixel and not re.search(r"\bmx_fresnel_eval\(", pixel)
    complete = gen.prepare(CONDUCTOR, environment="fis", target=target).emit()
    assert "mx_environment_reflected(" in complete["stages"]["pixel"]
    assert specialized["passes"]["forward"] > complete["passes"]["forward"] > 0
