"""Issue 27, item 3: OpenEXR files decoded in the page (service/static/editor/exr.js), in a real
browser (editor_testing.py), against OpenImageIO's reading of the same file, which OpenImageIO
wrote: the compressions read there (none, RLE, ZIPS, ZIP) and each pixel type give OpenImageIO's
values exactly with no request; what it leaves (PIZ, PXR24, B44, tiled files, other channel sets)
goes to the service's decoder, once, and comes back the same; a damaged file is an error naming it."""
import base64

import numpy as np
import pytest

from editor_testing import browser, editor  # noqa: F401 (fixtures)

DECODE = """
const [data, name, done] = arguments;
const bytes = Uint8Array.from(atob(data), (c) => c.charCodeAt(0));
Promise.all([import("/editor/images.js"), import("/editor/api.js")]).then(async ([images, api]) => {
  const before = api.traffic.decode;
  try {
    const image = await images.decodeImage(new Blob([bytes]), name);
    const raw = new Uint8Array(image.data.buffer, image.data.byteOffset, image.data.byteLength);
    let text = "";
    for (let i = 0; i < raw.length; i += 0x8000) text += String.fromCharCode(...raw.subarray(i, i + 0x8000));
    done({ width: image.width, height: image.height, channels: image.channels, data: btoa(text),
           requests: api.traffic.decode - before });
  } catch (failure) {
    done({ error: String(failure.message), requests: api.traffic.decode - before });
  }
});
"""


def written(tmp_path, pixels: np.ndarray, fmt: str, compression: str, channels=None, tile=0, origin=(0, 0)):
    """An .exr of `pixels` (h, w, c) written by OpenImageIO, and its pixels as OpenImageIO reads them."""
    import OpenImageIO as oiio

    height, width, count = pixels.shape
    spec = oiio.ImageSpec(width, height, count, oiio.FLOAT)
    spec.x, spec.y = origin
    if channels:
        spec.channelnames = channels
    spec.attribute("compression", compression)
    if tile:
        spec.tile_width = spec.tile_height = tile
    path = tmp_path / f"{compression}-{fmt}-{count}-{tile}.exr"
    out = oiio.ImageOutput.create(str(path))
    spec.set_format(getattr(oiio, fmt.upper()))
    assert out.open(str(path), spec), oiio.geterror()
    assert out.write_image(pixels.astype("f4")), out.geterror()
    out.close()
    read = oiio.ImageInput.open(str(path))
    assert read.spec().get_string_attribute("compression") == compression
    back = np.asarray(read.read_image(0, 0, 0, read.spec().nchannels, oiio.FLOAT), "f4")
    read.close()
    return path.read_bytes(), back.reshape(height, width, -1)


def decoded(editor, data: bytes, name: str = "image.exr") -> dict:
    editor.set_script_timeout(60)
    answer = editor.execute_async_script(DECODE, base64.b64encode(data).decode(), name)
    if "data" in answer:
        answer["pixels"] = np.frombuffer(base64.b64decode(answer.pop("data")), "<f4").reshape(
            answer["height"], answer["width"], answer["channels"])
    return answer


def ramp(height: int, width: int, channels: int) -> np.ndarray:
    """Values that differ pixel to pixel and channel to channel (any reordering shows), some
    negative, some above one, within half's range."""
    values = np.arange(height * width * channels, dtype="f4").reshape(height, width, channels)
    return np.sin(values * 0.37) * 3 + values / values.size


@pytest.mark.parametrize("compression", ["none", "rle", "zips", "zip"])
@pytest.mark.parametrize("fmt", ["half", "float", "uint"])
def test_the_page_reads_an_exr_as_openimageio_does_with_no_request(editor, tmp_path, compression, fmt):
    # 37 x 21: the last ZIP chunk is 5 rows, not 16; the data window starts at (3, 5)
    pixels = ramp(21, 37, 4)
    if fmt == "uint":  # OpenImageIO writes and reads unsigned ints as 0 to 1
        pixels = (pixels - pixels.min()) / np.ptp(pixels)
    data, expected = written(tmp_path, pixels, fmt, compression, origin=(3, 5))
    got = decoded(editor, data)
    assert got.get("error") is None and got["requests"] == 0, got
    assert (got["width"], got["height"], got["channels"]) == (37, 21, 4)
    if fmt == "uint":  # the division by 2^32 - 1 may round the other way in the last place
        np.testing.assert_allclose(got["pixels"], expected, rtol=0, atol=1e-7)
    else:
        np.testing.assert_array_equal(got["pixels"], expected)


@pytest.mark.parametrize("channels", [["Y"], ["Y", "A"], ["R", "G", "B"]])
def test_the_page_reads_grey_and_rgb_exrs_in_the_order_openimageio_gives(editor, tmp_path, channels):
    data, expected = written(tmp_path, ramp(16, 9, len(channels)), "half", "zip", channels=channels)
    got = decoded(editor, data)
    assert got.get("error") is None and got["requests"] == 0, got
    np.testing.assert_array_equal(got["pixels"], expected)


@pytest.mark.parametrize("compression, tile, channels", [
    ("piz", 0, None), ("pxr24", 0, None), ("b44", 0, None), ("zip", 16, None), ("zip", 0, ["R", "G"]),
])
def test_what_the_page_does_not_read_the_service_decodes(editor, tmp_path, compression, tile, channels):
    data, expected = written(tmp_path, ramp(20, 24, len(channels or "RGBA")), "half", compression,
                             channels=channels, tile=tile)
    got = decoded(editor, data)
    assert got.get("error") is None and got["requests"] == 1, got
    np.testing.assert_array_equal(got["pixels"], expected)


def test_a_damaged_exr_is_an_error_that_names_it(editor, tmp_path):
    data, _ = written(tmp_path, ramp(40, 40, 3), "half", "zip")
    cut = decoded(editor, data[: len(data) // 2], "cut.exr")
    assert cut["requests"] == 0 and "cut.exr" in cut["error"], cut
    not_exr = decoded(editor, b"\x89PNG\r\n\x1a\n" + bytes(64), "png.exr")
    assert not_exr == {"error": "png.exr is not an OpenEXR image", "requests": 0}
    # a header that declares an enormous image is refused before anything is allocated
    huge = bytearray(data)
    at = huge.index(b"dataWindow\x00box2i\x00") + len(b"dataWindow\x00box2i\x00") + 4
    huge[at + 8: at + 16] = np.array([1 << 20, 1 << 20], "<i4").tobytes()
    refused = decoded(editor, bytes(huge), "huge.exr")
    assert refused["requests"] == 0 and "more than the" in refused["error"], refused
