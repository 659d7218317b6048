"""Images the editor's browser cannot decode itself (OpenEXR, TIFF, Targa), decoded here through
OpenImageIO as the renderer reads textures and environments, and answered as float32 pixels the
page uploads as a float texture. Nothing is kept: the upload lives in a private temporary file
for the length of the read. Bounded twice: the file's bytes (SHADERGEN_MAX_TEXTURE_BYTES) and the
values its header declares (the renderer's SHADERGEN_MAX_IMAGE_VALUES), before a pixel is decoded."""
import os
import re
import tempfile

import numpy as np

from .errors import ServiceError

DECODED_FORMATS = (".exr", ".tif", ".tiff", ".tga")
# a name is only read for its suffix (OpenImageIO chooses its reader by it), never as a path
NAME_PATTERN = r"^[^/\\\x00]*\.([eE][xX][rR]|[tT][iI][fF][fF]?|[tT][gG][aA])$"


class DecodedImage:
    __slots__ = ("width", "height", "channels", "pixels")

    def __init__(self, pixels: np.ndarray):
        self.height, self.width, self.channels = pixels.shape
        self.pixels = np.ascontiguousarray(pixels, "<f4")


def decode_image(body: bytes, name: str, max_bytes: int) -> DecodedImage:
    """The pixels of an uploaded image file `name`, float32 (h, w, c) top row first, or the
    contract error that says why not (`where`: the body, or the query parameter, `query.name`)."""
    from shadergen.render.errors import RenderError
    from shadergen.render.imageio import read_image

    suffix = "." + name.rsplit(".", 1)[-1].lower()  # of ".tiff" too, which splitext calls a stem
    if not re.match(NAME_PATTERN, name) or suffix not in DECODED_FORMATS:
        raise ServiceError("invalid_request", f"name {name!r} must be a file name ending in one of "
                           f"{', '.join(DECODED_FORMATS)}", "query.name")
    if not body:
        raise ServiceError("invalid_image", f"{name} is empty", "body")
    if len(body) > max_bytes:
        raise ServiceError("too_large", f"{name} is {len(body)} bytes, more than the {max_bytes} decoded "
                           "(SHADERGEN_MAX_TEXTURE_BYTES)", "body")
    with tempfile.TemporaryDirectory(prefix="shadergen-decode-") as folder:
        path = os.path.join(folder, "upload" + suffix)
        with open(path, "wb") as f:
            f.write(body)
        try:
            pixels = read_image(path, name)
        except RenderError as exc:
            raise ServiceError(exc.code, exc.message, "body") from None
    if pixels.ndim != 3 or pixels.shape[2] > 4 or pixels.size == 0:
        raise ServiceError("invalid_image", f"{name}: {pixels.shape[-1]} channels; a texture has 1 to 4", "body")
    return DecodedImage(pixels)
