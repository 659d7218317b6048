"""Pixar's Lama nodes (libraries/bxdf/lama_ng.mtlx) draw what the pbrlib lobes they are built on
draw with the same parameters, and none returns more light than a white furnace sends."""
import sys
from pathlib import Path

import numpy as np
import pytest

from shadergen.api import Generator

from .test_shaderx_names import material, psnr

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
import stress  # noqa: E402  (the furnace environment and statistics of bench/stress.py)

GEN = Generator()
GOLD = '<input name="IOR" type="vector3" value="0.18, 0.42, 1.37"/><input name="extinction" type="vector3" value="3.42, 2.35, 1.77"/>'
GOLD_COLOR = '<input name="ior" type="color3" value="0.18, 0.42, 1.37"/><input name="extinction" type="color3" value="3.42, 2.35, 1.77"/>'
ALPHA = ('<roughness_anisotropy name="alpha" type="vector2"><input name="roughness" type="float" value="0.3"/>'
         '<input name="anisotropy" type="float" value="0.5"/></roughness_anisotropy>')
ROUGH = '<input name="roughness" type="float" value="0.3"/><input name="anisotropy" type="float" value="0.5"/>'
SCHLICK = '<input name="color0" type="color3" value="0.04, 0.04, 0.04"/><input name="color90" type="color3" value="1, 1, 1"/>'
DIFFUSE = ('<LamaDiffuse name="d" type="BSDF"><input name="color" type="color3" value="0.6, 0.3, 0.1"/>'
           '<input name="roughness" type="float" value="0.4"/><input name="energyCompensation" type="float" value="0"/></LamaDiffuse>')
ON = ('<oren_nayar_diffuse_bsdf name="d" type="BSDF"><input name="color" type="color3" value="0.6, 0.3, 0.1"/>'
      '<input name="roughness" type="float" value="0.4"/></oren_nayar_diffuse_bsdf>')
SHEEN = '<input name="color" type="color3" value="0.3, 0.5, 1"/><input name="roughness" type="float" value="0.4"/>'

