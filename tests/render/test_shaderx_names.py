"""The seed's own PBR node names (libraries/shaderx, seed section 4): a document written with them
renders the same image as the same material written with the MaterialX 1.39 nodes."""
import math
from pathlib import Path

import numpy as np
import pytest

from shadergen.api import Generator

GEN = Generator()


def document(body: str) -> str:
    return f'<?xml version="1.0"?>\n<materialx version="1.39">\n{body}\n</materialx>\n'


def material(nodes: str, bsdf: str | None = None, edf: str | None = None, shader: str | None = None) -> str:
    """A material over `nodes`: either its own surface of `bsdf`/`edf`, or the surface shader `shader`."""
    if shader is None:
        links = "".join(f'<input name="{n}" type="{n.upper()}" nodename="{v}"/>' for n, v in (("bsdf", bsdf), ("edf", edf)) if v)
        nodes += f'\n<surface name="srf" type="surfaceshader">{links}</surface>'
        shader = "srf"
    return document(nodes + f'\n<surfacematerial name="mat" type="material"><input name="surfaceshader" '
                            f'type="surfaceshader" nodename="{shader}"/></surfacematerial>')


DIFFUSE_SEED = ('<diffusebrdf name="under" type="BSDF"><input name="color" type="color3" value="0.6, 0.3, 0.1"/>'
                '<input name="roughness" type="float" value="0.4"/></diffusebrdf>')
DIFFUSE_MODERN = ('<oren_nayar_diffuse_bsdf name="under" type="BSDF"><input name="color" type="color3" value="0.6, 0.3, 0.1"/>'
                  '<input name="roughness" type="float" value="0.4"/></oren_nayar_diffuse_bsdf>')
ROUGH = '<input name="roughness" type="vector2" value="0.2, 0.35"/>'
GLASS = '<input name="ior" type="float" value="1.45"/><input name="tint" type="color3" value="0.9, 0.8, 1.0"/>'
FILM = '<input name="thickness" type="float" value="400"/><input name="ior" type="float" value="1.3"/>'
MODERN_FILM = '<input name="thinfilm_thickness" type="float" value="400"/><input name="thinfilm_ior" type="float" value="1.3"/>'

