"""A lobe that a mix leaves out at run time skips its work (nodes/closure_weights.py), and the
image is the one the mix gives: at weight 0 the background alone, at 1 the foreground alone."""
import numpy as np

from shadergen.api import Generator

from .conftest import set_value

GEN = Generator()
LOBES = {
    "metal": '<conductor_bsdf name="metal" type="BSDF"><input name="roughness" type="vector2" value="0.3, 0.3"/>'
             '</conductor_bsdf>',
    "matte": '<oren_nayar_diffuse_bsdf name="matte" type="BSDF"><input name="color" type="color3" value="0.2, 0.5, 0.8"/>'
             '</oren_nayar_diffuse_bsdf>',
}


def material(bsdf: str, nodes: str) -> str:
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  {nodes}
  <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="{bsdf}"/></surface>
  <surfacematerial name="M" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>
</materialx>"""


MIXED = material("blend", LOBES["metal"] + LOBES["matte"] + '<mix name="blend" type="BSDF">'
                 '<input name="fg" type="BSDF" nodename="metal"/><input name="bg" type="BSDF" nodename="matte"/>'
                 '<input name="mix" type="float" value="0.5"/></mix>')


def test_the_mix_weight_gates_its_lobes_in_the_source():
    main = GEN.prepare(MIXED, names="document").emit()["stages"]["pixel"].split("void main()")[1]
    assert "metal_active_weight = (blend_mix != 0.0) ? metal_weight : 0.0;" in main
    assert "matte_active_weight = (blend_mix != 1.0) ? matte_weight : 0.0;" in main
    assert main.count("mx_conductor_bsdf_prepare(pointData, metal_active_weight,") == 1
    assert main.count("mx_oren_nayar_diffuse_bsdf(closureData, matte_active_weight,") == main.count(
        "mx_oren_nayar_diffuse_bsdf(")


def test_a_lobe_left_out_at_run_time_leaves_the_image_of_the_other(renderer):
    mixed = GEN.prepare(MIXED, names="document").emit()
    image = {}
    for weight in (0.0, 0.5, 1.0):
        image[weight] = renderer.render(set_value(mixed, "blend_mix", weight), size=32).rgba
    alone = {name: renderer.render(GEN.prepare(material(name, LOBES[name])).emit(), size=32).rgba for name in LOBES}
    assert np.abs(image[0.0] - alone["matte"]).max() < 1e-5
    assert np.abs(image[1.0] - alone["metal"]).max() < 1e-5
    assert np.abs(image[0.5] - 0.5 * (alone["matte"] + alone["metal"])).max() < 1e-4
    assert np.abs(alone["matte"] - alone["metal"]).max() > 0.05  # the two lobes are told apart
