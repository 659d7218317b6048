"""USD uploads on the live server: `model/vnd.usda` text and `model/vnd.usdz+zip` packages written
with usd-core, confined to themselves, with bad USD answered by the contract's error object."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import os
from pathlib import Path

import pytest
from pxr import Sdf, Usd, UsdShade

from service_testing import assert_error

USDA = {"content-type": "model/vnd.usda"}
USDZ = {"content-type": "model/vnd.usdz+zip"}
MIB = 1024 * 1024


def layer_text(texture: str = "wood.png", shader_id: str = "UsdPreviewSurface") -> str:
    """Two materials: a textured UsdPreviewSurface (or a shader of `shader_id`) and a plain one."""
    stage = Usd.Stage.CreateInMemory()
    for name, textured in (("Wood", True), ("Plain", False)):
        material = UsdShade.Material.Define(stage, f"/Looks/{name}")
        surface = UsdShade.Shader.Define(stage, f"/Looks/{name}/Surface")
        surface.CreateIdAttr(shader_id if textured else "UsdPreviewSurface")
        surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.25)
        if textured:
            texture_shader = UsdShade.Shader.Define(stage, f"/Looks/{name}/Texture")
            texture_shader.CreateIdAttr("UsdUVTexture")
            texture_shader.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(texture)
            surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(
                texture_shader.ConnectableAPI(), "rgb")
        material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    return stage.GetRootLayer().ExportToString()


def package(folder: Path, text: str, *members: tuple[str, bytes]) -> bytes:
    (folder / "scene.usda").write_text(text)
    writer = Sdf.ZipFileWriter.CreateNew(str(folder / "scene.usdz"))
    writer.AddFile(str(folder / "scene.usda"), "scene.usda")
    for name, data in members:
        os.makedirs((folder / name).parent, exist_ok=True)
        (folder / name).write_bytes(data)
        writer.AddFile(str(folder / name), name)
    writer.Save()
    return (folder / "scene.usdz").read_bytes()


def uniforms(record: dict) -> dict:
    return {v["path"]: v for v in record["blocks"]["pixel"]["PublicUniforms"]}


def test_usda_upload_gives_the_first_or_the_named_material(client):
    r = client.post("/v1/generate", content=layer_text(), headers=USDA)
    assert r.status_code == 200, r.text
    assert r.json()["element"] == "/Looks/Wood" and r.json()["document"] is None
    assert uniforms(r.json())["/Looks/Wood/Texture.inputs:file"]["value"] == "wood.png"
    r = client.post("/v1/generate", params={"element": "/Looks/Plain", "target": "essl", "source": "false"},
                    content=layer_text(), headers=USDA)
    assert r.status_code == 200, r.text
    record = r.json()
    assert record["element"] == "/Looks/Plain" and record["target"] == "essl" and record["stages"]["pixel"] is None
    assert uniforms(record)["/Looks/Plain/Surface.inputs:roughness"]["value"] == 0.25


def test_usdz_upload_names_textures_inside_the_package(client, tmp_path):
    body = package(tmp_path, layer_text("textures/wood.png"), ("textures/wood.png", b"\x89PNG not read"))
    r = client.post("/v1/generate", content=body, headers=USDZ)
    assert r.status_code == 200, r.text
    assert uniforms(r.json())["/Looks/Wood/Texture.inputs:file"]["value"] == "textures/wood.png"


@pytest.mark.parametrize("texture", ["../../etc/passwd", "/etc/passwd"])
def test_usdz_asset_leaving_the_package_is_refused(client, tmp_path, texture):
    r = client.post("/v1/generate", content=package(tmp_path, layer_text(texture)), headers=USDZ)
    error = assert_error(r, 403, "path_not_allowed")
    assert error["where"] == "/Looks/Wood/Texture.inputs:file"


def test_layers_refering_outside_the_upload_are_refused(client, tmp_path):
    text = '#usda 1.0\n(\n    subLayers = [@/etc/hosts@]\n)\n'
    assert_error(client.post("/v1/generate", content=text, headers=USDA), 400, "include_refused")
    referencing = '#usda 1.0\ndef "Looks" (\n    references = @../outside.usda@\n)\n{\n}\n'
    r = client.post("/v1/generate", content=package(tmp_path, referencing), headers=USDZ)
    assert_error(r, 403, "path_not_allowed")


def test_bad_usd_uploads_get_error_records(client):
    r = client.post("/v1/generate", content=layer_text(shader_id="NoSuchShader"), headers=USDA)
    assert assert_error(r, 422, "unknown_node")["where"] == "/Looks/Wood/Surface"
    r = client.post("/v1/generate", content='#usda 1.0\ndef "A" {\n  float x = (1,\n}\n', headers=USDA)
    assert assert_error(r, 400, "invalid_document")["where"] == "/A.x"
    assert_error(client.post("/v1/generate", content=b"\xff\xfe not text", headers=USDA), 400, "invalid_document")
    assert_error(client.post("/v1/generate", content=b"PK not a zip", headers=USDZ), 400, "invalid_document")


def test_usd_uploads_have_the_same_size_limit(client):
    r = client.post("/v1/generate", content=b"PK\x03\x04" + b"\0" * (3 * MIB), headers=USDZ)
    assert_error(r, 413, "too_large")


# -- thumbnails ----------------------------------------------------------------------------------
def solid_png(rgb: tuple[int, int, int]) -> bytes:
    import OpenImageIO as oiio
    import numpy as np

    image = oiio.ImageBuf(oiio.ImageSpec(4, 4, 3, oiio.UINT8))
    image.set_pixels(oiio.ROI(0, 4, 0, 4), np.full((4, 4, 3), rgb, "u1"))
    path = Path(os.environ.get("TMPDIR", "/tmp")) / f"solid-{os.getpid()}-{rgb}.png"
    assert image.write(str(path)), oiio.geterror()
    data = path.read_bytes()
    path.unlink()
    return data


def centre_rgb(png: bytes) -> list[float]:
    import OpenImageIO as oiio
    import numpy as np

    path = Path(os.environ.get("TMPDIR", "/tmp")) / f"thumb-{os.getpid()}.png"
    path.write_bytes(png)
    pixels = np.asarray(oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT))
    path.unlink()
    h, w = pixels.shape[:2]
    return pixels[h // 2 - 4:h // 2 + 4, w // 2 - 4:w // 2 + 4, :3].mean(axis=(0, 1)).tolist()


def test_usdz_thumbnail_reads_its_textures_inside_the_package(client, tmp_path):
    colours = {}
    for name, rgb in (("red", (230, 20, 20)), ("blue", (20, 20, 230))):
        folder = tmp_path / name
        folder.mkdir()
        body = package(folder, layer_text("textures/wood.png"), ("textures/wood.png", solid_png(rgb)))
        r = client.post("/v1/thumbnails", params={"size": 64}, content=body, headers=USDZ)
        assert r.status_code == 200 and r.headers["content-type"] == "image/png", r.text
        colours[name] = centre_rgb(r.content)
    red, blue = colours["red"], colours["blue"]
    assert red[0] > 2 * red[2] and blue[2] > 2 * blue[0]  # each package's own texture, not a cached other


def test_usd_thumbnail_jobs_and_refusals(client, tmp_path):
    r = client.post("/v1/thumbnails", params={"async": "true", "size": 32, "element": "/Looks/Plain"},
                    content=layer_text(), headers=USDA)
    assert r.status_code == 202, r.text
    # a layer's textures come from the texture roots, as a MaterialX document's do
    r = client.post("/v1/thumbnails", content=layer_text("/etc/passwd"), headers=USDA)
    assert_error(r, 403, "path_not_allowed")
    r = client.post("/v1/thumbnails", content=package(tmp_path, layer_text("../../etc/passwd")), headers=USDZ)
    assert_error(r, 403, "path_not_allowed")
    assert_error(client.post("/v1/thumbnails", params={"size": 4}, content=layer_text(), headers=USDA),
                 422, "invalid_request")