# name: (seed document, 1.39 document)
PAIRS = {
    "diffusebrdf": (material(DIFFUSE_SEED, "under"), material(DIFFUSE_MODERN, "under")),
    "diffusebtdf": (
        material('<diffusebtdf name="b" type="BSDF"><input name="color" type="color3" value="0.2, 0.7, 0.4"/></diffusebtdf>', "b"),
        material('<translucent_bsdf name="b" type="BSDF"><input name="color" type="color3" value="0.2, 0.7, 0.4"/></translucent_bsdf>', "b")),
    # complexior into conductorbrdf must give back the complex IOR the 1.39 conductor takes directly
    "conductorbrdf+complexior": (
        material('<complexior name="c" type="multioutput"><input name="ior" type="color3" value="0.27, 0.68, 1.32"/>'
                 '<input name="extinction" type="color3" value="3.61, 2.62, 2.29"/></complexior>'
                 f'<conductorbrdf name="b" type="BSDF">{ROUGH}<input name="reflectivity" type="color3" nodename="c" output="reflectivity"/>'
                 '<input name="edgecolor" type="color3" nodename="c" output="edgecolor"/></conductorbrdf>', "b"),
        material(f'<conductor_bsdf name="b" type="BSDF">{ROUGH}<input name="ior" type="color3" value="0.27, 0.68, 1.32"/>'
                 '<input name="extinction" type="color3" value="3.61, 2.62, 2.29"/></conductor_bsdf>', "b")),
    "dielectricbrdf+base": (
        material(DIFFUSE_SEED + f'<dielectricbrdf name="b" type="BSDF">{ROUGH}{GLASS}'
                 '<input name="base" type="BSDF" nodename="under"/></dielectricbrdf>', "b"),
        material(DIFFUSE_MODERN + f'<dielectric_bsdf name="top" type="BSDF">{ROUGH}{GLASS}</dielectric_bsdf>'
                 '<layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="top"/>'
                 '<input name="base" type="BSDF" nodename="under"/></layer>', "b")),
    "dielectricbrdf ior 0": (
        material(f'<dielectricbrdf name="b" type="BSDF">{ROUGH}<input name="ior" type="float" value="0"/>'
                 '<input name="weight" type="float" value="0.5"/><input name="tint" type="color3" value="1, 0.5, 0.2"/></dielectricbrdf>', "b"),
        material(f'<generalized_schlick_bsdf name="b" type="BSDF">{ROUGH}<input name="weight" type="float" value="0.5"/>'
                 + "".join(f'<input name="color{a}" type="color3" value="1, 0.5, 0.2"/>' for a in ("0", "82", "90"))
                 + '</generalized_schlick_bsdf>', "b")),
    "dielectricbtdf+interior+vdfs": (
        material('<absorptionvdf name="a" type="VDF"><input name="absorption" type="color3" value="0.5, 0.2, 0.1"/></absorptionvdf>'
                 '<anisotropicvdf name="s" type="VDF"><input name="absorption" type="color3" value="0.1, 0.1, 0.1"/>'
                 '<input name="scattering" type="color3" value="1, 2, 3"/><input name="anisotropy" type="float" value="0.3"/></anisotropicvdf>'
                 '<scalevdf name="sa" type="VDF"><input name="in" type="VDF" nodename="a"/><input name="weight" type="color3" value="2, 1, 1"/></scalevdf>'
                 '<mixvdf name="m" type="VDF"><input name="in1" type="VDF" nodename="sa"/><input name="in2" type="VDF" nodename="s"/>'
                 '<input name="weight" type="float" value="0.25"/></mixvdf>'
                 f'<dielectricbtdf name="b" type="BSDF">{GLASS}<input name="interior" type="VDF" nodename="m"/></dielectricbtdf>', "b"),
        material('<absorption_vdf name="a" type="VDF"><input name="absorption" type="vector3" value="0.5, 0.2, 0.1"/></absorption_vdf>'
                 '<anisotropic_vdf name="s" type="VDF"><input name="absorption" type="vector3" value="0.1, 0.1, 0.1"/>'
                 '<input name="scattering" type="vector3" value="1, 2, 3"/><input name="anisotropy" type="float" value="0.3"/></anisotropic_vdf>'
                 '<multiply name="sa" type="VDF"><input name="in1" type="VDF" nodename="a"/><input name="in2" type="color3" value="2, 1, 1"/></multiply>'
                 '<mix name="m" type="VDF"><input name="fg" type="VDF" nodename="s"/><input name="bg" type="VDF" nodename="sa"/>'
                 '<input name="mix" type="float" value="0.25"/></mix>'
                 f'<dielectric_bsdf name="t" type="BSDF">{GLASS}<input name="roughness" type="vector2" value="0, 0"/>'
                 '<input name="scatter_mode" type="string" value="T"/></dielectric_bsdf>'
                 '<layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="t"/><input name="base" type="VDF" nodename="m"/></layer>', "b")),
    # the film reaches the lobes inside dielectricbrdf (not the diffuse base) ...
    "thinfilmbxdf+dielectricbrdf": (
        material(DIFFUSE_SEED + f'<dielectricbrdf name="coat" type="BSDF">{ROUGH}{GLASS}'
                 '<input name="base" type="BSDF" nodename="under"/></dielectricbrdf>'
                 f'<thinfilmbxdf name="b" type="BSDF">{FILM}<input name="base" type="BSDF" nodename="coat"/></thinfilmbxdf>', "b"),
        material(DIFFUSE_MODERN + f'<dielectric_bsdf name="top" type="BSDF">{ROUGH}{GLASS}{MODERN_FILM}</dielectric_bsdf>'
                 '<layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="top"/>'
                 '<input name="base" type="BSDF" nodename="under"/></layer>', "b")),
    # ... and a conductor's, with the seed's default film (550 nm, ior 1.5)
    "thinfilmbxdf+conductorbrdf": (
        material(f'<conductorbrdf name="metal" type="BSDF">{ROUGH}</conductorbrdf>'
                 '<thinfilmbxdf name="b" type="BSDF"><input name="base" type="BSDF" nodename="metal"/></thinfilmbxdf>', "b"),
        material('<artistic_ior name="c" type="multioutput"><input name="reflectivity" type="color3" value="0.8, 0.8, 0.8"/>'
                 '<input name="edge_color" type="color3" value="1, 1, 1"/></artistic_ior>'
                 f'<conductor_bsdf name="b" type="BSDF">{ROUGH}<input name="ior" type="color3" nodename="c" output="ior"/>'
                 '<input name="extinction" type="color3" nodename="c" output="extinction"/>'
                 '<input name="thinfilm_thickness" type="float" value="550"/><input name="thinfilm_ior" type="float" value="1.5"/>'
                 '</conductor_bsdf>', "b")),
    "subsurfacebrdf": (
        material('<subsurfacebrdf name="b" type="BSDF"><input name="color" type="color3" value="0.8, 0.4, 0.3"/>'
                 '<input name="radius" type="vector3" value="1, 0.5, 0.25"/></subsurfacebrdf>', "b"),
        material('<subsurface_bsdf name="b" type="BSDF"><input name="color" type="color3" value="0.8, 0.4, 0.3"/>'
                 '<input name="radius" type="color3" value="1, 0.5, 0.25"/></subsurface_bsdf>', "b")),
    "sheenbrdf+base": (
        material(DIFFUSE_SEED + '<sheenbrdf name="b" type="BSDF"><input name="color" type="color3" value="0.3, 0.5, 1"/>'
                 '<input name="base" type="BSDF" nodename="under"/></sheenbrdf>', "b"),
        material(DIFFUSE_MODERN + '<sheen_bsdf name="top" type="BSDF"><input name="color" type="color3" value="0.3, 0.5, 1"/>'
                 '<input name="roughness" type="float" value="0.2"/></sheen_bsdf>'
                 '<layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="top"/>'
                 '<input name="base" type="BSDF" nodename="under"/></layer>', "b")),
    # roughness_dual with the seed's two scalars; glossiness_anisotropy and roughness_anisotropy
    # are 1.39's own nodes under the seed's inputs
    "mixbsdf+scalebsdf+roughness nodes": (
        material(DIFFUSE_SEED + '<roughness_dual name="r" type="vector2"><input name="roughnessX" type="float" value="0.3"/>'
                 '<input name="roughnessY" type="float" value="0.6"/></roughness_dual>'
                 '<glossiness_anisotropy name="g" type="vector2"><input name="glossiness" type="float" value="0.7"/>'
                 '<input name="anisotropy" type="float" value="0.5"/></glossiness_anisotropy>'
                 '<conductorbrdf name="m1" type="BSDF"><input name="roughness" type="vector2" nodename="r"/></conductorbrdf>'
                 '<conductorbrdf name="m2" type="BSDF"><input name="roughness" type="vector2" nodename="g"/></conductorbrdf>'
                 '<scalebsdf name="s" type="BSDF"><input name="in" type="BSDF" nodename="m2"/>'
                 '<input name="weight" type="color3" value="2, 1, 0.5"/></scalebsdf>'
                 '<mixbsdf name="mm" type="BSDF"><input name="in1" type="BSDF" nodename="m1"/><input name="in2" type="BSDF" nodename="s"/>'
                 '<input name="weight" type="float" value="0.5"/></mixbsdf>'
                 '<mixbsdf name="b" type="BSDF"><input name="in1" type="BSDF" nodename="under"/><input name="in2" type="BSDF" nodename="mm"/>'
                 '<input name="weight" type="float" value="0.3"/></mixbsdf>', "b"),
        material(DIFFUSE_MODERN + '<roughness_dual name="r" type="vector2"><input name="roughness" type="vector2" value="0.3, 0.6"/></roughness_dual>'
                 '<glossiness_anisotropy name="g" type="vector2"><input name="glossiness" type="float" value="0.7"/>'
                 '<input name="anisotropy" type="float" value="0.5"/></glossiness_anisotropy>'
                 '<artistic_ior name="c" type="multioutput"><input name="reflectivity" type="color3" value="0.8, 0.8, 0.8"/>'
                 '<input name="edge_color" type="color3" value="1, 1, 1"/></artistic_ior>'
                 '<conductor_bsdf name="m1" type="BSDF"><input name="roughness" type="vector2" nodename="r"/>'
                 '<input name="ior" type="color3" nodename="c" output="ior"/><input name="extinction" type="color3" nodename="c" output="extinction"/></conductor_bsdf>'
                 '<conductor_bsdf name="m2" type="BSDF"><input name="roughness" type="vector2" nodename="g"/>'
                 '<input name="ior" type="color3" nodename="c" output="ior"/><input name="extinction" type="color3" nodename="c" output="extinction"/></conductor_bsdf>'
                 '<multiply name="s" type="BSDF"><input name="in1" type="BSDF" nodename="m2"/>'
                 '<input name="in2" type="color3" value="1, 0.5, 0.25"/></multiply>'
                 '<mix name="mm" type="BSDF"><input name="fg" type="BSDF" nodename="s"/><input name="bg" type="BSDF" nodename="m1"/>'
                 '<input name="mix" type="float" value="0.5"/></mix>'
                 '<mix name="b" type="BSDF"><input name="fg" type="BSDF" nodename="mm"/><input name="bg" type="BSDF" nodename="under"/>'
                 '<input name="mix" type="float" value="0.3"/></mix>', "b")),
    "edfs+blackbody": (
        material(DIFFUSE_SEED + '<blackbody name="k" type="color3"><input name="temperature" type="float" value="3000"/></blackbody>'
                 '<uniformedf name="u" type="EDF"><input name="color" type="color3" nodename="k"/></uniformedf>'
                 '<conicaledf name="c" type="EDF"><input name="color" type="color3" value="0.2, 0.4, 0.1"/>'
                 '<parameter name="inner_angle" type="float" value="20"/><parameter name="outer_angle" type="float" value="50"/></conicaledf>'
                 '<scaledf name="s" type="EDF"><input name="in" type="EDF" nodename="c"/><input name="weight" type="color3" value="1, 2, 3"/></scaledf>'
                 '<mixedf name="e" type="EDF"><input name="in1" type="EDF" nodename="u"/><input name="in2" type="EDF" nodename="s"/>'
                 '<input name="weight" type="float" value="0.6"/></mixedf>', "under", "e"),
        material(DIFFUSE_MODERN + '<blackbody name="k" type="color3"><input name="temperature" type="float" value="3000"/></blackbody>'
                 '<uniform_edf name="u" type="EDF"><input name="color" type="color3" nodename="k"/></uniform_edf>'
                 '<conical_edf name="c" type="EDF"><input name="color" type="color3" value="0.2, 0.4, 0.1"/>'
                 '<input name="inner_angle" type="float" value="20"/><input name="outer_angle" type="float" value="50"/></conical_edf>'
                 '<multiply name="s" type="EDF"><input name="in1" type="EDF" nodename="c"/><input name="in2" type="color3" value="1, 2, 3"/></multiply>'
                 '<mix name="e" type="EDF"><input name="fg" type="EDF" nodename="s"/><input name="bg" type="EDF" nodename="u"/>'
                 '<input name="mix" type="float" value="0.6"/></mix>', "under", "e")),
    "measurededf": (
        material(DIFFUSE_SEED + '<measurededf name="e" type="EDF"><input name="color" type="color3" value="0.4, 0.3, 0.2"/></measurededf>',
                 "under", "e"),
        material(DIFFUSE_MODERN + '<measured_edf name="e" type="EDF"><input name="color" type="color3" value="0.4, 0.3, 0.2"/></measured_edf>',
                 "under", "e")),
    "mixsurface": (
        material(DIFFUSE_SEED + '<surface name="s1" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="under"/></surface>'
                 '<conductorbrdf name="m" type="BSDF"/><surface name="s2" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="m"/></surface>'
                 '<mixsurface name="ms" type="surfaceshader"><input name="in1" type="surfaceshader" nodename="s1"/>'
                 '<input name="in2" type="surfaceshader" nodename="s2"/><input name="weight" type="float" value="0.7"/></mixsurface>', shader="ms"),
        material(DIFFUSE_MODERN + '<surface name="s1" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="under"/></surface>'
                 '<artistic_ior name="c" type="multioutput"><input name="reflectivity" type="color3" value="0.8, 0.8, 0.8"/>'
                 '<input name="edge_color" type="color3" value="1, 1, 1"/></artistic_ior>'
                 '<conductor_bsdf name="m" type="BSDF"><input name="roughness" type="vector2" value="0.1, 0.1"/>'
                 '<input name="ior" type="color3" nodename="c" output="ior"/><input name="extinction" type="color3" nodename="c" output="extinction"/></conductor_bsdf>'
                 '<surface name="s2" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="m"/></surface>'
                 '<mix name="ms" type="surfaceshader"><input name="fg" type="surfaceshader" nodename="s2"/>'
                 '<input name="bg" type="surfaceshader" nodename="s1"/><input name="mix" type="float" value="0.7"/></mix>', shader="ms")),
}


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    mse = float(np.mean((a.astype("f8") - b.astype("f8")) ** 2))
    return math.inf if mse == 0 else 10.0 * math.log10(1.0 / mse)


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_seed_document_renders_as_its_modern_equivalent(renderer, name):
    seed, modern = (GEN.prepare(d).emit() for d in PAIRS[name])
    assert "error" not in seed, seed.get("error")
    assert "error" not in modern, modern.get("error")
    ours, theirs = (renderer.render(r, size=32).rgba for r in (seed, modern))
    assert np.isfinite(ours).all()
    assert ours[..., :3].max() > 0.01  # something was drawn
    assert psnr(ours, theirs) >= 60.0


