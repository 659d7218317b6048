"""Image-based lighting: a lat-long radiance map and its irradiance map, as MaterialX's GLSL
lighting reads them (u_envRadiance, u_envIrradiance, u_envMatrix, u_envLightIntensity).

Map convention (MaterialX's mx_latlong_projection): texel (u, v), v = 0 the top row, holds the
radiance arriving along map direction m = (cos(lat) sin(lon), sin(lat), -cos(lat) cos(lon)) with
lat = (0.5 - v) pi and lon = (u - 0.5) 2 pi; the shader turns a world direction into a map
direction with u_envMatrix. The irradiance map holds irradiance / pi, so that a Lambert lobe of
albedo a reflects a * texel.

The procedural sky and computed irradiance maps are kept on disk (the cache folder), named by what
they are computed from, so that a thumbnail process reads them instead of computing them.
"""
import io
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..digest import sha256
from .errors import RenderError
from .imageio import read_image

# MaterialX's default u_envMatrix, a half turn about +Y (symmetric, so it is its own inverse).
ENV_MATRIX = np.diag([-1.0, 1.0, -1.0, 1.0])
SKY_SIZE = (256, 512)         # rows, columns of the procedural sky
IRRADIANCE_SIZE = (128, 256)  # rows, columns of a computed irradiance map
SH_ROWS = 256                 # radiance maps are box-filtered to at most this many rows before projection


@dataclass
class Environment:
    radiance: np.ndarray    # float32 (h, w, 3) lat-long
    irradiance: np.ndarray  # float32 (h, w, 3) lat-long, irradiance / pi
    key: str                # identifies the maps, for caching their GL textures
    intensity: float = 1.0  # u_envLightIntensity

    @classmethod
    def procedural(cls, intensity: float = 1.0) -> "Environment":
        radiance = computed("procedural-sky", procedural_sky)
        irradiance = computed("procedural-sky-irradiance", lambda: sh_irradiance(radiance))
        return cls(radiance, irradiance, "procedural-sky", intensity)

    @classmethod
    def load(cls, radiance_path: str, irradiance_path: str | None = None, intensity: float = 1.0) -> "Environment":
        """From lat-long files (.hdr, .exr, anything OpenImageIO reads); the irradiance map is
        computed from the radiance map when not given."""
        radiance = _read_map(radiance_path)
        stamp = [f"{os.path.abspath(p)}@{os.stat(p).st_mtime_ns}" for p in (radiance_path, irradiance_path) if p]
        irradiance = _read_map(irradiance_path) if irradiance_path \
            else computed(f"irradiance of {stamp[0]}", lambda: sh_irradiance(radiance))
        return cls(radiance, irradiance, "|".join(stamp), intensity)

    @property
    def radiance_mips(self) -> int:
        """u_envRadianceMips: the number of levels of the radiance map's full mip chain."""
        return int(np.floor(np.log2(max(self.radiance.shape[:2])))) + 1


def computed(name: str, compute) -> np.ndarray:
    """The float32 map `compute()` returns, read from the cache folder when an earlier process kept
    it: the file is named by `name` and this module's source (a change to how maps are computed
    is never served from an old file). A cache that cannot be read or written is computed past."""
    from shadergen.library import cache_dir, write_atomically  # the generator's cache, imported only here

    digest = sha256(Path(__file__).read_bytes() + name.encode()).hexdigest()[:24]
    path = os.path.join(cache_dir(), "environments", f"{digest}.npy")
    try:
        return np.load(path)
    except (OSError, ValueError, EOFError):
        pass  # missing or corrupt (an empty file is an EOFError): computed again
    image = np.ascontiguousarray(compute(), "f4")
    file = io.BytesIO()
    np.save(file, image)
    try:
        write_atomically(path, file.getvalue())
    except OSError:
        pass
    return image


def _read_map(path: str) -> np.ndarray:
    try:
        image = read_image(path)
    except RenderError as exc:
        if exc.code in ("too_large", "invalid_setting"):  # the renderer's limit or setting, not the file's fault
            raise
        raise RenderError("invalid_environment", exc.message, path) from exc
    if image.shape[2] < 3:  # a grey map lights in grey
        image = np.repeat(image[..., :1], 3, axis=2)
    return np.ascontiguousarray(image[..., :3], "f4")


