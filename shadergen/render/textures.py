"""File textures (and colour transforms' LUTs) of a shader record: where a filename may be read from, how MaterialX says it is
sampled, and the GL textures kept between renders.

Images are uploaded top row first, as float32 without colour conversion; the generated code
flips v (MaterialX's fileTextureVerticalFlip) and converts colour spaces. Every image is stored
as RGBA: a grey one as grey (what MaterialX's GL texture handler's RRR1 swizzle reads), an RGB one
opaque. One format for every file keeps one machine code per program: llvmpipe compiles a
fragment shader's code per texture format and swizzle bound, which cost a library thumbnail of a
known topology ~1.8 s whenever its texture had another channel count than the first one's.
For the same reason a filtered image is stored at power-of-two sides (power_of_two): llvmpipe's
machine code also depends on whether each side of a bound texture is a power of two.
"""
import base64
import os
from collections import OrderedDict
from dataclasses import dataclass

import numpy as np

from ..paths import inside
from .errors import RenderError
from .context import gl_extras
from .imageio import read_image
from .packages import has_member, member_file, split_member
from .values import numbers

# MaterialX address modes (image node `uaddressmode`/`vaddressmode`) -> GL wrap modes.
GL_CLAMP_TO_BORDER, GL_CLAMP_TO_EDGE, GL_REPEAT, GL_MIRRORED_REPEAT = 0x812D, 0x812F, 0x2901, 0x8370
ADDRESS_MODES = {"constant": GL_CLAMP_TO_BORDER, "clamp": GL_CLAMP_TO_EDGE, "periodic": GL_REPEAT,
                 "mirror": GL_MIRRORED_REPEAT}
ADDRESS_MODE_ORDER = ("constant", "clamp", "periodic", "mirror")  # the enum's integer values
FILTER_TYPE_ORDER = ("closest", "linear", "cubic")
UNRESOLVABLE_TOKENS = ("<UDIM>", "<UVTILE>")
# Failures that refuse the render instead of showing the image node's default: a file the server
# will not read (an image over the limit, a package that is not a valid usdz) is no missing file,
# nor is a limit the operator set wrongly, and a default colour would hide either behind a
# thumbnail that looks right.
REFUSALS = ("too_large", "invalid_document", "invalid_setting")


@dataclass(frozen=True)
class Sampling:
    """How one filename uniform is sampled. The default (no sibling inputs) is MaterialX's:
    periodic in both directions, linear with mipmaps, black border."""
    wrap_u: int = GL_REPEAT
    wrap_v: int = GL_REPEAT
    closest: bool = False
    mipmaps: bool = True  # False: the base level only (Renderer's file_mipmaps)
    border: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)


def _enum(value, names: tuple[str, ...]) -> str | None:
    """An enum input's value, given as its string or its integer index."""
    if isinstance(value, str) and value.strip().lower() in names:
        return value.strip().lower()
    try:
        index = int(value)
    except (TypeError, ValueError):
        return None
    return names[index] if 0 <= index < len(names) else None


def default_colour(value) -> tuple[float, float, float, float] | None:
    """An image node's `default` input as RGBA: a float is grey, missing channels are 0, alpha 1."""
    values = numbers("color4", value)
    if not values:
        return None
    if len(values) == 1:
        values = values * 3
    return tuple((values + [0.0, 0.0, 0.0])[:3] + (values[3:4] or [1.0]))


def sampling_from(siblings: dict[str, object]) -> Sampling:
    """Sampling of an image node from its other inputs (`uaddressmode`, `vaddressmode`,
    `filtertype`, `default`), as MaterialX's renderer sets GL sampler state; inputs absent from
    the record keep MaterialX's defaults. "closest" samples the nearest texel of the nearest mip
    level; "linear" and "cubic" filter trilinearly (GL has no cubic filter)."""
    u = _enum(siblings.get("uaddressmode"), ADDRESS_MODE_ORDER)
    v = _enum(siblings.get("vaddressmode"), ADDRESS_MODE_ORDER)
    return Sampling(wrap_u=ADDRESS_MODES[u] if u else GL_REPEAT, wrap_v=ADDRESS_MODES[v] if v else GL_REPEAT,
                    closest=_enum(siblings.get("filtertype"), FILTER_TYPE_ORDER) == "closest",
                    border=default_colour(siblings.get("default")) or Sampling.border)


