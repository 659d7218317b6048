"""Our generator's lit shaders drawn by our renderer: the light ids the record lists decide which
light function runs, whatever order the rig lists its lights in."""
import numpy as np
import pytest

from shadergen.api import Generator
from shadergen.render.errors import RenderError

DIFFUSE = '''<?xml version="1.0"?>
<materialx version="1.39">
  <oren_nayar_diffuse_bsdf name="diffuse" type="BSDF"/>
  <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="diffuse"/></surface>
  <surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>
</materialx>
'''
SUN = '<directional_light name="sun" type="lightshader"><input name="direction" type="vector3" value="0, 0, -1"/>' \
      '<input name="color" type="color3" value="1, 1, 1"/><input name="intensity" type="float" value="3"/></directional_light>'
DARK_BULB = '<point_light name="bulb" type="lightshader"><input name="color" type="color3" value="1, 1, 1"/>' \
            '<input name="intensity" type="float" value="0"/></point_light>'


def rig(tmp_path, name, body):
    path = tmp_path / name
    path.write_text(f'<?xml version="1.0"?><materialx version="1.39">{body}</materialx>')
    return str(path)


def test_light_ids_come_from_the_record(renderer, tmp_path):
    record = Generator().prepare(DIFFUSE).emit()
    ids = next(v for v in record["blocks"]["pixel"]["LightData"] if v["name"] == "type")["ui"]
    assert ids["enum"] == ["point_light", "directional_light", "spot_light"]
    assert ids["enumvalues"] == [1, 2, 3]
    dark = renderer.render(record, size=32).rgba
    sun_only = renderer.render(record, size=32, lights=rig(tmp_path, "a.mtlx", SUN)).rgba
    bulb_first = renderer.render(record, size=32, lights=rig(tmp_path, "b.mtlx", DARK_BULB + SUN)).rgba
    centre = (16, 16)
    # Lambert at normal incidence: albedo 0.18 (the nodedef's default) x intensity 3 / pi
    np.testing.assert_allclose(sun_only[centre][:3] - dark[centre][:3], 0.18 * 3 / np.pi, rtol=0.03)
    np.testing.assert_allclose(bulb_first, sun_only, atol=1e-5)


def test_a_shader_generated_without_lights_draws_the_unlit_scene_alike_and_refuses_a_rig(renderer, tmp_path):
    lit = Generator().prepare(DIFFUSE, environment="fis").emit()
    unlit = Generator().prepare(DIFFUSE, environment="fis", lights=False).emit()
    assert unlit["lights"] is False and "lights" not in lit
    assert "sampleLightSource" in lit["stages"]["pixel"] and "sampleLightSource" not in unlit["stages"]["pixel"]
    assert not unlit["blocks"]["pixel"]["LightData"]
    np.testing.assert_allclose(renderer.render(unlit, size=32).rgba, renderer.render(lit, size=32).rgba, atol=1e-6)
    with pytest.raises(RenderError) as refused:
        renderer.render(unlit, size=32, lights=rig(tmp_path, "a.mtlx", SUN))
    assert refused.value.code == "invalid_request"
