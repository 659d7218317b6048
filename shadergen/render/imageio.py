"""Images in and out: textures and environments read through OpenImageIO, renders written as PNG
(sRGB, composited on a grey background), EXR (linear RGBA) or .npy (the raw float32 framebuffer).

Every array here is float32 (height, width, channels) with the top row first. Framebuffer colour
is treated as premultiplied by alpha, as MaterialX's surface shaders write it (colour is scaled by
opacity), so supersampling averages it directly and compositing adds the background behind it.
"""
import os
import re
import struct
import zlib

import numpy as np

from .errors import RenderError

# An image of more values (width x height x depth x channels) than this is refused from its
# header, before a pixel is decoded, so a small file declaring a huge image costs nothing. Read as
# float32 and uploaded with its mipmaps, a texture peaks at about 17 bytes a value in a render
# process (a 4096 x 4096 RGBA PNG of 100 kB: 1.27 GB peak RSS, 154 MB before): at this limit
# (4096 x 4096 RGBA, 8192 x 8192 grey) that stays under a render worker's default memory limit.
# A machine with the memory for larger textures (8192 x 8192 RGB: 2^27.6) sets
# SHADERGEN_MAX_IMAGE_VALUES, read when an image is read.
MAX_IMAGE_VALUES = 1 << 26
IMAGE_LIMIT_VARIABLE = "SHADERGEN_MAX_IMAGE_VALUES"
# OpenImageIO refuses some such headers itself, in open (a PNG header claiming gigabytes from a
# small file; anything over its own limits:imagesize_MB): the same refusal, told by its message.
_OIIO_SIZE_REFUSAL = re.compile(r"claims an? [\d.]+ MB image|size [\d.]+ MB exceeds the [\d.]+ MB limit"
                                r"|resolution may not exceed \d+x\d+")


def image_limit() -> int:
    """The most values an image may have: SHADERGEN_MAX_IMAGE_VALUES, else MAX_IMAGE_VALUES."""
    text = os.environ.get(IMAGE_LIMIT_VARIABLE, "")
    if not text:
        return MAX_IMAGE_VALUES
    if not text.isdigit() or int(text) == 0:
        raise RenderError("invalid_setting", f"{IMAGE_LIMIT_VARIABLE} must be a positive integer, not {text!r}",
                          IMAGE_LIMIT_VARIABLE)
    return int(text)


def read_image(path: str, name: str | None = None, max_values: int | None = None) -> np.ndarray:
    """Any format OpenImageIO reads, as float32 (h, w, c) top row first; 8-bit files give
    value / 255 with no colour conversion (colour spaces are the shader's business). `name` is
    what errors call the file (a package member read from a temporary copy), `path` by default.
    An image of more than `max_values` values (default: image_limit()) is refused as too_large."""
    import OpenImageIO as oiio

    name = name or path
    image, spec = _open_checked(path, name, max_values)
    try:
        pixels = image.read_image(0, 0, 0, spec.nchannels, oiio.FLOAT)
        if pixels is None:
            raise RenderError("invalid_image", f"cannot decode image {name}: {_oiio_error(image, path, name)}", name)
    finally:
        image.close()
    pixels = np.asarray(pixels, "f4")
    return pixels[..., None] if pixels.ndim == 2 else pixels


def check_image(path: str, name: str | None = None, max_values: int | None = None) -> None:
    """What read_image refuses from the header alone (too_large, invalid_image), nothing decoded:
    for files passed on to a reader elsewhere (a browser) under the renderer's limits."""
    image, _ = _open_checked(path, name or path, max_values)
    image.close()


def _open_checked(path: str, name: str, max_values: int | None):
    """(the open ImageInput, its spec) once its header is within the limit; closed on refusal."""
    import OpenImageIO as oiio

    max_values = max_values or image_limit()
    image = oiio.ImageInput.open(path)
    if image is None:
        why = _oiio_error(oiio, path, name)
        if _OIIO_SIZE_REFUSAL.search(why):
            raise RenderError("too_large", f"{name}: the image's header declares more than the renderer reads "
                              f"(its limit: {max_values} values): {why}", name)
        raise RenderError("invalid_image", f"cannot read image {name}: {why}", name)
    try:
        spec = image.spec()
        if spec.deep:  # reading one through the Python binding corrupts the heap (OpenImageIO 3.2)
            raise RenderError("invalid_image", f"{name} is a deep image (samples per pixel), not a texture", name)
        values = spec.width * spec.height * max(spec.depth, 1) * spec.nchannels
        if values > max_values:
            depth = f" x {spec.depth}" if spec.depth > 1 else ""
            raise RenderError("too_large", f"{name}: an image of {spec.width} x {spec.height}{depth} pixels x "
                              f"{spec.nchannels} channels is more than the renderer reads (its limit: {max_values} "
                              "values)", name)
    except BaseException:
        image.close()
        raise
    return image, spec