def resolve_file(name: str, document_dir: str | None, search_paths: list[str],
                 texture_roots: list[str], confined: bool = True) -> tuple[str | None, str | None]:
    """(path, None) for a readable file, or (None, why not). A relative name is looked up in the
    document's folder, then in each search path. When `confined` (a service rendering what clients
    send), whatever it resolves to (symbolic links followed) must lie inside the document's
    folder, a search path or a texture root, so a document cannot make the renderer read
    arbitrary files, and so must the name made normal as written (`a/x/../b` is `a/b`), before
    the file system is asked: what lies outside the folders never decides what is read. A local
    user rendering their own document reads what it names.
    `package.usdz[member]` names a member of a package, the package being found as any file is."""
    name, member = split_member(name)
    if any(token in name for token in UNRESOLVABLE_TOKENS):
        return None, f"{name}: UDIM/UVTILE file sets are not supported by the thumbnail renderer"
    bases = [d for d in [document_dir, *search_paths] if d]
    roots = [os.path.realpath(d) for d in [*bases, *texture_roots]]
    candidates = [name] if os.path.isabs(name) else [os.path.join(b, name) for b in bases]
    left = False  # a candidate that leaves the folders as written, which the file system is not asked about
    if confined:  # as the service checks it (service/safety.py): made normal as written, in a folder as written
        written_roots = roots + [os.path.abspath(d) for d in [*bases, *texture_roots]]
        written = list(map(os.path.abspath, candidates))
        candidates = [c for c in written if _within(c, written_roots)]
        left = len(candidates) < len(written)
    outside = False
    for candidate in candidates:
        try:
            real = os.path.realpath(candidate)
            exists = os.path.isfile(real)
        except (OSError, ValueError):  # e.g. an embedded NUL byte
            continue
        if not exists:
            continue
        if not confined or _within(real, roots):
            if member is None:
                return real, None
            if has_member(real, member):
                return f"{real}[{member}]", None
            return None, f"{name}[{member}]: the package has no such file"
        outside = True
    if outside:  # a link's target is named to no one: it is a path of the server's
        return None, f"{name}: resolves (through a link) outside the allowed folders"
    if left:
        return None, f"{name}: outside the allowed folders"
    if confined:  # the service's folders are not the client's business
        return None, f"{name}: not found in the document's folder, its search paths or the texture roots"
    where = ", ".join(bases) if bases else "no folder (give a document folder or search paths)"
    return None, f"{name}: not found (looked in {where})"


def _within(path: str, folders: list[str]) -> bool:
    return any(inside(path, folder) for folder in folders)


class TextureCache:
    """Textures of image files, by resolved path and modification time, least recently used
    first out when over `budget_bytes` (trimmed between renders, never during one), and 1 x 1
    textures of constant colours for missing files and unbound samplers. `upload` makes a
    texture of the drawing API from a float32 (h, w, c) image; a texture has `width`, `height`,
    `components` and `release()`. An image of more than `max_image_values` values is refused
    (too_large) from its header (default: imageio.image_limit())."""

    def __init__(self, budget_bytes: int = 512 << 20, max_image_values: int | None = None,
                 power_of_two_sides: bool = True):
        self.budget_bytes = budget_bytes
        self.max_image_values = max_image_values
        self.power_of_two_sides = power_of_two_sides
        self._files: OrderedDict[tuple, object] = OrderedDict()
        self._constants: dict[tuple, object] = {}

    def file(self, upload, path: str, name: str | None = None, power_of_two_sides: bool = False):
        """The texture of a path resolve_file returned (a package member included), resampled to
        power-of-two sides if asked (power_of_two). A refusal calls a file `name` (as the document
        wrote it, not where the server keeps it), a package's member by its name in the package."""
        package, member = split_member(path)
        stat = os.stat(package)
        key = (path, stat.st_mtime_ns, stat.st_size, power_of_two_sides)
        texture = self._files.get(key)
        if texture is None:
            if member is None:
                image = read_image(path, name, self.max_image_values)
            else:
                with member_file(package, member) as copy:
                    image = read_image(copy, member, self.max_image_values)
            texture = upload(power_of_two(image) if power_of_two_sides else image)
            self._files[key] = texture
        self._files.move_to_end(key)
        return texture

    def constant(self, upload, rgba: tuple[float, float, float, float]):
        texture = self._constants.get(rgba)
        if texture is None:
            texture = self._constants[rgba] = upload(np.array(rgba, "f4").reshape(1, 1, 4))
        return texture

    def texture(self, upload, request) -> tuple[object, str | None]:
        """The texture of an inputs.TextureRequest, or a 1 x 1 texture of its default colour and
        the warning saying why the file could not be used."""
        problem = request.problem
        if request.path:
            # a "closest" read keeps the file's own texels: resampling would move their edges
            resample = self.power_of_two_sides and not request.sampling.closest
            try:
                return self.file(upload, request.path, request.file, resample), None
            except RenderError as exc:
                if exc.code in REFUSALS:
                    raise
                problem = exc.message
        warning = f"texture for {request.name} unusable, using its default colour: {problem}" if problem else None
        return self.constant(upload, request.sampling.border), warning

    def trim(self) -> None:
        """Release the textures of files that are gone or changed since they were read, which no
        render can ask for again (a usdz upload's package, removed with its job's folder: what
        one client sent is not kept after its job), then the least recently used over the budget."""
        for key in [key for key in self._files if not _unchanged(key)]:
            self._files.pop(key).release()
        total = sum(t.width * t.height * t.components * 4 for t in self._files.values())
        while self._files and total > self.budget_bytes:
            _, texture = self._files.popitem(last=False)
            total -= texture.width * texture.height * texture.components * 4
            texture.release()


