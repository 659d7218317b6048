"""Each USD scene renders the same image as its equivalent MaterialX document (our generator and
renderer on both): PSNR >= 60 dB on the linear framebuffer."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import math

import numpy as np
import pytest

from shadergen.render import Renderer

SIZE = 128
MIN_PSNR_DB = 60.0


@pytest.fixture(scope="module")
def renderer() -> Renderer:
    return Renderer(search_paths=[])


def render(gen, renderer, path, folder) -> np.ndarray:
    [record] = [r for r in gen.records(path) if "error" not in r]
    result = renderer.render(record, size=SIZE, document_dir=str(folder))
    assert result.warnings == []  # every texture was found and read
    return result.rgba


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    mse = float(np.mean((np.clip(a, 0, 1) - np.clip(b, 0, 1)) ** 2))
    return math.inf if mse == 0 else 10 * math.log10(1 / mse)


@pytest.mark.parametrize("usd, mtlx", [("preview", "preview_mtlx"), ("brick", "brick_mtlx"), ("usdz", "preview_mtlx")])
def test_usd_renders_like_the_equivalent_materialx(gen, renderer, scenes, usd, mtlx):
    ours = render(gen, renderer, getattr(scenes, usd), scenes.folder)
    reference = render(gen, renderer, getattr(scenes, mtlx), scenes.folder)
    db = psnr(ours, reference)
    print(f"{usd}: {db:.1f} dB against {getattr(scenes, mtlx).name}")
    assert db >= MIN_PSNR_DB
    # not two blank images: the sphere is there, and the texture varies across it
    covered = ours[..., 3] > 0.99
    assert covered.mean() > 0.2
    assert ours[covered][:, :3].std(axis=0).max() > 0.05


def test_sampler_state_is_read_from_the_usd_inputs_of_the_image(gen, scenes):
    """The renderer finds an image's address and filter modes beside its file by the record's
    paths, which for USD are attribute paths (`.../Image.inputs:file`)."""
    from shadergen.render.inputs import siblings
    from shadergen.render.textures import GL_MIRRORED_REPEAT, GL_REPEAT, sampling_from

    [record] = list(gen.records(scenes.brick))
    variables = record["blocks"]["pixel"]["PublicUniforms"]
    [file] = [v for v in variables if v["path"] == "/World/Looks/Brick/Textures/Image.inputs:file"]
    sampling = sampling_from(siblings(file, variables))
    assert (sampling.wrap_u, sampling.wrap_v, sampling.closest) == (GL_MIRRORED_REPEAT, GL_REPEAT, True)
