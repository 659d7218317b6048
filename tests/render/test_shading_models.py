"""The five shading models (libraries/bxdf) drawn in a white furnace: finite everywhere, lit, and
never brighter than the light around them when nothing emits."""
import numpy as np
import pytest

from shadergen.api import Generator
from shadergen.render.environment import Environment

GEN = Generator()
WHITE = Environment(np.ones((16, 32, 3), "f4"), np.ones((16, 32, 3), "f4"), "white-furnace")

# model: {case: inputs}
CASES = {
    "standard_surface": {
        "default": {},
        "coated metal": {"metalness": 1.0, "base_color": (0.9, 0.6, 0.3), "coat": 1.0, "coat_roughness": 0.3},
        "glass": {"transmission": 1.0, "specular_roughness": 0.3, "base": 0.0},
        "sheen subsurface": {"sheen": 1.0, "subsurface": 0.5, "specular_anisotropy": 0.5},
    },
    "open_pbr_surface": {
        "default": {},
        "coated metal": {"base_metalness": 1.0, "coat_weight": 1.0, "coat_darkening": 1.0},
        "glass": {"transmission_weight": 1.0, "specular_roughness": 0.3},
        "fuzz film": {"fuzz_weight": 1.0, "thin_film_weight": 1.0, "specular_roughness_anisotropy": 0.5},
    },
    "gltf_pbr": {
        "default": {},
        "dielectric": {"metallic": 0.0, "roughness": 0.4, "base_color": (0.8, 0.3, 0.2)},
        "clearcoat sheen": {"metallic": 0.0, "clearcoat": 1.0, "sheen_color": (0.5, 0.5, 0.5), "sheen_roughness": 0.5},
        "transmission": {"metallic": 0.0, "roughness": 0.2, "transmission": 1.0},
    },
    "UsdPreviewSurface": {
        "default": {},
        "metal coat": {"metallic": 1.0, "diffuseColor": (0.9, 0.6, 0.2), "clearcoat": 1.0},
        "specular workflow": {"useSpecularWorkflow": 1, "specularColor": (0.2, 0.4, 0.9), "roughness": 0.2},
    },
    "disney_principled": {
        "default": {},
        "metal": {"metallic": 1.0, "baseColor": (0.9, 0.7, 0.4), "roughness": 0.3},
        "clearcoat sheen": {"clearcoat": 1.0, "sheen": 1.0, "anisotropic": 0.5},
    },
}


def input_xml(name: str, value) -> str:
    if isinstance(value, tuple):
        return f'<input name="{name}" type="color3" value="{", ".join(map(str, value))}"/>'
    kind = "integer" if isinstance(value, int) else "float"
    return f'<input name="{name}" type="{kind}" value="{value}"/>'


def material(model: str, inputs: dict) -> str:
    body = "".join(input_xml(n, v) for n, v in inputs.items())
    return (f'<?xml version="1.0"?>\n<materialx version="1.39">\n<{model} name="sr" type="surfaceshader">{body}</{model}>\n'
            '<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="sr"/>'
            '</surfacematerial>\n</materialx>\n')


# Above 1.01 today because of the lobes themselves, not of how the graphs stack them: the Schlick
# lobe of a white rough metal (1.013) and clearcoat over sheen over it (1.022) lack the multiple-
# scattering compensation that issue 10's BSDF rewrite brings.
OVER_UNITY = {("gltf_pbr", "default"), ("gltf_pbr", "clearcoat sheen")}


def params():
    for model, cases in CASES.items():
        for case in cases:
            marks = [pytest.mark.xfail(reason="generalized_schlick_bsdf without energy compensation", strict=False)] \
                if (model, case) in OVER_UNITY else []
            yield pytest.param(model, case, marks=marks)


@pytest.mark.parametrize("model,case", list(params()))
def test_shading_model_in_a_white_furnace(renderer, model, case):
    record = GEN.prepare(material(model, CASES[model][case])).emit()
    assert "error" not in record, record.get("error")
    rgb = renderer.render(record, size=32, env=WHITE, env_samples=64).rgba[..., :3]
    covered = rgb[rgb.max(axis=2) > 0]  # the sphere, not the empty corners
    assert np.isfinite(rgb).all()
    assert len(covered) > 400 and covered.mean() > 0.02  # drawn and lit
    assert np.percentile(covered, 99.9) <= 1.01  # no energy made up


# Schlick's curve from F0 = 0.04 against the exact Fresnel of ior 1.5 that the refraction carries:
# +0.036 at cos 0.09, -0.020 at cos 0.46, equal at normal incidence.
SCHLICK_VS_EXACT = 0.04


@pytest.mark.parametrize("model,inputs,tolerance", [
    ("standard_surface", {"transmission": 1.0, "specular_roughness": 0.0, "base": 0.0}, 0.005),
    ("open_pbr_surface", {"transmission_weight": 1.0, "specular_roughness": 0.0}, 0.005),
    ("UsdPreviewSurface", {"opacity": 0.0, "roughness": 0.0}, 0.005),
    ("gltf_pbr", {"metallic": 0.0, "roughness": 0.0, "transmission": 1.0}, SCHLICK_VS_EXACT),
    ("disney_principled", {"specTrans": 1.0, "roughness": 0.0, "baseColor": (1.0, 1.0, 1.0)}, SCHLICK_VS_EXACT)])
def test_smooth_glass_returns_all_the_light(renderer, model, inputs, tolerance):
    """A smooth dielectric interface reflects F and lets 1 - F through: 1 at every pixel of a white
    furnace. Fresnel applied twice (the refraction layered below the reflection) gave F + (1 - F)^2,
    0.96 at the centre and 0.92 over the sphere. glTF's and Disney's reflection is Schlick's curve
    while the refraction carries the exact Fresnel: they agree at the centre and within
    SCHLICK_VS_EXACT elsewhere."""
    rgb = renderer.render(GEN.prepare(material(model, inputs)).emit(), size=32, env=WHITE, env_samples=64).rgba[..., :3]
    covered = rgb[rgb.max(axis=2) > 0]
    assert np.abs(rgb[15:17, 15:17] - 1.0).max() < 0.005
    assert np.abs(covered - 1.0).max() < tolerance
    assert abs(covered.mean() - 1.0) < 0.01
