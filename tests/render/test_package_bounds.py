"""Issue 21: what a usdz package or an image makes the renderer read is bounded before it is read.
A package with a compressed member (a deflate bomb) or a directory that lies is refused as not a
valid usdz; an image whose header declares more values than the renderer's limit is refused as
too_large, inside a package and outside, on the command line as an error record; a legitimate
package still renders its texture."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from hostile_packages import LAYER, deep_exr, deflate_bomb_package, huge_png_header, png, textured_layer, usdz, \
    with_directory_size
from shadergen.api import Generator
from shadergen.render import Environment, RenderError
from shadergen.render.imageio import MAX_IMAGE_VALUES

TEXTURE = "textures/wood.png"
RED = (230, 20, 20)


@pytest.fixture(scope="module")
def gen() -> Generator:
    return Generator()


def package_file(folder, members: list[tuple[str, bytes]], compressed=()) -> str:
    path = folder / "scene.usdz"
    path.write_bytes(usdz(members, compressed))
    return str(path)


def render_package(gen, renderer, path: str, folder):
    [record] = [r for r in gen.records(Path(path)) if "error" not in r]
    return renderer.render(record, size=32, document_dir=str(folder))


def refusal(gen, renderer, path: str, folder) -> RenderError:
    with pytest.raises(RenderError) as caught:
        render_package(gen, renderer, path, folder)
    return caught.value


def test_a_stored_package_renders_its_texture(gen, renderer, tmp_path):
    path = package_file(tmp_path, [(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(8, 8, RED))])
    result = render_package(gen, renderer, path, tmp_path)
    assert result.warnings == []
    red, green, blue = result.rgba[16, 16, :3]
    assert red > 4 * blue and red > 4 * green  # lit by the sky, but the texture's red


def test_a_deflate_bomb_member_is_refused_unread(gen, renderer, tmp_path):
    path = tmp_path / "scene.usdz"
    path.write_bytes(deflate_bomb_package(TEXTURE, 256 << 20))
    assert path.stat().st_size < 1 << 20
    error = refusal(gen, renderer, str(path), tmp_path)
    assert error.code == "invalid_document" and error.where == TEXTURE
    assert "compressed" in error.message


@pytest.mark.parametrize("local_header_too", [False, True])
def test_a_directory_that_understates_a_member_is_refused(gen, renderer, tmp_path, local_header_too):
    """Told in the directory only, the directory disagrees with the member's own header; told in
    both, the rest of the member lies between members unlisted: either way nothing of it is read."""
    honest = usdz([(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(64, 64, RED))])
    path = tmp_path / "scene.usdz"
    path.write_bytes(with_directory_size(honest, TEXTURE, 100, local_header_too))
    error = refusal(gen, renderer, str(path), tmp_path)
    assert error.code == "invalid_document" and error.where == TEXTURE


def test_a_directory_that_overstates_a_member_is_refused(gen, renderer, tmp_path):
    honest = usdz([(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(8, 8, RED))])
    path = tmp_path / "scene.usdz"
    path.write_bytes(with_directory_size(honest, TEXTURE, 1 << 30, local_header_too=True))
    error = refusal(gen, renderer, str(path), tmp_path)
    assert error.code == "invalid_document" and error.where == TEXTURE and "more than the package holds" in error.message


# 60000 x 60000 is refused by OpenImageIO's own check of the header in open, 10000 x 10000 (3e8
# values, 1.2 GB as float32) by the renderer's check of the header OpenImageIO read
@pytest.mark.parametrize("side", [60000, 10000])
def test_a_huge_image_header_is_refused_inside_a_package(gen, renderer, tmp_path, side):
    path = package_file(tmp_path, [(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, huge_png_header(side, side))])
    error = refusal(gen, renderer, path, tmp_path)
    assert error.code == "too_large" and error.where == TEXTURE
    assert f"limit: {MAX_IMAGE_VALUES} values" in error.message and "/tmp" not in error.message


def test_a_huge_image_header_is_refused_beside_a_layer_and_as_an_environment(gen, renderer, tmp_path):
    (tmp_path / "huge.png").write_bytes(huge_png_header(60000, 60000))
    (tmp_path / "scene.usda").write_text(textured_layer("huge.png"))
    error = refusal(gen, renderer, str(tmp_path / "scene.usda"), tmp_path)
    assert error.code == "too_large" and error.where == "huge.png"  # as the layer names it
    with pytest.raises(RenderError) as caught:
        Environment.load(str(tmp_path / "huge.png"))
    assert caught.value.code == "too_large"


def test_a_header_openimageio_refuses_for_its_size_is_too_large_too(tmp_path):
    """OpenImageIO refuses some headers itself (an HDR over 65535 a side) before ours is read."""
    from shadergen.render.imageio import read_image

    (tmp_path / "big.hdr").write_bytes(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n")
    with pytest.raises(RenderError) as caught:
        read_image(str(tmp_path / "big.hdr"))
    assert caught.value.code == "too_large", caught.value.message


def test_the_limit_counts_channels(tmp_path):
    from shadergen.render.textures import TextureCache

    (tmp_path / "wide.png").write_bytes(png(64, 64, RED))  # 64 x 64 x 3 = 12288 values
    upload = lambda image: image  # noqa: E731: the image itself stands for its texture
    assert TextureCache(max_image_values=12288).file(upload, str(tmp_path / "wide.png")).shape == (64, 64, 3)
    with pytest.raises(RenderError) as caught:
        TextureCache(max_image_values=12287).file(upload, str(tmp_path / "wide.png"))
    assert caught.value.code == "too_large" and "limit: 12287 values" in caught.value.message


def test_the_command_line_gives_an_error_record(tmp_path):
    (tmp_path / "huge.png").write_bytes(huge_png_header(60000, 60000))
    (tmp_path / "scene.usda").write_text(textured_layer("huge.png"))
    run = subprocess.run([sys.executable, "-m", "shadergen.cli", "render", "scene.usda", "-o", "out.png", "--json",
                          "--size", "32"], capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert run.returncode == 1 and "Traceback" not in run.stderr
    error = json.loads(run.stdout)["error"]
    assert error["code"] == "too_large" and error["where"].endswith("huge.png")
    assert not (tmp_path / "out.png").exists()


def test_the_limit_is_the_machines_to_set(tmp_path):
    """SHADERGEN_MAX_IMAGE_VALUES moves the limit for a command line render (a machine with the
    memory for 8K textures raises it); a value that is not a positive count is an error record."""
    (tmp_path / "wide.png").write_bytes(png(64, 64, RED))  # 12288 values
    (tmp_path / "scene.usda").write_text(textured_layer("wide.png"))

    def render(limit: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "shadergen.cli", "render", "scene.usda", "-o", "out.png",
                               "--json", "--size", "32"], capture_output=True, text=True, cwd=tmp_path, timeout=300,
                              env={**os.environ, "SHADERGEN_MAX_IMAGE_VALUES": limit})

    assert render("12288").returncode == 0 and (tmp_path / "out.png").exists()
    for limit, code in (("12287", "too_large"), ("lots", "invalid_setting")):
        run = render(limit)
        assert run.returncode == 1 and "Traceback" not in run.stderr, run.stderr
        assert json.loads(run.stdout)["error"]["code"] == code


def test_a_deep_image_is_refused_before_it_is_read(tmp_path):
    """Read through OpenImageIO's Python binding, a deep image corrupts the heap (the process aborts
    in free()): it is refused from its header, in a process of its own here, so that a regression
    fails this test instead of ending the session."""
    (tmp_path / "deep.exr").write_bytes(deep_exr())
    run = subprocess.run([sys.executable, "-c", "from shadergen.render.imageio import read_image\n"
                          "from shadergen.render import RenderError\n"
                          "try:\n    read_image('deep.exr')\nexcept RenderError as exc:\n    print(exc.code)\n"],
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert (run.returncode, run.stdout.strip()) == (0, "invalid_image"), run.stderr


CORRUPT_IMAGES = """
import random, sys
import numpy as np
from shadergen.render import RenderError
from shadergen.render.imageio import read_image, write_image

