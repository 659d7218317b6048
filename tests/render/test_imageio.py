"""Render outputs written and read back through OpenImageIO."""
import numpy as np
import OpenImageIO as oiio
import pytest

from shadergen.render import RenderError
from shadergen.render.imageio import encode_png, read_image, srgb_encode, write_image


def linear_image() -> np.ndarray:
    rgba = np.zeros((4, 6, 4), "f4")
    rgba[0, 0] = [1.0, 0.5, 0.0, 1.0]      # opaque
    rgba[1, 1] = [0.09, 0.09, 0.09, 0.5]   # half covered (premultiplied)
    rgba[2, 2] = [np.nan, np.inf, 2.0, 1.0]  # broken shading must not break the PNG
    rgba[3, 5] = [0.2, 0.4, 0.6, 1.0]
    return rgba


def test_png_round_trip_is_srgb_over_the_background(tmp_path):
    path = tmp_path / "thumb.png"
    write_image(str(path), linear_image(), background=0.18)
    back = oiio.ImageBuf(str(path))
    assert back.spec().nchannels == 3 and back.spec().format == oiio.UINT8
    pixels = np.asarray(back.get_pixels(oiio.UINT8))
    assert pixels.shape == (4, 6, 3)
    expected = lambda linear: np.round(np.clip(srgb_encode(np.float64(linear)), 0, 1) * 255).astype(int)
    np.testing.assert_array_equal(pixels[0, 0], expected([1.0, 0.5, 0.0]))
    np.testing.assert_array_equal(pixels[0, 1], expected([0.18] * 3))            # empty: the background
    np.testing.assert_array_equal(pixels[1, 1], expected([0.09 + 0.18 * 0.5] * 3))
    np.testing.assert_array_equal(pixels[2, 2], expected([0.0, 0.0, 1.0]))       # NaN and Inf drawn black
    np.testing.assert_array_equal(pixels[3, 5], expected([0.2, 0.4, 0.6]))
    assert path.read_bytes() == encode_png(linear_image(), background=0.18)


def test_exr_round_trip_is_exact_linear_rgba(tmp_path):
    rgba = np.random.default_rng(1).uniform(-1, 8, (5, 7, 4)).astype("f4")
    write_image(str(tmp_path / "thumb.exr"), rgba)
    back = read_image(str(tmp_path / "thumb.exr"))
    assert back.shape == (5, 7, 4)
    np.testing.assert_array_equal(back, rgba)


def test_npy_is_the_raw_float_array(tmp_path):
    rgba = linear_image()
    write_image(str(tmp_path / "raw.npy"), rgba)
    back = np.load(tmp_path / "raw.npy")
    assert back.dtype == np.float32
    np.testing.assert_array_equal(back, rgba)  # NaN included: nothing is cleaned


def test_unknown_output_format_and_unreadable_images_raise(tmp_path):
    with pytest.raises(RenderError) as caught:
        write_image(str(tmp_path / "thumb.gif2"), linear_image())
    assert caught.value.code == "invalid_output"
    (tmp_path / "junk.png").write_bytes(b"not a png")
    with pytest.raises(RenderError) as caught:
        read_image(str(tmp_path / "junk.png"))
    assert caught.value.code == "invalid_image"
