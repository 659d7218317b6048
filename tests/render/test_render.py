"""A real EGL context draws hand-written records; the tests read back pixel values."""
import math
import threading

import numpy as np
import pytest

from shadergen.render import Environment, RenderError
from shadergen.render.scene import EYE, FOV_Y_DEGREES

from .conftest import DATA, record, set_value

SIZE = 96


def pixel_at(x: float, y: float, size: int = SIZE) -> tuple[int, int]:
    """(row, column) of the pixel that sees world point (x, y, 0) (the plane) from the fixed camera."""
    half = EYE[2] * math.tan(math.radians(FOV_Y_DEGREES) / 2)
    column = (x / half + 1) / 2 * size
    row = (1 - y / half) / 2 * size
    return int(row), int(column)


def test_emission_ball_has_the_records_colour_and_the_reference_silhouette(renderer):
    result = renderer.render(record("emission"), size=SIZE)
    rgba = result.rgba
    assert rgba.shape == (SIZE, SIZE, 4) and rgba.dtype == np.float32
    centre = rgba[SIZE // 2, SIZE // 2]
    np.testing.assert_array_equal(centre, np.float32([0.25, 0.5, 0.75, 1.0]))  # the record's value, not the GLSL default
    np.testing.assert_array_equal(rgba[0, 0], np.zeros(4, "f4"))  # cleared to transparent black
    # A unit sphere 3 units away under a 45 degree field of view covers a disc of radius
    # tan(asin(1/3)) / tan(22.5 deg) of the half-image.
    radius = math.tan(math.asin(1 / 3)) / math.tan(math.radians(22.5)) / 2
    assert rgba[..., 3].mean() == pytest.approx(math.pi * radius ** 2, abs=0.01)
    assert result.warnings == []
    assert set(result.timings_ms) >= {"compile_link", "first_frame", "frame"}


def test_a_program_is_compiled_once_and_reused(renderer):
    rec = set_value(record("emission"), "u_color", [0.5, 0.5, 0.5])
    renderer.render(rec, size=32)
    again = renderer.render(set_value(rec, "u_color", [1.0, 0.0, 0.0]), size=32)
    assert again.timings_ms["compile_link"] == 0.0
    np.testing.assert_array_equal(again.rgba[16, 16], np.float32([1, 0, 0, 1]))  # new values, same program


def test_supersampling_averages_edge_pixels(renderer):
    rgba = renderer.render(record("emission"), size=SIZE, supersample=3).rgba
    assert rgba.shape == (SIZE, SIZE, 4)
    alpha = rgba[..., 3]
    partial = (alpha > 0) & (alpha < 1)
    assert partial.sum() > 100  # the silhouette is anti-aliased
    # colour is premultiplied: rgb scales with coverage
    edge = rgba[partial][0]
    np.testing.assert_allclose(edge[:3], np.float32([0.25, 0.5, 0.75]) * edge[3], rtol=1e-5)


def texture_record(mode: str | None = None, scale: float = 1.0, offset: float = 0.0, file: str = "quads.png") -> dict:
    rec = set_value(record("texture"), "image_file", file)
    set_value(rec, "image_default", [0.5, 0.25, 0.125])
    set_value(rec, "image_uvscale", [scale, scale])
    set_value(rec, "image_uvoffset", [offset, offset])
    if mode:
        set_value(rec, "image_uaddressmode", mode)
        set_value(rec, "image_vaddressmode", mode)
    return rec


RED, GREEN, BLUE, WHITE = [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]
DEFAULT = [0.5, 0.25, 0.125]


def test_texture_lookup_at_known_uvs_puts_the_images_top_row_on_top(renderer):
    rgba = renderer.render(texture_record(), size=SIZE, mesh="plane", document_dir=str(DATA)).rgba
    # quads.png: red, green on its top row; blue, white below. On the plane, uv = (x + 1) / 2.
    for (x, y), colour in {(-0.5, 0.5): RED, (0.5, 0.5): GREEN, (-0.5, -0.5): BLUE, (0.5, -0.5): WHITE}.items():
        np.testing.assert_array_equal(rgba[pixel_at(x, y)][:3], np.float32(colour), err_msg=str((x, y)))


@pytest.mark.parametrize("mode, expected", [
    ("periodic", (WHITE, BLUE)),
    ("clamp", (BLUE, BLUE)),
    ("mirror", (BLUE, WHITE)),
    ("constant", (DEFAULT, DEFAULT)),  # outside the image: the border, which is the node's default
    (2, (WHITE, BLUE)),                # enums may come as their integer index (2 = periodic)
])
def test_address_modes_follow_materialx(renderer, mode, expected):
    # uv * 3 - 1 runs from -1 to 2 across the plane; both points sample the image's bottom row
    # (t = 0.75) at u = -0.3 and u = -0.85, left of the image.
    rgba = renderer.render(texture_record(mode, scale=3.0, offset=-1.0), size=SIZE, mesh="plane",
                           document_dir=str(DATA)).rgba
    y = 2 * (1.25 / 3) - 1
    for u, colour in zip((-0.3, -0.85), expected):
        x = 2 * ((u + 1) / 3) - 1
        np.testing.assert_allclose(rgba[pixel_at(x, y)][:3], colour, atol=1e-6, err_msg=f"{mode} at u={u}")


def test_one_channel_images_read_as_grey(renderer):
    rgba = renderer.render(texture_record(file="grey.png"), size=SIZE, mesh="plane", document_dir=str(DATA)).rgba
    np.testing.assert_allclose(rgba[SIZE // 2, SIZE // 2][:3], [128 / 255] * 3, atol=1e-6)


def test_missing_texture_warns_and_shows_the_default(renderer):
    result = renderer.render(texture_record(file="no_such_image.png"), size=SIZE, mesh="plane", document_dir=str(DATA))
    assert any("no_such_image.png" in w and "not found" in w for w in result.warnings)
    assert not any(str(DATA) in w for w in result.warnings)  # the server's folders are no client's business
    np.testing.assert_allclose(result.rgba[SIZE // 2, SIZE // 2][:3], DEFAULT, atol=1e-6)


def test_textures_outside_the_allowed_folders_are_not_read(renderer, tmp_path):
    secret = tmp_path / "secret.png"
    secret.write_bytes((DATA / "quads.png").read_bytes())
    result = renderer.render(texture_record(file=str(secret)), size=32, mesh="plane", document_dir=str(DATA))
    assert any("outside the allowed folders" in w for w in result.warnings)
    escaping = texture_record(file="../" * 12 + str(secret).lstrip("/"))
    result = renderer.render(escaping, size=32, mesh="plane", document_dir=str(DATA))
    assert any("outside the allowed folders" in w for w in result.warnings)
    # a link out of the document's folder: refused without naming where it leads
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "link.png").symlink_to(secret)
    result = renderer.render(texture_record(file="link.png"), size=32, mesh="plane", document_dir=str(tmp_path / "docs"))
    assert any("link.png" in w and "outside the allowed folders" in w for w in result.warnings)
    assert not any(str(secret) in w for w in result.warnings)


def test_light_rig_binds_lightdata_with_materialx_type_ids(renderer):
    result = renderer.render(record("lights"), size=SIZE, lights=str(DATA / "rig.mtlx"))
    # centre normal +Z; key light along -Z: (1, .5, .25) * 2; fill (type 2): 0.125 everywhere
    np.testing.assert_allclose(result.rgba[SIZE // 2, SIZE // 2][:3], [2.125, 1.125, 0.625], atol=2e-3)
    without = renderer.render(record("lights"), size=SIZE)
    np.testing.assert_array_equal(without.rgba[SIZE // 2, SIZE // 2][:3], np.zeros(3, "f4"))


def latlong_map(rows: int, columns: int, fill) -> np.ndarray:
    return np.broadcast_to(np.float32(fill), (rows, columns, 3)).copy()


def write_hdr(path, image: np.ndarray) -> str:
    from shadergen.render.imageio import write_image

    write_image(str(path), np.concatenate([image, np.ones(image.shape[:2] + (1,), "f4")], 2))
    return str(path)


def test_constant_environment_gives_its_radiance_as_irradiance(renderer, tmp_path):
    env = Environment.load(write_hdr(tmp_path / "grey.exr", latlong_map(32, 64, [0.2, 0.4, 0.6])), intensity=0.5)
    rgba = renderer.render(record("environment"), size=SIZE, env=env).rgba
    np.testing.assert_allclose(rgba[SIZE // 2, SIZE // 2][:3], np.float32([0.1, 0.2, 0.3]), rtol=2e-3)


def test_environment_orientation_follows_materialx(renderer, tmp_path):
    # Sky (upper half of the map) white, ground black: the top of the ball is lit, the bottom not.
    sky = latlong_map(64, 128, [0.0, 0.0, 0.0])
    sky[:32] = 1.0
    rgba = renderer.render(record("environment"), size=SIZE, env=Environment.load(write_hdr(tmp_path / "sky.exr", sky))).rgba
    column = rgba[:, SIZE // 2, 0][rgba[:, SIZE // 2, 3] > 0]
    assert column[1] > 0.9 and column[-2] < 0.1
    # A mirror ball's centre reflects the direction behind the camera, +Z, which MaterialX's
    # default u_envMatrix maps to the middle of the lat-long image.
    band = latlong_map(64, 128, [0.0, 0.0, 0.0])
    band[:, 48:80] = [0.0, 1.0, 0.0]
    mirror = set_value(record("environment"), "u_mirror", 1)
    rgba = renderer.render(mirror, size=SIZE, env=Environment.load(write_hdr(tmp_path / "band.exr", band))).rgba
    np.testing.assert_allclose(rgba[SIZE // 2, SIZE // 2][:3], [0, 1, 0], atol=1e-3)


def test_procedural_sky_lights_a_ball_without_nan(renderer):
    rgba = renderer.render(record("environment"), size=SIZE).rgba
    lit = rgba[rgba[..., 3] > 0][:, :3]
    assert np.isfinite(rgba).all() and lit.min() >= 0 and lit.mean() > 0.1


def test_streams_a_mesh_lacks_get_materialx_defaults(renderer):
    rgba = renderer.render(record("streams"), size=SIZE).rgba
    np.testing.assert_allclose(rgba[SIZE // 2, SIZE // 2], [1, 1, 1, 1], atol=1e-6)  # white colour set, zero geomprop


def test_obj_mesh_is_framed_and_textured(renderer):
    rgba = renderer.render(texture_record(), size=SIZE, mesh=str(DATA / "quad.obj"), document_dir=str(DATA)).rgba
    assert rgba[SIZE // 2, SIZE // 2, 3] == 1.0
    assert {tuple(rgba[pixel_at(x, y)][:3]) for x in (-0.3, 0.3) for y in (-0.3, 0.3)} == {
        tuple(np.float32(c)) for c in (RED, GREEN, BLUE, WHITE)}


def test_shader_asking_for_a_stream_the_mesh_lacks_fails_clearly(renderer):
    with pytest.raises(RenderError) as caught:
        renderer.render(texture_record(), size=32, mesh=str(DATA / "triangle_no_uv.obj"), document_dir=str(DATA))
    assert caught.value.code == "missing_stream" and "i_texcoord_0" in caught.value.message
    assert caught.value.where == "i_texcoord_0"


def test_compile_errors_name_the_stage_and_line(renderer):
    broken = record("emission")
    lines = broken["stages"]["pixel"].splitlines()
    target = next(i for i, line in enumerate(lines) if "out1 = " in line)
    lines[target] = "    out1 = vec4(undeclared_thing, 1.0);"
    broken["stages"]["pixel"] = "\n".join(lines)
    with pytest.raises(RenderError) as caught:
        renderer.render(broken, size=32)
    assert caught.value.code == "compile_error"
    assert caught.value.where == f"pixel:{target + 1}"
    assert "undeclared_thing" in caught.value.message


@pytest.mark.parametrize("broken, code", [
    ("not a record", "invalid_record"),
    ({"element": "x", "error": {"code": "unknown_node", "message": "no nodedef"}}, "invalid_record"),
    ({"element": "x", "target": "glsl", "stages": {"vertex": "", "pixel": None}}, "invalid_record"),
    ({"element": "x", "target": "osl", "stages": {"vertex": "a", "pixel": "b"}}, "unsupported_target"),
    ({"element": "x", "target": "glsl", "stages": {"vertex": "a", "pixel": "b"}, "blocks": {"pixel": []}}, "invalid_record"),
])
def test_broken_records_raise_render_errors(renderer, broken, code):
    with pytest.raises(RenderError) as caught:
        renderer.render(broken, size=32)
    assert caught.value.code == code


def test_unknown_mesh_and_missing_environment_raise(renderer, tmp_path):
    with pytest.raises(RenderError) as caught:
        renderer.render(record("emission"), size=32, mesh="teapot")
    assert caught.value.code == "invalid_mesh"
    with pytest.raises(RenderError) as caught:
        renderer.render(record("emission"), size=32, env=str(tmp_path / "none.hdr"))
    assert caught.value.code == "invalid_environment"


def test_the_context_refuses_another_thread(renderer):
    renderer.render(record("emission"), size=16)  # the context exists, owned by this thread
    caught = []

    def other():
        try:
            renderer.render(record("emission"), size=16)
        except RenderError as exc:
            caught.append(exc.code)

    thread = threading.Thread(target=other)
    thread.start()
    thread.join()
    assert caught == ["context_misuse"]


def test_a_rig_on_a_shader_without_lights_is_reported(renderer):
    result = renderer.render(record("emission"), size=16, lights=str(DATA / "rig.mtlx"))
    assert any("light rig has no effect" in w for w in result.warnings)