def map_directions(rows: int, columns: int) -> tuple[np.ndarray, np.ndarray]:
    """Map-space unit direction (rows, columns, 3) and latitude (rows, columns) of texel centres."""
    v = (np.arange(rows) + 0.5) / rows
    u = (np.arange(columns) + 0.5) / columns
    lat = (0.5 - v)[:, None] * np.pi + np.zeros((1, columns))
    lon = (u - 0.5)[None, :] * 2.0 * np.pi + np.zeros((rows, 1))
    direction = np.stack([np.cos(lat) * np.sin(lon), np.sin(lat), -np.cos(lat) * np.cos(lon)], -1)
    return direction, lat


def procedural_sky(sun_direction=(0.55, 0.6, 0.58), rows: int = SKY_SIZE[0], columns: int = SKY_SIZE[1]) -> np.ndarray:
    """A clear sky over a dark ground with a sun up and to the right, behind the viewer (world
    space: the camera looks down -Z), so a ball is lit from the front right with a visible
    highlight. Radiances are chosen so that the sun gives about as much irradiance as the sky."""
    map_dir, _ = map_directions(rows, columns)
    world = map_dir @ ENV_MATRIX[:3, :3]  # row vectors: inverse(M) @ m, and M is orthogonal and symmetric
    elevation = world[..., 1:2]
    zenith, horizon = np.array([0.20, 0.36, 0.80]), np.array([0.80, 0.85, 0.92])
    ground_far, ground_near = np.array([0.30, 0.28, 0.25]), np.array([0.12, 0.11, 0.10])
    up = np.clip(elevation, 0.0, 1.0) ** 0.4
    down = np.clip(-elevation * 3.0, 0.0, 1.0)
    radiance = np.where(elevation >= 0.0, horizon + (zenith - horizon) * up, ground_far + (ground_near - ground_far) * down)
    sun = np.asarray(sun_direction, "f8") / np.linalg.norm(sun_direction)
    angle = np.degrees(np.arccos(np.clip(world @ sun, -1.0, 1.0)))[..., None]
    disc = np.clip((2.5 - angle) / 0.5 + 0.5, 0.0, 1.0)  # 2.5 degree radius, edge blended over a texel
    glow = np.exp(-angle / 6.0)
    sun_colour = np.array([1.0, 0.92, 0.80])
    radiance = radiance + sun_colour * (250.0 * disc + 1.5 * glow)
    return radiance.astype("f4")


def _sh9_basis(d: np.ndarray) -> np.ndarray:
    """The nine real spherical harmonics of bands 0-2 at unit directions d (..., 3)."""
    x, y, z = d[..., 0], d[..., 1], d[..., 2]
    return np.stack([np.full_like(x, 0.282095), 0.488603 * y, 0.488603 * z, 0.488603 * x,
                     1.092548 * x * y, 1.092548 * y * z, 0.315392 * (3.0 * z * z - 1.0),
                     1.092548 * x * z, 0.546274 * (x * x - y * y)], -1)


# Cosine-lobe convolution per band (Ramamoorthi and Hanrahan 2001): pi, 2pi/3, pi/4.
_BAND_SCALE = np.array([np.pi] + [2.0 * np.pi / 3.0] * 3 + [np.pi / 4.0] * 5)


def sh_irradiance(radiance: np.ndarray, rows: int = IRRADIANCE_SIZE[0], columns: int = IRRADIANCE_SIZE[1]) -> np.ndarray:
    """Irradiance / pi lat-long map of a radiance lat-long map, through its order-2 spherical
    harmonic projection (exact for irradiance up to about 3 %, and cheap)."""
    radiance = _box_reduce(np.asarray(radiance, "f8")[..., :3], SH_ROWS)
    h, w = radiance.shape[:2]
    direction, lat = map_directions(h, w)
    solid_angle = (np.pi / h) * (2.0 * np.pi / w) * np.cos(lat)
    coefficients = _sh9_basis(direction).reshape(-1, 9).T @ (radiance * solid_angle[..., None]).reshape(-1, 3)
    out_direction, _ = map_directions(rows, columns)
    irradiance = _sh9_basis(out_direction) @ (coefficients * _BAND_SCALE[:, None]) / np.pi
    return np.maximum(irradiance, 0.0).astype("f4")


def _box_reduce(image: np.ndarray, max_rows: int) -> np.ndarray:
    """Average blocks of texels (keeping the integral) until the map has at most max_rows rows."""
    factor = 1
    while image.shape[0] // factor > max_rows and image.shape[0] % (factor * 2) == 0 and image.shape[1] % (factor * 2) == 0:
        factor *= 2
    if factor == 1:
        return image
    h, w, c = image.shape
    return image.reshape(h // factor, factor, w // factor, factor, c).mean(axis=(1, 3))
