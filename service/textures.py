"""Texture files for browsers (the editor's preview): a filename as a document names it, read
only from the configured texture roots, as thumbnails read it (safety.texture_in_roots), and
refused before it is read when the file or the image its header declares is over the limits."""
from pathlib import Path

from .errors import ServiceError
from .safety import texture_in_roots

# what a browser decodes itself; other formats (EXR, HDR, TIFF, TGA) are sent as they are too,
# the editor decodes the ones it can
MEDIA_TYPES = {".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg", ".gif": "image/gif",
               ".bmp": "image/bmp", ".webp": "image/webp", ".hdr": "image/vnd.radiance", ".exr": "image/x-exr",
               ".tif": "image/tiff", ".tiff": "image/tiff", ".tga": "image/x-tga"}


class TextureFile:
    __slots__ = ("path", "media_type")

    def __init__(self, path: Path, media_type: str):
        self.path, self.media_type = path, media_type


def find_texture(name: str, roots: list[str], max_bytes: int) -> TextureFile:
    """The file `name` names in the roots, or the contract error that says why not (`where`:
    the query parameter `path`)."""
    real = texture_in_roots(name, roots)
    if real is None:
        raise ServiceError("path_not_allowed", f"texture {name!r} is outside the configured texture roots", "path")
    media_type = MEDIA_TYPES.get(real.suffix.lower())
    if media_type is None:
        # no image this route serves is there: 404 (415 is a request body's refusal, the contract's)
        raise ServiceError("not_found", f"texture {name!r} is not an image format the editor reads "
                           f"({', '.join(sorted(MEDIA_TYPES))})", "path")
    try:
        size = real.stat().st_size if real.is_file() else None
    except OSError:
        size = None
    if size is None:
        raise ServiceError("not_found", f"texture {name!r} is not a file in the texture roots", "path")
    if size > max_bytes:
        raise ServiceError("too_large", f"texture {name!r} is {size} bytes, more than the {max_bytes} served "
                           "(SHADERGEN_MAX_TEXTURE_BYTES)", "path")
    check_image_header(real, name)
    return TextureFile(real, media_type)


def check_image_header(path: Path, name: str) -> None:
    """The renderer's refusals from the header (a 60000 x 60000 PNG is 70 bytes), so the editor
    is never sent what a thumbnail of it would refuse; `where` is the query parameter."""
    from shadergen.render.errors import RenderError
    from shadergen.render.imageio import check_image

    try:
        check_image(str(path), name)
    except RenderError as exc:
        raise ServiceError(exc.code, exc.message, "path") from None