# name: (Lama document, the same material written with pbrlib nodes)
PAIRS = {
    "LamaConductor scientific, anisotropic": (
        material(f'<LamaConductor name="b" type="BSDF"><input name="fresnelMode" type="integer" value="1"/>{GOLD}{ROUGH}'
                 '</LamaConductor>', "b"),
        material(f'{ALPHA}<conductor_bsdf name="b" type="BSDF">{GOLD_COLOR}'
                 '<input name="roughness" type="vector2" nodename="alpha"/></conductor_bsdf>', "b")),
    "LamaConductor artistic, tinted": (
        material('<LamaConductor name="b" type="BSDF"><input name="tint" type="color3" value="0.9, 0.8, 0.7"/>'
                 '<input name="reflectivity" type="color3" value="0.9, 0.6, 0.3"/><input name="edgeColor" type="color3" value="1, 0.9, 0.8"/>'
                 '</LamaConductor>', "b"),
        material('<artistic_ior name="c" type="multioutput"><input name="reflectivity" type="color3" value="0.9, 0.6, 0.3"/>'
                 '<input name="edge_color" type="color3" value="1, 0.9, 0.8"/></artistic_ior>'
                 '<conductor_bsdf name="m" type="BSDF"><input name="roughness" type="vector2" value="0.01, 0.01"/>'
                 '<input name="ior" type="color3" nodename="c" output="ior"/><input name="extinction" type="color3" nodename="c" output="extinction"/>'
                 '</conductor_bsdf><multiply name="b" type="BSDF"><input name="in1" type="BSDF" nodename="m"/>'
                 '<input name="in2" type="color3" value="0.9, 0.8, 0.7"/></multiply>', "b")),
    # reflectivity 0.04 is an IOR of 1.5; no absorption radius: clear glass, one tint for both parts
    "LamaDielectric": (
        material('<LamaDielectric name="b" type="BSDF"><input name="reflectivity" type="float" value="0.04"/>'
                 '<input name="reflectionTint" type="color3" value="0.9, 0.95, 1"/><input name="transmissionTint" type="color3" value="0.9, 0.95, 1"/>'
                 f'<input name="absorptionRadius" type="float" value="0"/>{ROUGH}</LamaDielectric>', "b"),
        material(f'{ALPHA}<dielectric_bsdf name="b" type="BSDF"><input name="ior" type="float" value="1.5"/>'
                 '<input name="tint" type="color3" value="0.9, 0.95, 1"/><input name="roughness" type="vector2" nodename="alpha"/>'
                 '<input name="scatter_mode" type="string" value="RT"/></dielectric_bsdf>', "b")),
    # a reflectivity profile of 0.2 is Schlick's exponent 5; white absorption absorbs nothing
    "LamaGeneralizedSchlick": (
        material(f'<LamaGeneralizedSchlick name="b" type="BSDF">{ROUGH}'
                 '<input name="reflectivity" type="color3" value="0.04, 0.04, 0.04"/></LamaGeneralizedSchlick>', "b"),
        material(f'{ALPHA}<generalized_schlick_bsdf name="b" type="BSDF">{SCHLICK}<input name="roughness" type="vector2" nodename="alpha"/>'
                 '<input name="scatter_mode" type="string" value="RT"/></generalized_schlick_bsdf>', "b")),
    "LamaDiffuse compensated": (
        material(DIFFUSE.replace('value="0"/></LamaDiffuse>', 'value="1"/></LamaDiffuse>'), "d"),
        material(ON.replace('</oren_nayar', '<input name="energy_compensation" type="boolean" value="true"/></oren_nayar'), "d")),
    "LamaSheen over LamaDiffuse, LamaMix 0.3": (
        material(DIFFUSE + f'<LamaSheen name="s" type="BSDF">{SHEEN}</LamaSheen><LamaMix name="b" type="BSDF">'
                 '<input name="material1" type="BSDF" nodename="d"/><input name="material2" type="BSDF" nodename="s"/>'
                 '<input name="mix" type="float" value="0.3"/></LamaMix>', "b"),
        material(ON + f'<sheen_bsdf name="s" type="BSDF">{SHEEN}</sheen_bsdf><mix name="b" type="BSDF">'
                 '<input name="fg" type="BSDF" nodename="s"/><input name="bg" type="BSDF" nodename="d"/>'
                 '<input name="mix" type="float" value="0.3"/></mix>', "b")),
    "LamaDielectric over LamaDiffuse, LamaLayer": (
        material(DIFFUSE + '<LamaDielectric name="t" type="BSDF"><input name="roughness" type="float" value="0.2"/></LamaDielectric>'
                 '<LamaLayer name="b" type="BSDF"><input name="materialTop" type="BSDF" nodename="t"/>'
                 '<input name="materialBase" type="BSDF" nodename="d"/></LamaLayer>', "b"),
        material(ON + '<dielectric_bsdf name="t" type="BSDF"><input name="roughness" type="vector2" value="0.04, 0.04"/>'
                 '</dielectric_bsdf><layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="t"/>'
                 '<input name="base" type="BSDF" nodename="d"/></layer>', "b")),
    "LamaTranslucent and LamaSSS, LamaAdd": (
        material('<LamaTranslucent name="t" type="BSDF"><input name="color" type="color3" value="0.2, 0.7, 0.4"/></LamaTranslucent>'
                 '<LamaSSS name="s" type="BSDF"><input name="color" type="color3" value="0.8, 0.4, 0.3"/>'
                 '<input name="sssRadius" type="color3" value="1, 0.5, 0.25"/><input name="sssScale" type="float" value="2"/></LamaSSS>'
                 '<LamaAdd name="b" type="BSDF"><input name="material1" type="BSDF" nodename="t"/><input name="material2" type="BSDF" nodename="s"/>'
                 '<input name="weight1" type="float" value="0.5"/><input name="weight2" type="float" value="0.25"/></LamaAdd>', "b"),
        material('<translucent_bsdf name="t" type="BSDF"><input name="weight" type="float" value="0.5"/>'
                 '<input name="color" type="color3" value="0.2, 0.7, 0.4"/></translucent_bsdf>'
                 '<subsurface_bsdf name="s" type="BSDF"><input name="weight" type="float" value="0.25"/>'
                 '<input name="color" type="color3" value="0.8, 0.4, 0.3"/><input name="radius" type="color3" value="2, 1, 0.5"/></subsurface_bsdf>'
                 '<add name="b" type="BSDF"><input name="in1" type="BSDF" nodename="t"/><input name="in2" type="BSDF" nodename="s"/></add>', "b")),
    "LamaEmission, LamaMix of EDFs": (
        material(DIFFUSE + '<LamaEmission name="e1" type="EDF"><input name="color" type="color3" value="0.4, 0.3, 0.2"/></LamaEmission>'
                 '<LamaEmission name="e2" type="EDF"><input name="color" type="color3" value="0.1, 0.2, 0.6"/></LamaEmission>'
                 '<LamaMix name="e" type="EDF"><input name="material1" type="EDF" nodename="e1"/><input name="material2" type="EDF" nodename="e2"/>'
                 '<input name="mix" type="float" value="0.75"/></LamaMix>', "d", "e"),
        material(ON + '<uniform_edf name="e" type="EDF"><input name="color" type="color3" value="0.175, 0.225, 0.5"/></uniform_edf>', "d", "e")),
}


