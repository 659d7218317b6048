"""POST /v1/images/decode: the EXR, TIFF and TGA files the editor's browser cannot decode, decoded
through OpenImageIO into float32 pixels (nothing stored), sizes bounded, bad files refused with
code, message and where."""
import numpy as np
import pytest

from service.errors import ServiceError
from service.images import decode_image
from service_testing import assert_error

FORMATS = {"exr": "half", "tif": "float", "tga": "uint8"}


def image_file(tmp_path, suffix: str, pixels: np.ndarray, pixel_type: str = "float", compression: str = "") -> bytes:
    import OpenImageIO as oiio

    height, width, channels = pixels.shape
    spec = oiio.ImageSpec(width, height, channels, oiio.FLOAT)
    if compression:
        spec.attribute("compression", compression)
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(0, width, 0, height), pixels.astype("f4"))
    path = tmp_path / f"made.{suffix}"
    assert buf.write(str(path), pixel_type), buf.geterror()
    return path.read_bytes()


def gradient(height: int = 8, width: int = 16, channels: int = 3) -> np.ndarray:
    y, x = np.mgrid[0:height, 0:width].astype("f4")
    planes = [x / width, y / height, (x + y) / (width + height), np.full_like(x, 0.5)]
    return np.stack(planes[:channels], axis=-1)


def decoded(response) -> np.ndarray:
    assert response.status_code == 200, response.text
    shape = [int(response.headers[f"x-image-{n}"]) for n in ("height", "width", "channels")]
    return np.frombuffer(response.content, "<f4").reshape(shape)


@pytest.mark.parametrize("suffix", sorted(FORMATS))
def test_each_format_decodes_to_its_pixels_top_row_first(client, tmp_path, suffix):
    pixels = gradient(channels=4 if suffix == "exr" else 3)
    body = image_file(tmp_path, suffix, pixels, FORMATS[suffix])
    r = client.post(f"/v1/images/decode?name=Folder-less.{suffix.upper()}", content=body,
                    headers={"content-type": "application/octet-stream"})
    got = decoded(r)
    assert got.shape == pixels.shape
    tolerance = 1 / 255 if FORMATS[suffix] == "uint8" else 1e-3
    assert np.abs(got - pixels).max() <= tolerance
    assert r.headers["cache-control"] == "no-store"


def test_a_file_larger_than_a_request_body_is_decoded_up_to_the_texture_limit(client, tmp_path):
    """An EXR of 4 MiB, over the 2 MiB of SHADERGEN_MAX_BODY_BYTES: the route takes bodies up to
    SHADERGEN_MAX_TEXTURE_BYTES, as large as a texture the editor fetches."""
    pixels = np.random.default_rng(1).random((512, 512, 4), dtype=np.float32)
    body = image_file(tmp_path, "exr", pixels, "float", compression="none")
    assert len(body) > 4 * 1024 * 1024
    got = decoded(client.post("/v1/images/decode?name=large.exr", content=body))
    assert np.array_equal(got, pixels)


def test_a_file_that_is_no_image_is_refused(client):
    error = assert_error(client.post("/v1/images/decode?name=broken.exr", content=b"not an exr at all"), 422,
                         "invalid_image")
    assert error["where"] == "body" and "broken.exr" in error["message"]


def test_an_empty_body_is_refused(client):
    error = assert_error(client.post("/v1/images/decode?name=empty.exr", content=b""), 422, "invalid_image")
    assert error["where"] == "body"


@pytest.mark.parametrize("name", ["picture.png", "../up.exr", "a/b.exr", "exr"])
def test_a_name_that_is_not_a_decoded_format_or_has_a_folder_is_refused(client, name):
    error = assert_error(client.post("/v1/images/decode", params={"name": name}, content=b"x"), 422,
                         "invalid_request")
    assert error["where"] == "query.name"


def test_sizes_are_bounded_by_the_file_and_by_what_its_header_declares(tmp_path, monkeypatch):
    body = image_file(tmp_path, "exr", gradient(), "half")
    with pytest.raises(ServiceError) as e:
        decode_image(body, "big.exr", max_bytes=len(body) - 1)
    assert (e.value.code, e.value.status, e.value.where) == ("too_large", 413, "body")
    monkeypatch.setenv("SHADERGEN_MAX_IMAGE_VALUES", "100")  # 16 x 8 x 3 values declared
    with pytest.raises(ServiceError) as e:
        decode_image(body, "big.exr", max_bytes=len(body))
    assert (e.value.code, e.value.status, e.value.where) == ("too_large", 413, "body")
