"""The prefiltered environment (--env-method prefilter and hybrid): the DFG table of tools/fit_dfg.py
against a direct integration, a material drawn each way, the prefiltered ones close to a converged
FIS, and the hybrid's control variate in a white furnace, where its answer is the table's albedo."""
import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

from shadergen.api import Generator
from shadergen.render import RenderError
from shadergen.render.environment import Environment
from shadergen.render.imageio import srgb_encode

ROOT = Path(__file__).resolve().parents[2]
DFG_GLSL = ROOT / "libraries/pbrlib/genglsl/lib/mx_environment_dfg.glsl"
_spec = importlib.util.spec_from_file_location("fit_dfg", ROOT / "tools/fit_dfg.py")
fit_dfg = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(fit_dfg)


def schlick(c):
    return 0.04 + 0.96 * (1.0 - c) ** 5


def direct_moments(n_dot_v: float, alpha: float, steps: int = 1200) -> np.ndarray:
    """m_k = integral of VdotH^k D G2 / (4 NdotV) over L, k = 0..3, and last that of Schlick's
    Fresnel of ior 1.5 in place of VdotH^k, by the midpoint rule over L's
    (cos theta, phi), from GGX's D and height-correlated G2 as written in the papers: independent
    of the visible-normal sampling the script uses."""
    cos_l = (np.arange(steps) + 0.5) / steps
    phi = (np.arange(2 * steps) + 0.5) / (2 * steps) * 2.0 * np.pi
    c, p = np.meshgrid(cos_l, phi, indexing="ij")
    s = np.sqrt(1.0 - c * c)
    light = np.stack([s * np.cos(p), s * np.sin(p), c], -1)
    view = np.array([np.sqrt(1.0 - n_dot_v ** 2), 0.0, n_dot_v])
    half = light + view
    half /= np.linalg.norm(half, axis=-1)[..., None]
    n_dot_h, v_dot_h = half[..., 2], half @ view
    d = alpha ** 2 / (np.pi * (n_dot_h ** 2 * (alpha ** 2 - 1.0) + 1.0) ** 2)

    def smith_lambda(x):
        return 0.5 * (np.sqrt(1.0 + alpha ** 2 * (1.0 - x * x) / (x * x)) - 1.0)

    brdf_cos = d / (1.0 + smith_lambda(n_dot_v) + smith_lambda(c)) / (4.0 * n_dot_v)
    solid_angle = (1.0 / steps) * (np.pi / steps)
    integrands = [v_dot_h ** k for k in range(4)] + [schlick(v_dot_h)]
    return np.array([(brdf_cos * g).sum() * solid_angle for g in integrands])


def shipped_table() -> np.ndarray:
    """(size, size, 4): (c1, c2, w1, w2) from the GLSL arrays the shaders compile."""
    text = DFG_GLSL.read_text()
    channels = [np.array([float(x) for x in re.search(rf"{name}\[\d+\] = float\[\]\(([^;]*)\);", text, re.S)
                          .group(1).replace("\n", " ").split(",")]) for name in fit_dfg.NAMES]
    size = int(round(len(channels[0]) ** 0.5))
    return np.stack(channels, -1).reshape(size, size, 4)


@pytest.mark.parametrize("row,column", [(5, 6), (10, 9), (15, 15), (8, 12), (3, 15)])
def test_shipped_dfg_table_matches_direct_integration(row, column):
    """The table's quadrature rule reproduces the measure's moments, so it integrates any cubic
    in VdotH exactly: Schlick's Fresnel (a quintic) closely."""
    table = shipped_table()
    size = table.shape[0]
    n_dot_v, roughness = (row / (size - 1)) ** 2, column / (size - 1)
    c1, c2, w1, w2 = table[row, column]
    expected = direct_moments(n_dot_v, roughness ** 2)
    assert [w1 * c1 ** k + w2 * c2 ** k for k in range(4)] == pytest.approx(expected[:4], abs=2e-3)
    assert w1 * schlick(c1) + w2 * schlick(c2) == pytest.approx(expected[4], abs=1e-2)


@pytest.mark.parametrize("n_dot_v,alpha", [(0.3, 0.5), (0.7, 0.2), (0.05, 0.9)])
def test_script_integration_matches_direct_integration_between_nodes(n_dot_v, alpha):
    assert fit_dfg.moments(n_dot_v, alpha) == pytest.approx(direct_moments(n_dot_v, alpha)[:4], abs=1e-3)


def psnr(image: np.ndarray, reference: np.ndarray) -> float:
    """Over the object's pixels, clipped to [0, 1] and sRGB-encoded, peak 1."""
    covered = reference[..., 3] > 0
    image, reference = (srgb_encode(np.clip(x[..., :3], 0.0, 1.0)) for x in (image, reference))
    mse = float(((image - reference)[covered] ** 2).mean())
    return 10.0 * np.log10(1.0 / mse)


MATERIALS = {
    "rough copper": '<input name="metalness" type="float" value="1"/>'
                    '<input name="base_color" type="color3" value="0.95, 0.64, 0.54"/>'
                    '<input name="specular_roughness" type="float" value="0.35"/>',
    "glossy plastic": '<input name="base_color" type="color3" value="0.1, 0.3, 0.8"/>'
                      '<input name="specular_roughness" type="float" value="0.15"/>',
}


def standard_surface(inputs: str, **options) -> dict:
    return Generator().prepare('<?xml version="1.0"?><materialx version="1.39">'
                               f'<standard_surface name="sr" type="surfaceshader">{inputs}</standard_surface>'
                               '<surfacematerial name="mat" type="material">'
                               '<input name="surfaceshader" type="surfaceshader" nodename="sr"/>'
                               '</surfacematerial></materialx>', **options).emit()