def record_of(document: str) -> dict:
    record = GEN.prepare(document).emit()
    assert "error" not in record, record.get("error")
    return record


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_a_lama_node_draws_as_the_pbrlib_lobes_it_is_built_on(renderer, name):
    lama, pbrlib = (renderer.render(record_of(d), size=32).rgba for d in PAIRS[name])
    assert np.isfinite(lama).all()
    assert lama[..., :3].max() > 0.01  # something was drawn
    assert psnr(lama, pbrlib) >= 60.0, psnr(lama, pbrlib)


IRIDESCENCE = material('<LamaIridescence name="b" type="BSDF"><input name="roughness" type="float" value="0.2"/></LamaIridescence>', "b")
# a film over gold, coating it: the layer is lit by the furnace from every side
COATED_GOLD = material(f'<LamaConductor name="g" type="BSDF"><input name="fresnelMode" type="integer" value="1"/>{GOLD}</LamaConductor>'
                       '<LamaIridescence name="f" type="BSDF"/><LamaLayer name="b" type="BSDF"><input name="materialTop" type="BSDF" nodename="f"/>'
                       '<input name="materialBase" type="BSDF" nodename="g"/></LamaLayer>', "b")
FURNACE = {"LamaIridescence": IRIDESCENCE, "LamaIridescence over LamaConductor": COATED_GOLD,
           **{name: lama for name, (lama, _) in PAIRS.items() if "Emission" not in name}}


@pytest.mark.parametrize("name", sorted(FURNACE))
def test_a_lama_material_returns_at_most_what_a_white_furnace_sends(renderer, name):
    stats = stress.render_records(renderer, {name: record_of(FURNACE[name])}, 32, 32, stress.white_furnace())[name]
    assert stats["nan"] == 0 and stats["negative"] == 0, stats
    assert 0.0 < stats["p999"] <= stress.LIMIT, stats


def test_lama_iridescence_colours_the_reflection_by_the_film(renderer):
    """A free-standing film over a black base, in white light: what it reflects, a few per cent, is
    coloured by interference, and the colour changes with the film's thickness (a film-less
    reflection of white light would stay grey)."""
    def over_black(thickness: float) -> str:
        return material('<LamaDiffuse name="black" type="BSDF"><input name="color" type="color3" value="0, 0, 0"/></LamaDiffuse>'
                        '<LamaIridescence name="f" type="BSDF"><input name="roughness" type="float" value="0.2"/>'
                        f'<input name="relativeFilmThickness" type="float" value="{thickness}"/></LamaIridescence>'
                        '<LamaLayer name="b" type="BSDF"><input name="materialTop" type="BSDF" nodename="f"/>'
                        '<input name="materialBase" type="BSDF" nodename="black"/></LamaLayer>', "b")

    thin, thick = (renderer.render(record_of(over_black(t)), size=32, env=stress.white_furnace()).rgba for t in (0.1, 0.9))
    covered = thin[..., 3] > 0
    mean_thin, mean_thick = thin[covered, :3].mean(axis=0), thick[covered, :3].mean(axis=0)
    assert 0.005 < mean_thin.max() < 0.5 and 0.005 < mean_thick.max() < 0.5
    assert np.ptp(mean_thin) > 0.01 or np.ptp(mean_thick) > 0.01  # coloured, not grey
    assert np.abs(mean_thin - mean_thick).max() > 0.01  # the thickness moves the colour
