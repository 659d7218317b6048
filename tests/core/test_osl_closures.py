"""OSL's closures (targets/osl/closures.py): every shading model and every closure node of the PBR
library, the specification's 2018 names and RenderMan's Lama nodes become closures of OSL 1.13's
stdosl.h (and the hair closure later releases declare) that oslc compiles, in each interface; the output is a `closure color` (oslinfo: a
pointer); what stdosl.h has no closure for is an error record that names the node."""
import pytest

from shadergen.api import default_generator
from shadergen.targets.osl import check
from tests.required_tools import missing

SURFACES = ("standard_surface", "open_pbr_surface", "gltf_pbr", "UsdPreviewSurface", "disney_principled",
            "thinsurface", "mixsurface")
BSDFS = ("oren_nayar_diffuse_bsdf", "burley_diffuse_bsdf", "translucent_bsdf", "dielectric_bsdf", "conductor_bsdf",
         "generalized_schlick_bsdf", "subsurface_bsdf", "sheen_bsdf", "chiang_hair_bsdf", "diffusebrdf", "diffusebtdf", "conductorbrdf",
         "dielectricbrdf", "dielectricbtdf", "subsurfacebrdf", "sheenbrdf", "LamaConductor", "LamaDielectric",
         "LamaDiffuse", "LamaGeneralizedSchlick", "LamaSheen", "LamaSSS", "LamaTranslucent")
EDFS = ("uniform_edf", "conical_edf", "uniformedf", "conicaledf", "LamaEmission")
VDFS = ("absorption_vdf", "anisotropic_vdf", "absorptionvdf", "anisotropicvdf")
# what each kind of node's output becomes a material through
WRAP = {"surfaceshader": '<{node} name="n" type="surfaceshader"/>',
        "BSDF": '<{node} name="n" type="BSDF"/><surface name="s" type="surfaceshader">'
                '<input name="bsdf" type="BSDF" nodename="n"/><input name="opacity" type="float" value="0.5"/></surface>',
        "EDF": '<{node} name="n" type="EDF"/><surface name="s" type="surfaceshader">'
               '<input name="edf" type="EDF" nodename="n"/></surface>'}
MATERIAL = ('<surfacematerial name="M" type="material"><input name="surfaceshader" type="surfaceshader" '
            'nodename="{shader}"/></surfacematerial>')
VOLUME = ('<{node} name="n" type="VDF"/><volume name="v" type="volumeshader"><input name="vdf" type="VDF" nodename="n"/>'
          '</volume><volumematerial name="M" type="material"><input name="volumeshader" type="volumeshader" '
          'nodename="v"/></volumematerial>')


@pytest.fixture(scope="module")
def oslc():
    if check.tool("oslc") is None or check.tool("oslinfo") is None:
        missing("oslc and oslinfo", "scripts/osl.sh builds them")


def document(body: str) -> bytes:
    return f'<?xml version="1.0"?>\n<materialx version="1.39">{body}</materialx>'.encode()


def material(node: str, kind: str) -> bytes:
    if kind == "VDF":
        return document(VOLUME.format(node=node))
    return document(WRAP[kind].format(node=node) + MATERIAL.format(shader="n" if kind == "surfaceshader" else "s"))


def cases():
    for kind, nodes in (("surfaceshader", SURFACES), ("BSDF", BSDFS), ("EDF", EDFS), ("VDF", VDFS)):
        for node in nodes:
            yield node, kind


@pytest.mark.parametrize("interface", ["complete", "reduced", "specialized"])
def test_every_closure_node_compiles(oslc, interface):
    shaders = {}
    for node, kind in cases():
        records = list(default_generator().records(material(node, kind), target="osl", all=True, interface=interface))
        assert len(records) == 1 and "error" not in records[0], (node, records)
        shaders[node] = ("pixel", records[0]["stages"]["pixel"])
    assert check.errors(shaders) == {}


def test_closures_are_stdosl_closures_layered_and_weighted(oslc):
    source = next(default_generator().records(material("standard_surface", "surfaceshader"), target="osl",
                                              interface="specialized"))["stages"]["pixel"]
    for closure in ("oren_nayar_diffuse_bsdf(", "dielectric_bsdf(", "layer(", '"ggx"'):
        assert closure in source, closure
    assert "closureData" not in source and "mx_" not in source  # no evaluated lobes, no light loop
    partly = next(default_generator().records(material("burley_diffuse_bsdf", "BSDF"), target="osl",
                                              interface="specialized"))["stages"]["pixel"]
    assert "burley_diffuse_bsdf(" in partly and "0.5 * transparent_bsdf()" in partly


def test_the_output_is_a_closure_as_oslinfo_reads_it(oslc):
    rec = next(default_generator().records(material("gltf_pbr", "surfaceshader"), target="osl"))
    info = check.oslinfo(rec["stages"]["pixel"])
    [output] = rec["blocks"]["pixel"]["Outputs"]
    assert output["type"] == "material"
    assert f'"{output["name"]}" "output pointer"' in info  # (how oslinfo 1.13 spells a closure output)
    assert "output closure color " + output["name"] in rec["stages"]["pixel"]


def test_a_closure_osl_lacks_is_an_error_record_naming_the_node():
    doc = document('<measured_edf name="glow" type="EDF"/><surface name="s" type="surfaceshader">'
                   '<input name="edf" type="EDF" nodename="glow"/></surface>' + MATERIAL.format(shader="s"))
    [rec] = default_generator().records(doc, target="osl")
    assert rec["error"]["code"] == "unsupported_node"
    assert "measured_edf" in rec["error"]["message"] and rec["error"]["where"].endswith("glow")


def test_hair_is_the_declared_closure_with_each_roughness_pair_split(oslc):
    """OSL 1.13's stdosl.h has no hair closure: the shader declares the one later releases have
    (longitudinal roughnesses of R, TT, TRT, then their azimuthal ones), once, and oslc takes it."""
    doc = document('<chiang_hair_bsdf name="hair" type="BSDF"><input name="roughness_R" type="vector2" value="0.3, 0.7"/>'
                   '<input name="roughness_TT" type="vector2" value="0.2, 0.6"/></chiang_hair_bsdf>'
                   '<surface name="s" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="hair"/></surface>'
                   + MATERIAL.format(shader="s"))
    [rec] = default_generator().records(doc, target="osl", interface="specialized")
    source = rec["stages"]["pixel"]
    assert source.count("closure color chiang_hair_bsdf(") == 1 and "[[ int builtin = 1 ]]" in source
    call = " ".join(source.split("= chiang_hair_bsdf(")[1].split(";")[0].split())
    assert "1.55, 0.3, 0.2, 0.2, 0.7, 0.6, 0.2, 0.5," in call, call
    assert check.errors({"hair": ("pixel", source)}) == {}