def _unchanged(key: tuple) -> bool:
    """Whether the file of a TextureCache key (path, mtime, size, resampled) is still there as it was read."""
    path, mtime_ns, size, _ = key
    try:
        stat = os.stat(split_member(path)[0])
    except OSError:
        return False
    return (stat.st_mtime_ns, stat.st_size) == (mtime_ns, size)


def upload(ctx, image: np.ndarray, levels: list[np.ndarray] | None = None):
    """A float32 (h, w, c) image, top row first, as a mipmapped GL texture (rows in the same
    order: GL's t = 0 is the first row uploaded, which is what the generated code's v flip
    expects). `levels`: the images of levels 1, 2, ... down to 1 x 1; by default computed here
    as GL's mipmap generation makes them (the driver's own generation compiles a blit shader on
    first use: about 0.1-0.2 s of every thumbnail process on llvmpipe). An RGB image is stored
    as RGBA with alpha 1 (what GL reads from RGB anyway): llvmpipe filters four float channels
    faster than three (Examples carpaint, complete: ~8% less CPU per frame with the environment's
    radiance so stored), and every image in one format (`rgba`) is one machine code per program."""
    image = rgba(np.asarray(image, "f4"))
    height, width = image.shape[:2]
    levels = None if levels is None else [rgba(level) for level in levels]
    texture = ctx.texture((width, height), 4, image.tobytes(), dtype="f4")
    texture.use(location=ctx.default_texture_unit)  # moderngl's own unit: no sampler's binding is disturbed
    gl_extras().define_levels(4, mip_chain(image)[1:] if levels is None else levels)
    return texture


def rgba(image: np.ndarray) -> np.ndarray:
    """A float32 (h, w, c) image as (h, w, 4), contiguous: grey as grey, grey-alpha as grey with
    its alpha, RGB with alpha 1, more channels than four cut to four."""
    channels = image.shape[2]
    if channels == 1:
        image = np.concatenate([np.repeat(image, 3, axis=2), np.ones_like(image)], axis=2)
    elif channels == 2:
        image = np.concatenate([np.repeat(image[..., :1], 3, axis=2), image[..., 1:2]], axis=2)
    elif channels == 3:
        image = opaque(image)
    return np.ascontiguousarray(image[..., :4], "f4")


def opaque(rgb: np.ndarray) -> np.ndarray:
    """An (h, w, 3) image as (h, w, 4), alpha 1."""
    return np.concatenate([rgb, np.ones_like(rgb[..., :1])], axis=2)


def power_of_two(image: np.ndarray) -> np.ndarray:
    """`image` resampled so that each side is the power of two nearest it in ratio (640 texels
    become 512, 768 become 1024: at most 1.41 times more or fewer), as real-time engines import
    textures: llvmpipe compiles a program's machine code apart for power-of-two and other sides of
    a bound texture, so a library thumbnail of a known topology whose file had the other kind of
    side than the first one's cost ~1.8 s to compile again. The filter is a cubic (_cubic_resample),
    not mip_chain's linear one: detail near the file's own texel frequency would otherwise beat
    through the mip levels (1-texel stripes 60 -> 64 wide: level 1 between 0.47 and 0.94 where the
    file's own chain is 0.5 grey, within 0.05 of it with the cubic). The result stays within each
    channel's range in the file, which the cubic's small negative lobes would leave."""
    height, width = image.shape[:2]
    sides = (_nearest_power_of_two(height), _nearest_power_of_two(width))
    if sides == (height, width):
        return image
    resampled = _cubic_resample(_cubic_resample(image, sides[0], 0), sides[1], 1)
    return np.clip(resampled, image.min(axis=(0, 1)), image.max(axis=(0, 1)))


def _nearest_power_of_two(side: int) -> int:
    below = 1 << (side.bit_length() - 1)
    return 2 * below if side * side >= 2 * below * below else below


