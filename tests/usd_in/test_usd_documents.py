"""USD scenes in: UsdShade networks translated onto our nodes, one record per material, and bad
USD answered with error records whose `where` is a prim path."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import json
import subprocess
import sys
from pathlib import Path

import pytest
from pxr import Sdf, Usd, UsdShade

from shadergen.api import Generator

from .scenes import TEXTURE, _shader, preview_surface_stage, standard_surface_stage, write_scene, write_usdz


def records(gen: Generator, path: Path, **kw) -> list[dict]:
    return list(gen.records(path, all=True, **kw))


def public(record: dict) -> dict:
    return {v["path"]: v for v in record["blocks"]["pixel"]["PublicUniforms"]}


def test_preview_surface_network_becomes_our_nodes_with_prim_paths(gen, scenes):
    [rec] = records(gen, scenes.preview)
    assert "error" not in rec, rec
    assert rec["element"] == "/World/Looks/Textured" and rec["document"] == str(scenes.preview)
    uniforms = public(rec)
    file = uniforms["/World/Looks/Textured/Texture.inputs:file"]
    assert file["value"] == TEXTURE and file["colorspace"] == "srgb_texture"  # sourceColorSpace sRGB
    assert uniforms["/World/Looks/Textured/Surface.inputs:roughness"]["value"] == pytest.approx(0.35)
    assert uniforms["/World/Looks/Textured/Transform.inputs:scale"]["value"] == [2.0, 3.0]
    assert uniforms["/World/Looks/Textured/Transform.inputs:rotation"]["value"] == 30.0
    # the `st` primvar reader is the mesh's texture coordinates, not a geometry property named st
    assert "texcoord_0" in rec["stages"]["vertex"] and "geomprop_st" not in rec["stages"]["vertex"]
    assert rec["warnings"] == []


def test_materialx_network_through_a_node_graph_and_the_material_interface(gen, scenes):
    [rec] = records(gen, scenes.brick)
    assert "error" not in rec, rec
    uniforms = public(rec)
    # outputs:mtlx:surface wins over outputs:surface: standard_surface, not the UsdPreviewSurface
    assert uniforms["/World/Looks/Brick/Surface.inputs:coat_color"]["value"] == pytest.approx([0.9, 0.8, 0.5])
    assert not any("Fallback" in (path or "") for path in uniforms)
    # the material's interface value reached the shader input connected to it
    assert uniforms["/World/Looks/Brick/Surface.inputs:specular_roughness"]["value"] == pytest.approx(0.6)
    image = uniforms["/World/Looks/Brick/Textures/Image.inputs:file"]
    assert image["value"] == TEXTURE and image["colorspace"] == "srgb_texture"  # colorSpace metadata


def test_usdz_textures_are_named_inside_the_package(gen, scenes):
    [rec] = records(gen, scenes.usdz)
    assert "error" not in rec, rec
    assert public(rec)["/World/Looks/Textured/Texture.inputs:file"]["value"] == f"preview.usdz[{TEXTURE}]"


def test_every_material_of_a_stage_and_element_by_prim_path(gen, tmp_path):
    def build(stage):
        preview_surface_stage(stage, "/World/Looks/A")
        standard_surface_stage(stage, "/World/Looks/B")
    path = write_scene(tmp_path, "two.usda", build)
    assert [r["element"] for r in records(gen, path)] == ["/World/Looks/A", "/World/Looks/B"]
    [only] = list(gen.records(path, element="/World/Looks/B"))
    assert only["element"] == "/World/Looks/B" and "error" not in only


# -- bad USD -------------------------------------------------------------------------------------
def bad_scene(folder: Path, build) -> Path:
    def with_material(stage):
        material = UsdShade.Material.Define(stage, "/Looks/Bad")
        surface = _shader(stage, "/Looks/Bad/Surface", "UsdPreviewSurface")
        material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
        build(stage, surface)
    return write_scene(folder, "bad.usda", with_material)


def error_of(gen, path: Path) -> dict:
    [rec] = records(gen, path)
    assert rec["element"] == "/Looks/Bad"
    return rec["error"]


def test_unknown_shader_id_names_its_prim(gen, tmp_path):
    def build(stage, surface):
        other = _shader(stage, "/Looks/Bad/Mystery", "MyStudioNoise")
        surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).ConnectToSource(other.ConnectableAPI(), "out")
    error = error_of(gen, bad_scene(tmp_path, build))
    assert error["code"] == "unknown_node" and "MyStudioNoise" in error["message"]
    assert error["where"] == "/Looks/Bad/Mystery"


def test_connection_cycle_is_named_by_prim_paths(gen, tmp_path):
    def build(stage, surface):
        first = _shader(stage, "/Looks/Bad/First", "UsdTransform2d")
        second = _shader(stage, "/Looks/Bad/Second", "UsdTransform2d")
        first.CreateInput("in", Sdf.ValueTypeNames.Float2).ConnectToSource(second.ConnectableAPI(), "result")
        second.CreateInput("in", Sdf.ValueTypeNames.Float2).ConnectToSource(first.ConnectableAPI(), "result")
        texture = _shader(stage, "/Looks/Bad/Texture", "UsdUVTexture")
        texture.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(first.ConnectableAPI(), "result")
        surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(texture.ConnectableAPI(), "rgb")
    error = error_of(gen, bad_scene(tmp_path, build))
    assert error["code"] == "cycle"
    assert "/Looks/Bad/First -> /Looks/Bad/Second -> /Looks/Bad/First" in error["message"]


def test_a_value_of_the_wrong_type_names_its_attribute(gen, tmp_path):
    def build(stage, surface):
        surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Float).Set(0.5)
    error = error_of(gen, bad_scene(tmp_path, build))
    assert error["code"] == "type_mismatch" and error["where"] == "/Looks/Bad/Surface.inputs:diffuseColor"


def test_a_material_without_a_surface_is_an_error_and_the_others_still_generate(gen, tmp_path):
    def build(stage):
        UsdShade.Material.Define(stage, "/Looks/Empty")
        preview_surface_stage(stage, "/Looks/Good")
    recs = records(gen, write_scene(tmp_path, "partial.usda", build))
    assert [r["element"] for r in recs] == ["/Looks/Empty", "/Looks/Good"]
    assert recs[0]["error"]["code"] == "invalid_document" and recs[0]["error"]["where"] == "/Looks/Empty"
    assert "error" not in recs[1]


def test_malformed_layer_is_an_error_record(gen, tmp_path):
    path = tmp_path / "broken.usda"
    path.write_text('#usda 1.0\ndef Material "Mat" {\n    float inputs:x = (1, 2\n}\n')
    [rec] = records(gen, path)
    assert rec["element"] is None and rec["error"]["code"] == "invalid_document"
    assert "malformed USD" in rec["error"]["message"] and rec["error"]["where"] == "/Mat.inputs:x"


def test_asset_leaving_the_package_is_refused(gen, tmp_path):
    inner = tmp_path / "inner"
    inner.mkdir()
    layer = write_scene(inner, "scene.usda", lambda stage: preview_surface_stage(stage, texture="../secret.png"))
    [rec] = records(gen, write_usdz(tmp_path, "escape.usdz", layer))
    assert rec["error"]["code"] == "path_not_allowed"
    assert rec["error"]["where"] == "/World/Looks/Textured/Texture.inputs:file"


def test_uploads_are_confined_to_themselves(gen, scenes):
    text = '#usda 1.0\n(\n    subLayers = [@/etc/hosts@]\n)\n'
    [rec] = list(gen.records(text.encode(), document_format="usda"))
    assert rec["error"]["code"] == "include_refused"
    package = scenes.usdz.read_bytes()
    [rec] = list(gen.records(package, document_format="usdz"))
    assert "error" not in rec, rec
    assert public(rec)["/World/Looks/Textured/Texture.inputs:file"]["value"] == TEXTURE  # the member, no path
    [rec] = list(gen.records(b"not a zip", document_format="usdz"))
    assert rec["error"]["code"] == "invalid_document"


# -- command line --------------------------------------------------------------------------------
def shadergen(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "shadergen.cli", *args], capture_output=True, text=True, timeout=300)


def test_cli_generate_prints_one_record_per_material(scenes, tmp_path):
    def build(stage):
        preview_surface_stage(stage, "/World/Looks/A")
        standard_surface_stage(stage, "/World/Looks/B")
    path = write_scene(tmp_path, "two.usda", build)
    done = shadergen("generate", str(path), "--all", "--no-source")
    assert done.returncode == 0, done.stderr
    assert [json.loads(line)["element"] for line in done.stdout.splitlines()] == ["/World/Looks/A", "/World/Looks/B"]
    done = shadergen("generate", str(path), "--element", "/World/Looks/B", "--no-source")
    assert [json.loads(line)["element"] for line in done.stdout.splitlines()] == ["/World/Looks/B"]


def test_cli_generate_reports_bad_usd_as_a_record_and_exit_code(tmp_path):
    path = tmp_path / "broken.usda"
    path.write_text("this is not a layer")
    done = shadergen("generate", str(path))
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert json.loads(done.stdout)["error"]["code"] == "invalid_document"


def test_cli_render_usdz(scenes, tmp_path):
    out = tmp_path / "usdz.png"
    done = shadergen("render", str(scenes.usdz), "-o", str(out), "--size", "64")
    assert done.returncode == 0, done.stderr
    assert "warning" not in done.stderr  # the texture inside the package was read
    assert out.stat().st_size > 1000


def test_prim_paths_key_the_record(gen, tmp_path):
    """/Looks/A_B and /Looks/A/B make the same MaterialX names and graph; their records name
    different prims, so a cache keyed by the hash must not give one for the other."""
    def material_at(root):
        def build(stage):
            material = UsdShade.Material.Define(stage, root)
            surface = _shader(stage, f"{root}/S", "UsdPreviewSurface")
            material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
        return build
    first = records(gen, write_scene(tmp_path, "first.usda", material_at("/Looks/A_B")))[0]
    second = records(gen, write_scene(tmp_path, "second.usda", material_at("/Looks/A/B")))[0]
    assert (first["element"], second["element"]) == ("/Looks/A_B", "/Looks/A/B")
    assert first["stages"] == second["stages"] and first["hash"] != second["hash"]


def test_asset_paths_are_relative_to_the_layer_that_wrote_them(gen, tmp_path):
    """A sublayer in another folder names its texture beside itself; the record names it from
    the document's folder, where the renderer looks."""
    looks = tmp_path / "looks"
    looks.mkdir()
    write_scene(looks, "looks.usdc", lambda stage: preview_surface_stage(stage, texture="wood.png"))
    root = write_scene(tmp_path, "shot.usda", lambda stage: stage.GetRootLayer().subLayerPaths.append(
        "looks/looks.usdc"))
    [rec] = records(gen, root)
    assert "error" not in rec, rec
    assert public(rec)["/World/Looks/Textured/Texture.inputs:file"]["value"] == "looks/wood.png"
