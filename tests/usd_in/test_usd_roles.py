"""Connections across roles of one underlying type (float3 into normal3f or color3f), which USD
makes freely and sample scenes are full of: accepted through a `convert` node, generated for every
target and drawn as the same material written in MaterialX is."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

from functools import partial

import pytest

from .scenes import (DISPLAY_COLOR_FALLBACK, ROLE_CONNECTIONS_MTLX, TILTED_NORMAL, role_connections_stage, write_mtlx,
                     write_normal_map, write_scene)
from .test_usd_render import MIN_PSNR_DB, psnr, render


@pytest.fixture(scope="module")
def renderer():
    from shadergen.render import Renderer

    return Renderer(search_paths=[])


@pytest.fixture(scope="module")
def roles(tmp_path_factory):
    folder = tmp_path_factory.mktemp("roles")
    write_normal_map(folder)
    usd = write_scene(folder, "roles.usda", role_connections_stage)
    diffuse = "%g, %g, %g" % DISPLAY_COLOR_FALLBACK
    tilted = write_mtlx(folder, "tilted.mtlx", ROLE_CONNECTIONS_MTLX.format(normal="%g, %g, %g" % TILTED_NORMAL,
                                                                            diffuse=diffuse))
    flat = write_mtlx(folder, "flat.mtlx", ROLE_CONNECTIONS_MTLX.format(normal="0, 0, 1", diffuse=diffuse))
    return folder, usd, tilted, flat


@pytest.mark.parametrize("target", ["glsl", "essl", "wgsl"])
def test_connections_across_roles_generate_through_convert_nodes(gen, roles, target):
    _, usd, _, _ = roles
    [rec] = list(gen.records(usd, all=True, target=target, names="document"))  # the convert nodes by name
    assert "error" not in rec, rec["error"]
    pixel = rec["stages"]["pixel"]
    assert "NormalMap_rgb_as_vector3" in pixel and "DisplayColor_out_as_color3" in pixel
    # the stream is the primvar the reader names (its varname reaches the geompropvalue inside the
    # reader's nodegraph through an interface input, which `complete` publishes), its value the fallback
    [stream] = [v for v in rec["blocks"]["vertex"]["AppData"] if v["name"].startswith("i_geomprop_")]
    assert stream["name"] == "i_geomprop_displayColor" and stream["value"] == pytest.approx(DISPLAY_COLOR_FALLBACK)


def test_a_normal_map_and_a_colour_primvar_across_roles_draw_like_materialx(gen, renderer, roles):
    """On the sphere, which has no displayColor, the primvar reader gives its fallback."""
    folder, usd, tilted, flat = roles
    ours = render(gen, renderer, usd, folder)
    same, other = psnr(ours, render(gen, renderer, tilted, folder)), psnr(ours, render(gen, renderer, flat, folder))
    print(f"roles: {same:.1f} dB against the tilted normal, {other:.1f} dB against the flat one")
    assert same >= MIN_PSNR_DB
    # the normal map was applied: the image is not the one of the untilted normal
    assert other < 40


def test_connections_of_different_underlying_types_stay_refused(gen, tmp_path):
    """A float output into a float3 input is no role conversion: USD would not read it either."""
    from pxr import Sdf, Usd, UsdShade

    from .scenes import _shader

    stage = Usd.Stage.CreateNew(str(tmp_path / "scalar.usda"))
    material = UsdShade.Material.Define(stage, "/M")
    surface = _shader(stage, "/M/Surface", "UsdPreviewSurface")
    texture = _shader(stage, "/M/Texture", "UsdUVTexture")
    surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(
        texture.CreateOutput("r", Sdf.ValueTypeNames.Float))
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    stage.GetRootLayer().Save()
    [rec] = list(gen.records(tmp_path / "scalar.usda", all=True))
    assert rec["error"]["code"] == "type_mismatch" and rec["error"]["where"] == "/M/Surface.inputs:diffuseColor"


@pytest.mark.parametrize("value", ["red", [1, 2, 3, 4, 5], [float("nan")], [[1]]])
def test_a_record_whose_stream_value_is_not_numbers_is_an_invalid_record(gen, renderer, roles, value):
    from shadergen.render.errors import RenderError

    _, usd, _, _ = roles
    [rec] = list(gen.records(usd, all=True))
    [stream] = [v for v in rec["blocks"]["vertex"]["AppData"] if v["name"] == "i_geomprop_displayColor"]
    stream["value"] = value
    with pytest.raises(RenderError) as error:
        renderer.render(rec, size=16)
    assert error.value.code == "invalid_record" and error.value.where == "i_geomprop_displayColor"