for kind in ("png", "exr"):
    write_image(f"base.{kind}", np.random.default_rng(1).random((16, 16, 4)).astype("f4"))
    original = open(f"base.{kind}", "rb").read()
    for case in range(200):
        rng = random.Random(case)
        data = bytearray(original)
        if case % 5 == 0:
            data = data[:rng.randrange(len(data))]
        else:
            for _ in range(rng.randint(1, 6)):
                data[rng.randrange(len(data))] = rng.randrange(256)
        open(f"case.{kind}", "wb").write(data)
        try:
            read_image(f"case.{kind}")
        except RenderError:
            pass
        except Exception as exc:
            print(kind, case, type(exc).__name__, exc)
print("done")
"""


def test_corrupt_images_are_refused_with_a_code(tmp_path):
    """200 truncations and byte flips each of a PNG and an EXR (fixed seeds), in a process of their
    own: each reads or raises a RenderError; nothing else escapes and nothing aborts. (OpenImageIO's
    message about EXR case 94 quotes bytes that are not UTF-8, which once escaped as a
    UnicodeDecodeError.)"""
    run = subprocess.run([sys.executable, "-c", CORRUPT_IMAGES], capture_output=True, text=True, cwd=tmp_path,
                         timeout=300)
    assert run.returncode == 0 and run.stdout == "done\n", run.stdout + run.stderr[-2000:]