# thinsurface (seed 4.5): two-sided, a BSDF and an EDF per side. On this mesh the faces seen from
# behind are exactly those right of x = 0, so the modern document picks the back side by position.
TWO_SIDED = str(Path(__file__).parent / "data" / "two_sided.obj")
FRONT = ('<diffusebrdf name="front" type="BSDF"><input name="color" type="color3" value="0.8, 0.2, 0.1"/></diffusebrdf>'
         '<uniformedf name="glow" type="EDF"><input name="color" type="color3" value="0.05, 0.05, 0.02"/></uniformedf>')
BACK = (f'<conductorbrdf name="back" type="BSDF">{ROUGH}<input name="reflectivity" type="color3" value="0.1, 0.3, 0.9"/>'
        '</conductorbrdf>')
BACK_MODERN = ('<artistic_ior name="c" type="multioutput"><input name="reflectivity" type="color3" value="0.1, 0.3, 0.9"/>'
               '<input name="edge_color" type="color3" value="1, 1, 1"/></artistic_ior>'
               f'<conductor_bsdf name="back" type="BSDF">{ROUGH}<input name="ior" type="color3" nodename="c" output="ior"/>'
               '<input name="extinction" type="color3" nodename="c" output="extinction"/></conductor_bsdf>')
SEEN_FROM_BEHIND = ('<position name="p" type="vector3"><input name="space" type="string" value="world"/></position>'
                    '<extract name="px" type="float"><input name="in" type="vector3" nodename="p"/>'
                    '<input name="index" type="integer" value="0"/></extract>'
                    '<ifgreater name="behind" type="float"><input name="value1" type="float" nodename="px"/>'
                    '<input name="value2" type="float" value="0"/><input name="in1" type="float" value="1"/>'
                    '<input name="in2" type="float" value="0"/></ifgreater>')