def _oiio_error(source, path: str, name: str) -> str:
    """OpenImageIO's message with the file called by `name` (not a temporary copy's path)."""
    try:
        message = source.geterror()
    except UnicodeDecodeError:  # the message quotes bytes of a corrupt file (an EXR attribute's name)
        message = "a corrupt file (OpenImageIO's message about it is not UTF-8)"
    return (message or "unknown format or unreadable file").replace(path, name)


# the linear grey a thumbnail's transparent pixels are composited over
BACKGROUND = 0.18


def srgb_encode(linear: np.ndarray) -> np.ndarray:
    x = np.maximum(linear, 0.0)
    return np.where(x <= 0.0031308, x * 12.92, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)


def to_srgb8(rgba: np.ndarray, background: float = BACKGROUND, encode=None) -> np.ndarray:
    """uint8 (h, w, 3) sRGB of a linear premultiplied RGBA image over a linear grey background.
    NaN and Inf pixels become black rather than poisoning the conversion. `encode`: linear RGB
    -> display values, instead of sRGB's transfer on Rec.709 (a colour management system's view
    of another working space: cms/ocio.py display_encoder)."""
    rgba = np.nan_to_num(np.asarray(rgba, "f4"), nan=0.0, posinf=0.0, neginf=0.0)
    alpha = np.clip(rgba[..., 3:4], 0.0, 1.0)
    composite = rgba[..., :3] + background * (1.0 - alpha)
    return (np.clip((encode or srgb_encode)(composite), 0.0, 1.0) * 255.0 + 0.5).astype("u1")


def encode_png(rgba: np.ndarray, background: float = BACKGROUND, encode=None) -> bytes:
    """PNG file bytes (8-bit sRGB RGB) of a linear RGBA render, composited over `background`."""
    rgb = to_srgb8(rgba, background, encode)
    height, width = rgb.shape[:2]
    # Each scanline is preceded by its filter type; 0 (none) keeps the encoder trivial.
    raw = np.concatenate([np.zeros((height, 1), "u1"), rgb.reshape(height, width * 3)], 1).tobytes()

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit truecolour
    srgb_intent = b"\x00"  # sRGB chunk: perceptual rendering intent
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"sRGB", srgb_intent)
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def write_image(path: str, rgba: np.ndarray, background: float = BACKGROUND, encode=None) -> None:
    """Write a linear RGBA render by the file's extension: .png (sRGB over `background`, or
    `encode`d as to_srgb8 says), .exr (linear RGBA float), .npy (the float32 array as is)."""
    ext = os.path.splitext(path)[1].lower()
    rgba = np.ascontiguousarray(rgba, "f4")
    try:
        if ext == ".png":
            with open(path, "wb") as f:
                f.write(encode_png(rgba, background, encode))
        elif ext == ".npy":
            np.save(path, rgba)
        elif ext == ".exr":
            _write_exr(path, rgba)
        else:
            raise RenderError("invalid_output", f"cannot write {ext or 'extensionless'} files: use .png, .exr or .npy", path)
    except OSError as exc:
        raise RenderError("invalid_output", f"cannot write {path}: {exc.strerror}", path) from exc


def _write_exr(path: str, rgba: np.ndarray) -> None:
    import OpenImageIO as oiio

    out = oiio.ImageOutput.create(path)
    if out is None:
        raise RenderError("invalid_output", f"OpenImageIO cannot write {path}: {oiio.geterror()}", path)
    spec = oiio.ImageSpec(rgba.shape[1], rgba.shape[0], rgba.shape[2], oiio.FLOAT)
    spec.channelnames = ("R", "G", "B", "A")[: rgba.shape[2]]
    ok = out.open(path, spec) and out.write_image(rgba)
    error = out.geterror()
    out.close()
    if not ok:
        raise RenderError("invalid_output", f"cannot write {path}: {error}", path)