@pytest.mark.parametrize("name", sorted(MATERIALS))
def test_prefiltered_render_is_close_to_converged_fis(renderer, name):
    record = standard_surface(MATERIALS[name])
    converged = renderer.render(record, size=48, env_samples=1024).rgba
    prefiltered = renderer.render(record, size=48, env_method="prefilter")
    few_samples = renderer.render(record, size=48, env_samples=4).rgba
    assert np.isfinite(prefiltered.rgba).all() and not prefiltered.warnings
    assert psnr(prefiltered.rgba, converged) > 32.0
    assert psnr(prefiltered.rgba, converged) > psnr(few_samples, converged) + 3.0


@pytest.mark.parametrize("name", sorted(MATERIALS))
def test_hybrid_render_is_closer_to_converged_than_sampling_and_keeps_the_lookup(renderer, name):
    """Four correcting samples, read smoothly from the prefiltered map, are closer to the converged
    image than four times as many FIS samples, and never lose what the single lookup had (they
    gain most at grazing views, which these 48-pixel spheres hardly have: bench/accuracy_time.py)."""
    record = standard_surface(MATERIALS[name])
    converged = renderer.render(record, size=48, env_samples=1024).rgba
    hybrid = renderer.render(record, size=48, env_method="hybrid", env_samples=4)
    assert np.isfinite(hybrid.rgba).all() and not hybrid.warnings
    closeness = psnr(hybrid.rgba, converged)
    assert closeness > psnr(renderer.render(record, size=48, env_samples=16).rgba, converged) + 3.0
    assert closeness > psnr(renderer.render(record, size=48, env_method="prefilter").rgba, converged) - 1.0


# Radiance 1 from everywhere: every mean radiance the hybrid forms is 1, the lookup's and the two
# sample sets' (whose difference is the control variate), so a lobe returns exactly its albedo.
WHITE = Environment(np.ones((16, 32, 3), "f4"), np.ones((16, 32, 3), "f4"), "white-furnace")
WHITE_METAL = ('<input name="base" type="float" value="1"/><input name="metalness" type="float" value="1"/>'
               '<input name="base_color" type="color3" value="1, 1, 1"/>'
               '<input name="specular_color" type="color3" value="1, 1, 1"/>')


@pytest.mark.parametrize("roughness", [0.05, 0.4, 0.9])
@pytest.mark.parametrize("samples", [1, 4])
def test_hybrid_in_a_white_furnace_is_the_albedo(renderer, roughness, samples):
    """In a constant environment the samples' correction vanishes at every pixel, grazing ones
    included: the hybrid draws exactly what the single lookup draws, the table's albedo, which for
    a white metal (Turquin's compensation restoring the multiple scattering) is all the light, to
    the table's precision at grazing views."""
    record = standard_surface(WHITE_METAL + f'<input name="specular_roughness" type="float" value="{roughness}"/>')
    hybrid = renderer.render(record, size=32, env=WHITE, env_method="hybrid", env_samples=samples).rgba[..., :3]
    lookup = renderer.render(record, size=32, env=WHITE, env_method="prefilter").rgba[..., :3]
    covered = hybrid.max(axis=2) > 0
    assert covered.sum() > 400
    assert np.abs(hybrid - lookup).max() < 1e-5
    assert hybrid[covered].min() > 0.98 and hybrid[covered].max() <= 1.01


def test_hybrid_gives_an_anisotropic_lobe_its_own_albedo(renderer):
    """The table holds isotropic lobes; an anisotropic one reflects up to a few percent more or less
    at grazing views, depending on the view's azimuth. In a white furnace (no radiance error, only
    the albedo's) the hybrid's samples bring a glossy anisotropic dielectric closer to what the
    converged sampling gives than the table's isotropic value is."""
    record = standard_surface('<input name="base" type="float" value="0"/>'
                              '<input name="specular_roughness" type="float" value="0.4"/>'
                              '<input name="specular_anisotropy" type="float" value="0.5"/>')
    converged = renderer.render(record, size=32, env=WHITE, env_samples=1024).rgba
    hybrid = renderer.render(record, size=32, env=WHITE, env_method="hybrid", env_samples=8).rgba
    lookup = renderer.render(record, size=32, env=WHITE, env_method="prefilter").rgba
    assert psnr(hybrid, converged) > psnr(lookup, converged) + 3.0


def test_unknown_env_method_is_refused(renderer):
    record = standard_surface("")
    with pytest.raises(RenderError) as error:
        renderer.render(record, size=8, env_method="pathtrace")
    assert error.value.code == "invalid_request"


def test_a_shader_generated_for_one_env_method_draws_as_the_one_with_both(renderer):
    inputs = MATERIALS["rough copper"]
    both = standard_surface(inputs, interface="specialized")
    for method in ("fis", "prefilter", "hybrid"):
        only = standard_surface(inputs, interface="specialized", environment=method)
        assert only["stages"]["pixel"].count("\n") < both["stages"]["pixel"].count("\n")
        same = renderer.render(only, size=32, env_method=method).rgba
        assert np.array_equal(same, renderer.render(both, size=32, env_method=method).rgba)


def test_a_shader_generated_for_fis_is_not_drawn_with_the_prefiltered_map(renderer):
    record = standard_surface("", interface="specialized", environment="fis")
    with pytest.raises(RenderError) as error:
        renderer.render(record, size=8, env_method="prefilter")
    assert error.value.code == "invalid_request" and "fis" in error.value.message