def by_side(kind: str, front: str | None, back: str | None) -> str:
    sides = "".join(f'<input name="{n}" type="{kind}" nodename="{v}"/>' for n, v in (("bg", front), ("fg", back)) if v)
    return f'<mix name="{kind.lower()}" type="{kind}">{sides}<input name="mix" type="float" nodename="behind"/></mix>'


def thin(front: str | None, back: str | None, frontedf: str | None) -> str:
    links = "".join(f'<input name="{n}" type="{t}" nodename="{v}"/>' for n, t, v in
                    (("frontbsdf", "BSDF", front), ("backbsdf", "BSDF", back), ("frontedf", "EDF", frontedf)) if v)
    return f'<thinsurface name="thin" type="surfaceshader">{links}</thinsurface>'


def modern_thin(front: str | None, back: str | None, frontedf: str | None) -> str:
    return (SEEN_FROM_BEHIND + by_side("BSDF", front, back) + by_side("EDF", frontedf, None)
            + '<surface name="thin" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="bsdf"/>'
              '<input name="edf" type="EDF" nodename="edf"/><input name="thin_walled" type="boolean" value="true"/></surface>')


THIN_PAIRS = {
    "front and back": (material(FRONT + BACK + thin("front", "back", "glow"), shader="thin"),
                       material(FRONT + BACK_MODERN + modern_thin("front", "back", "glow"), shader="thin")),
    # "If only one BSDF is connected the same BSDF will be used on both sides"
    "front only": (material(FRONT + thin("front", None, "glow"), shader="thin"),
                   material(FRONT + modern_thin("front", "front", "glow"), shader="thin")),
    "back only": (material(BACK + thin(None, "back", None), shader="thin"),
                  material(BACK_MODERN + modern_thin("back", "back", None), shader="thin")),
}


@pytest.mark.parametrize("name", sorted(THIN_PAIRS))
def test_thinsurface_shows_each_side_its_own_bsdf(renderer, name):
    seed, modern = (GEN.prepare(d).emit() for d in THIN_PAIRS[name])
    assert "error" not in seed, seed.get("error")
    assert "error" not in modern, modern.get("error")
    ours, theirs = (renderer.render(r, size=48, mesh=TWO_SIDED).rgba for r in (seed, modern))
    assert np.isfinite(ours).all()
    row = ours[24]
    front_face, back_face = row[8:20, :3], row[28:40, :3]  # the middle of each quad
    assert (row[8:20, 3] > 0).all() and (row[28:40, 3] > 0).all()  # both faces drawn
    assert front_face.max() > 0.01 and back_face.max() > 0.01  # and lit, the back one too
    assert psnr(ours, theirs) >= 60.0
