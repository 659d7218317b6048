"""Light rigs and environment maps as data (no GL needed)."""
import numpy as np
import pytest

from shadergen.render import RenderError
from shadergen.render.environment import map_directions, procedural_sky, sh_irradiance
from shadergen.library import Library
from shadergen.render.lights import light_uniforms, load_lights

from .conftest import DATA


def test_light_ids_follow_first_appearance_of_each_light_kind(tmp_path):
    lights = load_lights(str(DATA / "rig.mtlx"), library=Library.load(tmp_path))
    assert [(l.name, l.category, l.type_id) for l in lights] == [("key", "directional_light", 1), ("fill", "point_light", 2)]
    uniforms = light_uniforms(lights)
    assert uniforms["u_numActiveLightSources"] == [2.0]
    assert uniforms["u_lightData[0].direction"] == [0.0, 0.0, -1.0]
    assert uniforms["u_lightData[1].type"] == [2.0]


def test_unset_light_inputs_take_the_library_defaults(tmp_path):
    (tmp_path / "lights_defs.mtlx").write_text(
        '<materialx version="1.39"><nodedef name="ND_point_light" node="point_light">'
        '<input name="decay_rate" type="float" value="2.0"/><input name="color" type="color3"/>'
        '<output name="out" type="lightshader"/></nodedef></materialx>')
    lights = load_lights(str(DATA / "rig.mtlx"), library=Library.load(tmp_path))
    assert lights[1].inputs["decay_rate"] == [2.0] and "decay_rate" not in lights[0].inputs


def test_rigs_are_read_as_documents_with_includes_and_inherited_defaults(tmp_path):
    (tmp_path / "defs.mtlx").write_text(
        '<materialx version="1.39"><nodedef name="ND_lamp_base" node="lamp_base">'
        '<input name="intensity" type="float" value="3.0"/><output name="out" type="lightshader"/></nodedef>'
        '<nodedef name="ND_lamp" node="lamp" inherit="ND_lamp_base"><input name="color" type="color3" '
        'value="1, 0.5, 0.25"/></nodedef>'
        '<lamp name="included" type="lightshader"/></materialx>')
    (tmp_path / "rig.mtlx").write_text(
        '<materialx version="1.39" xmlns:xi="http://www.w3.org/2001/XInclude"><xi:include href="defs.mtlx"/>'
        '<lamp name="own" type="lightshader"><input name="color" type="color3" value="0, 1, 0"/></lamp></materialx>')
    lights = load_lights(str(tmp_path / "rig.mtlx"))
    assert [l.name for l in lights] == ["included", "own"]
    assert lights[0].inputs == {"intensity": [3.0], "color": [1.0, 0.5, 0.25]}
    assert lights[1].inputs == {"intensity": [3.0], "color": [0.0, 1.0, 0.0]}
    assert load_lights(str(DATA / "rig.mtlx"))[1].inputs["decay_rate"] == [2.0]  # the generator's libraries


def test_bad_rigs_fail_clearly(tmp_path):
    (tmp_path / "empty.mtlx").write_text('<materialx version="1.39"/>')
    (tmp_path / "broken.mtlx").write_text("<materialx")
    for name in ("empty.mtlx", "broken.mtlx", "absent.mtlx"):
        with pytest.raises(RenderError) as caught:
            load_lights(str(tmp_path / name))
        assert caught.value.code == "invalid_lights"


def test_sh_irradiance_of_a_constant_sky_is_the_constant():
    irradiance = sh_irradiance(np.full((64, 128, 3), 0.7, "f4"))
    np.testing.assert_allclose(irradiance, 0.7, rtol=1e-3)


def test_sh_irradiance_of_a_sun_peaks_facing_it():
    radiance = np.zeros((128, 256, 3), "f4")
    radiance[10:14, 60:64] = 100.0  # a small bright patch high in the sky
    directions, _ = map_directions(128, 256)
    sun = directions[12, 62]
    irradiance = sh_irradiance(radiance)[..., 0]
    out_directions, _ = map_directions(*irradiance.shape)
    brightest = out_directions.reshape(-1, 3)[irradiance.argmax()]
    assert brightest @ sun > 0.97  # SH order 2 smooths, but the peak faces the sun


def test_procedural_sky_has_a_sun_over_a_sky_over_a_ground():
    sky = procedural_sky()
    assert sky.shape == (256, 512, 3) and np.isfinite(sky).all() and sky.min() > 0
    assert sky.max() > 100 * np.median(sky)        # the sun
    assert sky[:128].mean(axis=(0, 1))[2] > sky[128:].mean(axis=(0, 1))[2]  # blue above, dark below