def _cubic_resample(image: np.ndarray, size: int, axis: int) -> np.ndarray:
    """`image` at `size` texels spanning the same extent along `axis`, filtered by _mitchell (its
    support widened by the ratio where the image shrinks), the edge texels repeated beyond it."""
    n = image.shape[axis]
    scale = min(1.0, size / n)
    support = 2.0 / scale
    centre = (np.arange(size) + 0.5) * n / size - 0.5  # each new texel's centre in the old texels
    first = np.floor(centre - support).astype(int) + 1
    taps = range(int(np.ceil(2 * support)))
    weights = np.stack([_mitchell((first + k - centre) * scale) for k in taps])
    weights = (weights / weights.sum(axis=0)).astype("f4")
    shape = [1] * image.ndim
    shape[axis] = size
    resampled = np.zeros(image.shape[:axis] + (size,) + image.shape[axis + 1:], "f4")
    for k in taps:
        resampled += np.take(image, np.clip(first + k, 0, n - 1), axis=axis) * weights[k].reshape(shape)
    return resampled


def _mitchell(x: np.ndarray) -> np.ndarray:
    """Mitchell and Netravali's cubic with B = C = 1/3 ("Reconstruction Filters in Computer
    Graphics", SIGGRAPH 1988): little ringing, little blur; its weights sum to one at any phase."""
    x = np.abs(x)
    inner = (7 * x ** 3 - 12 * x ** 2 + 16 / 3) / 6
    outer = (-7 / 3 * x ** 3 + 12 * x ** 2 - 20 * x + 32 / 3) / 6
    return np.where(x < 1, inner, np.where(x < 2, outer, 0.0))


def mip_chain(image: np.ndarray) -> list[np.ndarray]:
    """Level 0 and every smaller level down to 1 x 1, each side halved (rounded down), each texel
    the bilinear sample of the level above at its centre: the 2 x 2 average where the side is
    even, as GL's mipmap generation gives."""
    levels = [image]
    while max(levels[-1].shape[:2]) > 1:
        above = levels[-1]
        h, w = (max(1, n // 2) for n in above.shape[:2])
        levels.append(_resample(_resample(above, h, 0), w, 1))
    return levels


def _resample(image: np.ndarray, size: int, axis: int) -> np.ndarray:
    """Linear interpolation along `axis` at the centres of `size` texels spanning the same extent."""
    n = image.shape[axis]
    if n == size:
        return image
    centre = (np.arange(size) + 0.5) * n / size - 0.5
    low = np.clip(np.floor(centre).astype(int), 0, n - 1)
    high = np.clip(low + 1, 0, n - 1)
    weight = (centre - np.floor(centre)).astype("f4")
    shape = [1] * image.ndim
    shape[axis] = size
    weight = weight.reshape(shape)
    return np.take(image, low, axis=axis) * (1 - weight) + np.take(image, high, axis=axis) * weight


def lut_image(entry: dict) -> np.ndarray:
    """A record's LUT (an entry of its `luts`: a colour transform's table, cms/ocio.py) as a
    float32 (h, w, c) image, first row first."""
    values = np.frombuffer(base64.b64decode(entry["data"]), "<f4")
    return values.reshape(int(entry["height"]), int(entry["width"]), int(entry["channels"]))


def lut_key(entry: dict) -> tuple:
    """What identifies a LUT's texture between renders (its description and texels)."""
    return tuple(sorted((k, str(v)) for k, v in entry.items()))


MAX_LUTS = 64  # colour transforms' LUT textures a renderer keeps between renders


def upload_lut(ctx, entry: dict):
    """A LUT as a GL texture sampled as OCIO's code expects: its own filter, no mipmaps (a table,
    not an image: a coarser level would blur it), clamped at the edges."""
    import moderngl

    image = lut_image(entry)
    if image.shape[2] == 3:
        image = opaque(image)
    texture = ctx.texture((image.shape[1], image.shape[0]), image.shape[2], np.ascontiguousarray(image).tobytes(),
                          dtype="f4")
    filtering = moderngl.LINEAR if entry.get("filter") == "linear" else moderngl.NEAREST
    texture.filter = (filtering, filtering)
    texture.repeat_x = texture.repeat_y = False
    return texture


def bind(texture, unit: int, sampling: Sampling) -> None:
    """Bind to a texture unit with the sampler state of `sampling` (set on every bind: one cached
    texture may be sampled differently by different materials)."""
    import moderngl

    if sampling.closest:
        texture.filter = (moderngl.NEAREST_MIPMAP_NEAREST if sampling.mipmaps else moderngl.NEAREST, moderngl.NEAREST)
    else:
        texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR if sampling.mipmaps else moderngl.LINEAR, moderngl.LINEAR)
    texture.use(location=unit)  # after `filter`, which binds on a unit of moderngl's own
    gl_extras().set_wrap(sampling.wrap_u, sampling.wrap_v, sampling.border)  # acts on the active unit
