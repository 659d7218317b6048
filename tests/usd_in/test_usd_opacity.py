"""UsdPreviewSurface's opacity and opacityThreshold as its specification reads them, in rendered
images. Transparent opacity (opacityThreshold 0) is drawn by transmission: a clear glass shows the
environment behind it under its full-strength reflections, alpha 1. Presence (opacityThreshold > 0,
a cutout, or opacityMode "presence") is the thumbnail's alpha, over which colour is premultiplied."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

from functools import partial

import numpy as np
import pytest

from .scenes import TEXTURE, opacity_stage, write_checker, write_scene

SIZE = 64
CENTRE = (SIZE // 2, SIZE // 2)
# a uniform environment: whatever the surface reflects and lets through, it is this radiance
UNIFORM = np.float32([0.2, 0.4, 0.6])
SCENES = {
    "glass": dict(opacity=0.0), "half": dict(opacity=0.5), "opaque": dict(opacity=1.0),
    "presence": dict(opacity=0.5, mode="presence"),
    "cutout": dict(texture=TEXTURE, threshold=0.5),
}


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("opacity")
    write_checker(folder)
    for name, options in SCENES.items():
        write_scene(folder, f"{name}.usda", partial(opacity_stage, **options))
    return folder


@pytest.fixture(scope="module")
def drawn(folder, gen):
    """name -> environment ('uniform' or 'sky') -> the rendered RGBA."""
    from shadergen.render import Renderer
    from shadergen.render.environment import Environment

    renderer = Renderer(search_paths=[])
    uniform = Environment(np.full((16, 32, 3), UNIFORM), np.full((16, 32, 3), UNIFORM), "uniform-test-environment")
    images = {}
    for name in SCENES:
        [record] = list(gen.records(folder / f"{name}.usda"))
        assert "error" not in record, record["error"]
        images[name] = {env: renderer.render(record, size=SIZE, env=environment, document_dir=str(folder)).rgba
                        for env, environment in (("uniform", uniform), ("sky", None))}
    return images


def disc(rgba: np.ndarray) -> np.ndarray:
    """Where the sphere is, whatever its alpha: inside the silhouette of the opaque material."""
    return rgba[..., 3] > 0.99


def test_clear_glass_shows_what_is_behind_it_and_its_reflections(drawn):
    glass, opaque = drawn["glass"], drawn["opaque"]
    inside = disc(opaque["uniform"])
    # in a uniform environment, reflection plus transmission is the environment itself: not black,
    # and not the red of a diffuse the glass does not have
    np.testing.assert_allclose(glass["uniform"][inside][:, :3], np.broadcast_to(UNIFORM, (inside.sum(), 3)), atol=0.02)
    assert (glass["uniform"][inside][:, 3] == 1.0).all()  # by transmission, not alpha
    red, _, blue = opaque["uniform"][CENTRE][:3]
    assert red > 1.5 * blue  # the opaque one is its diffuse colour
    # under the sky the sun's highlight is reflected at full strength, as on the opaque surface
    sky = glass["sky"][..., :3].max(axis=2)
    assert sky.max() > 2.0 and sky.max() == pytest.approx(opaque["sky"][..., :3].max(axis=2).max(), rel=0.1)
    assert np.unravel_index(sky.argmax(), sky.shape) == np.unravel_index(
        opaque["sky"][..., :3].max(axis=2).argmax(), sky.shape)


def test_half_opacity_lies_between_glass_and_opaque(drawn):
    half, glass, opaque = (drawn[n]["uniform"][CENTRE] for n in ("half", "glass", "opaque"))
    np.testing.assert_allclose(half[:3], (glass[:3] + opaque[:3]) / 2, atol=0.01)
    assert half[3] == 1.0


def test_presence_mode_is_alpha_with_premultiplied_colour(drawn):
    presence, opaque = drawn["presence"]["uniform"], drawn["opaque"]["uniform"]
    assert presence[CENTRE][3] == pytest.approx(0.5, abs=1e-3)
    np.testing.assert_allclose(presence[CENTRE][:3], opaque[CENTRE][:3] * 0.5, atol=1e-3)


def test_opacity_threshold_cuts_out_wholly(drawn):
    cutout, inside = drawn["cutout"]["sky"], disc(drawn["opaque"]["sky"])
    alpha = cutout[..., 3][inside]
    absent = alpha == 0.0
    # every fragment is either there or not (the checker's red channel is 0.08 or 0.12 against 0.9 or 0.98)
    assert ((alpha == 1.0) | absent).mean() > 0.97
    assert 0.2 < absent.mean() < 0.8
    assert np.abs(cutout[inside][absent][:, :3]).max() == 0.0  # absent: no reflection either


@pytest.mark.parametrize("name", ["glass", "presence", "cutout"])
def test_webgpu_draws_transmission_and_alpha_as_gl_does(gen, folder, drawn, name):
    from required_tools import require_wgpu
    require_wgpu()
    from shadergen.render.wgpu_renderer import WgpuRenderer

    [record] = list(gen.records(folder / f"{name}.usda", target="wgsl"))
    wgpu = WgpuRenderer(search_paths=[]).render(record, size=SIZE, document_dir=str(folder)).rgba
    gl = drawn[name]["sky"]
    # where the filtered texture is at the cutout's threshold the two rasterizers may cut either way
    differ = (wgpu[..., 3] > 0.5) != (gl[..., 3] > 0.5)
    assert differ.sum() <= 4
    assert np.abs(wgpu - gl)[~differ].max() < 0.01
