"""A filtered file texture is stored at power-of-two sides, each the one nearest in ratio to the
file's: llvmpipe compiles a program's machine code apart for power-of-two and other sides, so a
library of one topology whose files had both kinds compiled it twice. A "closest" read and a
renderer made for like-for-like reads (file_mipmaps=False) keep the file's own texels."""
import numpy as np
import pytest

from shadergen.render.inputs import TextureRequest
from shadergen.render.textures import Sampling, TextureCache, mip_chain, power_of_two


@pytest.fixture
def gradient(tmp_path) -> str:
    """A 40 x 60 (rows x columns) image: red rising along the columns, green along the rows."""
    oiio = pytest.importorskip("OpenImageIO")
    rows, columns = np.meshgrid(np.linspace(0, 1, 40), np.linspace(0, 1, 60), indexing="ij")
    pixels = np.stack([columns, rows, np.full_like(rows, 0.5)], axis=2).astype("f4")
    path = str(tmp_path / "gradient.exr")
    assert oiio.ImageBuf(pixels).write(path)
    return path


def stored(cache: TextureCache, path: str, sampling: Sampling) -> np.ndarray:
    texture, warning = cache.texture(lambda image: image, TextureRequest("u_file", sampling, path, None))
    assert warning is None
    return texture


@pytest.mark.parametrize("side, expected", [(1, 1), (2, 2), (3, 4), (40, 32), (60, 64), (640, 512), (768, 1024),
                                            (2048, 2048)])
def test_each_side_becomes_the_power_of_two_nearest_it_in_ratio(side, expected):
    assert power_of_two(np.zeros((side, 1, 1), "f4")).shape[0] == expected
    assert power_of_two(np.zeros((1, side, 1), "f4")).shape[1] == expected


def test_a_filtered_file_is_stored_at_power_of_two_sides_with_its_content(gradient):
    image = stored(TextureCache(), gradient, Sampling())
    assert image.shape == (32, 64, 3)
    # a linear ramp resampled over the same extent is the same ramp, at the new texel centres
    np.testing.assert_allclose(image[16, :, 0], np.interp((np.arange(64) + 0.5) * 60 / 64 - 0.5, np.arange(60),
                                                          np.linspace(0, 1, 60)), atol=2e-3)
    np.testing.assert_allclose(image[..., 2], 0.5, atol=1e-6)


def test_detail_at_the_files_texel_frequency_stays_grey_in_the_mip_levels():
    """1-texel black and white columns, 60 wide: the file's own chain averages them to 0.5 grey;
    resampled to 64 texels, a linear filter left level 1 between 0.47 and 0.94."""
    stripes = np.zeros((60, 60, 1), "f4")
    stripes[:, 1::2] = 1.0
    levels = mip_chain(power_of_two(stripes))
    assert levels[0].shape == (64, 64, 1) and 0.0 <= levels[0].min() and levels[0].max() <= 1.0
    for level in levels[1:]:
        np.testing.assert_allclose(level, 0.5, atol=0.05)


def test_a_closest_read_or_a_like_for_like_cache_keeps_the_files_sides(gradient):
    assert stored(TextureCache(), gradient, Sampling(closest=True)).shape == (40, 60, 3)
    assert stored(TextureCache(power_of_two_sides=False), gradient, Sampling()).shape == (40, 60, 3)


def test_the_same_file_read_both_ways_is_two_textures(gradient):
    cache = TextureCache()
    assert stored(cache, gradient, Sampling()).shape == (32, 64, 3)
    assert stored(cache, gradient, Sampling(closest=True)).shape == (40, 60, 3)
    assert stored(cache, gradient, Sampling()).shape == (32, 64, 3)
