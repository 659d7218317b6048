"""The ground-truth scene: our thumbnail scene (shadergen/render/scene.py) as a scene of OSL's
`testrender`, a path tracer with its own implementation of MaterialX's closures.

Equal to the thumbnail scene: camera at scene.EYE looking at the origin, +Y up, vertical field of
view scene.FOV_Y_DEGREES, a square image; an analytic sphere of radius 1 at the origin (our
thumbnail's UV sphere is the unit sphere tessellated 128 x 64: the silhouette differs by under a
thousandth of the radius); the environment is infinitely distant light through an OSL background
shader reading the same lat-long map with our map convention (environment.py: the world direction
d reads the map direction ENV_MATRIX @ d), importance-sampled by testrender; no other light.

testrender 1.13 has spheres and quads, no meshes, and its sphere's (u, v) are not ours (its u =
0.5 at +Z where ours is 0; its v = 0 at the north pole where ours is 1). The texture coordinates a
material reads are the thumbnail sphere's instead (THUMBNAIL_U, THUMBNAIL_V): its parametrisation
(render/geometry.py, uv_sphere) computed from the shading point, as a mesh's primvar would carry
it; OSL differentiates the expression, so texture filtering sees the same footprint. World- and
object-space positions and normals are the same.

The image is rendered at twice the side and each 2 x 2 block averaged (pixel_mean): each pixel of
the render is testrender's tent filter of radius one of its pixels, so the truth's pixel is the area
under its footprint, as a supersampled thumbnail's is. Its noise is not the difference of two of
those four pixels: they integrate different parts of the footprint, and where the image has detail
inside a pixel (texture, edges) their expected values differ by it however many samples they take
(marble at 64 px: 30.6, 35.7, 37.6 dB at 16, 64, 256 samples each, against a detail floor near
39 dB). testrender's sampler (sampling.h, Sampler) is an Owen-scrambled sequence seeded by the
pixel's x, y and indexed by the sample: a render of aa x aa samples holds, as its first quarter,
the render of aa/2 x aa/2 of the same pixels, and the two differ by noise only (nested_noise_psnr).
"""
import hashlib
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from shadergen.render import scene  # noqa: E402
from shadergen.render.environment import ENV_MATRIX  # noqa: E402
from shadergen.targets.osl.check import tool  # noqa: E402

# Scene shaders (not materials): the lat-long environment and a constant one, as OSL background
# shaders, and the surfaces that check the scene against answers known without a path tracer.
SCENE_SHADERS = {
    "latlong_environment": """\
// The lat-long radiance map as light from infinitely far (environment.py's map convention).
shader latlong_environment(string filename = "", float intensity = 1,
                           vector env_matrix_diagonal = vector(-1, 1, -1))
{
    vector m = normalize(I) * env_matrix_diagonal;
    float lat = asin(clamp(m[1], -1.0, 1.0));
    float lon = atan2(m[0], -m[2]);
    float s = lon / M_2PI + 0.5;
    float t = 0.5 - lat / M_PI;
    color radiance = texture(filename, s, t, "swrap", "periodic", "twrap", "clamp", "interp", "bilinear");
    Ci = intensity * radiance * background();
}
""",
    "constant_environment": """\
// The same radiance from every direction (a white furnace).
shader constant_environment(color radiance = 1)
{
    Ci = radiance * background();
}
""",
    "white_lambert": """\
// A white Lambertian surface: in a white furnace it is exactly as bright as the environment.
surface white_lambert(color albedo = 1)
{
    Ci = oren_nayar_diffuse_bsdf(N, albedo, 0.0);
}
""",
    "closure_to_ci": """\
// A material shader's closure output (connected to `surface`) as the surface's Ci.
surface closure_to_ci(closure color surface = 0)
{
    Ci = surface;
}
""",
    "mirror": """\
// A perfect mirror: the environment reflected, known without a path tracer.
surface mirror()
{
    Ci = reflection(N);
}
""",
}
# The thumbnail sphere's texture coordinates at the shading point P of the unit sphere at the
# origin (render/geometry.py, uv_sphere): u the longitude from +Z towards +X over 2 pi, v the
# latitude from the south pole (0) to the north pole (1). What our OSL reads as its texcoord in
# this scene in place of OSL's globals u and v (bench/ground_truth.py, scene_form).
THUMBNAIL_U = "mod(atan2(P[0], P[2]) / M_2PI, 1.0)"
THUMBNAIL_V = "(asin(clamp(P[1] / length(P), -1.0, 1.0)) / M_PI + 0.5)"
# The thumbnail sphere's bitangent (N x T, towards the north pole) at the shading point. testrender's
# dPdu runs along the thumbnail's tangent (raytracer.h, Sphere::uv: u grows with atan2(x, z) too),
# but its v grows from the north pole southwards, so its dPdv points south: a normal map read with it
# tilts every normal the other way along v (standard_surface_brick_procedural's mortar grooves lit
# from below). What our OSL reads as its bitangent in place of dPdv (bench/ground_truth.py, scene_form).
THUMBNAIL_BITANGENT = "(-dPdv)"
ENV_DIAGONAL = tuple(float(ENV_MATRIX[i, i]) for i in range(3))
assert np.allclose(ENV_MATRIX[:3, :3], np.diag(ENV_DIAGONAL)), "the background shader assumes a diagonal u_envMatrix"


def testrender() -> str | None:
    return tool("testrender")


def build_time() -> str:
    """scripts/osl.sh's record of the cold build of the testrender in use, or why there is none."""
    path = testrender()
    record = os.path.join(os.path.dirname(os.path.dirname(os.path.realpath(path))), "build-time.txt") if path else ""
    try:
        with open(record, encoding="utf-8") as f:
            return f.read().strip()
    except OSError:
        return "not recorded (a cache built before scripts/osl.sh kept build-time.txt)"


def compile_osl(source: str, folder: str, name: str) -> str | None:
    """`source` compiled to `folder`/`name`.oso; None when it compiled, else oslc's message."""
    path = os.path.join(folder, f"{name}.osl")
    with open(path, "w", encoding="utf-8") as f:
        f.write(source)
    done = subprocess.run([tool("oslc"), "-q", "-o", os.path.join(folder, f"{name}.oso"), path],
                          capture_output=True, text=True, timeout=300)
    return None if done.returncode == 0 else (done.stdout + done.stderr).strip() or f"oslc exit {done.returncode}"


def write_map(radiance: np.ndarray, path: str) -> None:
    """A float lat-long map as an OpenEXR file testrender's texture system reads."""
    import OpenImageIO as oiio

    image = np.ascontiguousarray(radiance[..., :3], "f4")
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(image.shape[1], image.shape[0], 3, oiio.FLOAT))
    out.write_image(image)
    out.close()


def parameters(params: dict | None) -> str:
    """testrender's Parameter elements: values as its strings ("float 1", "color 1 1 1", a bare string)."""
    return "".join(f'<Parameter {name}="{value}"/>' for name, value in (params or {}).items())


def scene_xml(surface_group: str, background: str, background_params: dict, max_bounces: int = 16,
              background_resolution: int = 1024) -> str:
    """A testrender World: the thumbnail camera, the unit sphere with `surface_group` (the body of
    its ShaderGroup: Parameter, Shader and ConnectShaders elements of compiled shaders on the
    search path) and `background` lighting it."""
    eye, target, up = (", ".join(f"{c:g}" for c in v) for v in (scene.EYE, scene.TARGET, scene.UP))
    # testrender's image spans tan(fov / 2) / 2 either side of the centre (raytracer.h, Camera::get):
    # the field of view it is given is the one whose half tangent is twice ours
    fov = math.degrees(2.0 * math.atan(2.0 * math.tan(math.radians(scene.FOV_Y_DEGREES) / 2.0)))
    return f"""<World>
  <Option max_bounces="int {max_bounces}" rr_depth="int {max_bounces}"/>
  <Camera eye="{eye}" look_at="{target}" up="{up}" fov="{fov:.6f}"/>
  <ShaderGroup>{parameters(background_params)}<Shader name="{background}" layer="env"/></ShaderGroup>
  <Background resolution="{background_resolution}"/>
  <ShaderGroup>{surface_group}</ShaderGroup>
  <Sphere center="0, 0, 0" radius="1"/>
</World>
"""


def render(xml: str, folder: str, side: int, samples: int, timeout: float = 3600, cwd: str | None = None) -> np.ndarray:
    """testrender's float image of the scene `xml` (shaders searched in `folder`) at `side` x `side`
    with `samples` samples per pixel (rounded up to a square: testrender takes aa x aa); relative
    texture file names are read from `cwd` (default `folder`)."""
    scene_path = os.path.join(folder, "scene.xml")
    out = os.path.join(folder, "out.exr")
    with open(scene_path, "w", encoding="utf-8") as f:
        f.write(xml)
    aa = max(1, math.ceil(math.sqrt(samples)))
    done = subprocess.run(["nice", testrender(), "--path", folder, "-r", str(side), str(side), "-aa", str(aa),
                           scene_path, out], capture_output=True, text=True, timeout=timeout, cwd=cwd or folder)
    if done.returncode != 0 or not os.path.exists(out):
        raise RuntimeError(f"testrender failed ({done.returncode}): {(done.stdout + done.stderr).strip()[-2000:]}")
    from shadergen.render.imageio import read_image

    return read_image(out)[..., :3].astype("f8")


def pixel_mean(image: np.ndarray) -> np.ndarray:
    """A 2s x 2s render at s x s: the mean of each 2 x 2 block."""
    return (image[0::2, 0::2] + image[0::2, 1::2] + image[1::2, 0::2] + image[1::2, 1::2]) / 4.0


def nested_noise_psnr(coarse: np.ndarray, fine: np.ndarray, mask: np.ndarray) -> float:
    """The estimated noise of `fine`, as psnr_viewed against the image it estimates, from `coarse`:
    the same pixels rendered with a quarter of its samples (aa halved), which are its first quarter.
    With n samples of variance s2, fine = (coarse + 3 rest) / 4 and rest independent of coarse:
    Var(fine - coarse) = (9 / 16) (s2 / n + s2 / (3 n)) = 3 Var(fine), so the noise's PSNR is the
    two images' PSNR plus 10 log10(3). testrender's scrambled sequence mostly converges faster than
    independent samples (marble: the same pixels' PSNR grows 8.5 dB from 16 to 64 to 256 samples,
    not 6), where this overstates the noise: the white Lambertian's estimate at 64 samples was 3 dB
    under its error against 1024 samples, the mirror sphere's 11 dB under; at 16 samples the
    mirror's was 1.2 dB over it (tests/tools/test_ground_truth_scene.py)."""
    return psnr_viewed(coarse, fine, mask) + 10.0 * math.log10(3.0)


def psnr_viewed(x: np.ndarray, y: np.ndarray, mask: np.ndarray | None = None) -> float:
    """PSNR, peak 1, of the two images clipped to [0, 1] and sRGB-encoded (what a viewer sees),
    over `mask` (all pixels when None): bench/accuracy_time.py's measure."""
    from shadergen.render.imageio import srgb_encode

    x, y = (srgb_encode(np.clip(np.nan_to_num(v[..., :3]), 0.0, 1.0)) for v in (x, y))
    d = (x - y) if mask is None else (x - y)[mask]
    mse = float((d ** 2).mean())
    return float("inf") if mse == 0 else 10.0 * math.log10(1.0 / mse)


def sphere_mask(side: int, inset: float = 0.0) -> np.ndarray:
    """The pixels whose centre sees the unit sphere (exactly, by the camera's rays); `inset` pixels
    inside its silhouette with inset > 0 (pixels whose filter footprint holds no background, and
    which our tessellated sphere covers too)."""
    d = camera_rays(side)
    eye = np.asarray(scene.EYE, "f8")
    # distance of the ray from the centre, against the radius less `inset` pixels at the centre's depth
    closest = np.linalg.norm(np.cross(d, -eye), axis=-1)
    pixel = 2.0 * math.tan(math.radians(scene.FOV_Y_DEGREES) / 2.0) * np.linalg.norm(eye) / side
    return closest < 1.0 - inset * pixel


def camera_rays(side: int) -> np.ndarray:
    """Unit world direction through each pixel centre (row 0 the top), the thumbnail camera's."""
    k = math.tan(math.radians(scene.FOV_Y_DEGREES) / 2.0)
    c = (np.arange(side) + 0.5) / side * 2.0 - 1.0
    x, y = np.meshgrid(c * k, -c * k)
    view = scene.look_at(scene.EYE, scene.TARGET, scene.UP)
    d = np.stack([x, y, -np.ones_like(x)], -1) @ view[:3, :3]  # inverse(view) rotation on row vectors
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def mirror_image(radiance: np.ndarray, side: int) -> np.ndarray:
    """A perfect mirror sphere in the lat-long map, computed directly: each pixel centre's ray
    reflected off the unit sphere reads the map (nearest texel), background where it misses."""
    d = camera_rays(side)
    eye = np.asarray(scene.EYE, "f8")
    b = d @ eye
    disc = b * b - (eye @ eye - 1.0)
    hit = disc > 0
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    n = eye + t[..., None] * d
    r = d - 2.0 * (d * n).sum(-1, keepdims=True) * n
    direction = np.where(hit[..., None], r, d)
    return lookup(radiance, direction)


def fresnel_dielectric(cosine: np.ndarray, ior: float) -> np.ndarray:
    """Unpolarised Fresnel reflectance of light arriving at `cosine` from outside an interface of
    relative index `ior` (1 where it is totally reflected, for ior < 1)."""
    sin2_t = np.maximum(0.0, 1.0 - cosine * cosine) / (ior * ior)
    cos_t = np.sqrt(np.maximum(0.0, 1.0 - sin2_t))
    rs = (cosine - ior * cos_t) / (cosine + ior * cos_t)
    rp = (ior * cosine - cos_t) / (ior * cosine + cos_t)
    return np.where(sin2_t >= 1.0, 1.0, 0.5 * (rs * rs + rp * rp))


def _refract(d: np.ndarray, n: np.ndarray, eta: float) -> np.ndarray:
    """`d` refracted through the interface of normal `n` (against d), eta = n_from / n_to."""
    c = -(d * n).sum(-1, keepdims=True)
    return eta * d + (eta * c - np.sqrt(np.maximum(0.0, 1.0 - eta * eta * (1.0 - c * c)))) * n


def glass_sphere_image(radiance: np.ndarray, side: int, ior: float, absorption=(0.0, 0.0, 0.0),
                       internal: int = 16) -> np.ndarray:
    """A smooth dielectric unit sphere of index `ior` holding a medium of `absorption` (per unit
    length: -ln(transmission_color) / transmission_depth) in the lat-long map, computed directly at
    each pixel centre: the Fresnel reflection F env(r), and every path through the sphere,
    (1 - F)^2 F^k exp(-absorption L (k + 1)) env(exit_k) for k internal reflections. On a sphere
    every internal hit meets the surface at the refraction angle theta_t of the entry (so F is the
    same, by reciprocity, and nothing is totally reflected) and every chord is L = 2 cos(theta_t)."""
    d = camera_rays(side)
    hit = sphere_mask(side)
    n = np.where(hit[..., None], sphere_normals(side), -d)  # -d off the sphere: finite, then replaced
    cosine = np.clip(-(d * n).sum(-1), 0.0, 1.0)
    f = fresnel_dielectric(cosine, ior)[..., None]
    chord = 2.0 * np.sqrt(np.maximum(0.0, 1.0 - (1.0 - cosine * cosine) / (ior * ior)))[..., None]
    loss = np.exp(-np.asarray(absorption, "f8") * chord)
    image = f * lookup(radiance, d + 2.0 * cosine[..., None] * n)
    position, direction, weight = n, _refract(d, n, 1.0 / ior), (1.0 - f) * loss
    for _ in range(internal):
        position = position + chord * direction
        position /= np.linalg.norm(position, axis=-1, keepdims=True)  # rounding must not grow over the bounces
        image += weight * (1.0 - f) * lookup(radiance, _refract(direction, -position, ior))
        direction = direction - 2.0 * (direction * position).sum(-1, keepdims=True) * position
        weight = weight * f * loss
    return np.where(hit[..., None], image, lookup(radiance, d))


def sphere_normals(side: int) -> np.ndarray:
    """The unit sphere's normal at each pixel centre's hit (the far side's where the ray misses)."""
    d = camera_rays(side)
    eye = np.asarray(scene.EYE, "f8")
    b = d @ eye
    t = -b - np.sqrt(np.maximum(b * b - (eye @ eye - 1.0), 0.0))
    return eye + t[..., None] * d


def lambert_image(radiance: np.ndarray, side: int, albedo: float, rows: int = 64) -> np.ndarray:
    """A Lambertian sphere of `albedo` in the lat-long map, by direct quadrature of the irradiance
    over every texel of the map (box-reduced to `rows` rows, which keeps its integral): an answer
    independent of testrender's sampling and of our spherical-harmonic irradiance map."""
    from shadergen.render.environment import _box_reduce, map_directions

    radiance = _box_reduce(np.asarray(radiance, "f8")[..., :3], rows)
    h, w = radiance.shape[:2]
    map_dir, lat = map_directions(h, w)
    world = (map_dir * np.asarray(ENV_DIAGONAL)).reshape(-1, 3)  # the diagonal u_envMatrix is its own inverse
    solid_angle = ((np.pi / h) * (2.0 * np.pi / w) * np.cos(lat)).reshape(-1, 1)
    cosine = np.maximum(sphere_normals(side).reshape(-1, 3) @ world.T, 0.0)
    return (albedo / np.pi * cosine @ (radiance.reshape(-1, 3) * solid_angle)).reshape(side, side, 3)


def lookup(radiance: np.ndarray, direction: np.ndarray) -> np.ndarray:
    m = direction * np.asarray(ENV_DIAGONAL)
    lat = np.arcsin(np.clip(m[..., 1], -1.0, 1.0))
    lon = np.arctan2(m[..., 0], -m[..., 2])
    h, w = radiance.shape[:2]
    col = np.floor((lon / (2.0 * np.pi) + 0.5) * w).astype(int) % w
    row = np.clip(np.floor((0.5 - lat / np.pi) * h).astype(int), 0, h - 1)
    return radiance[row, col].astype("f8")


class Scene:
    """A folder holding the scene shaders compiled and the environment map written; renders
    surfaces (compiled .oso names in the folder) in it."""

    def __init__(self, folder: str | None = None, radiance: np.ndarray | None = None, intensity: float = 1.0):
        self._tmp = None if folder else tempfile.TemporaryDirectory(prefix="ground-truth-")
        self.folder = folder or self._tmp.name
        os.makedirs(self.folder, exist_ok=True)
        for name, source in SCENE_SHADERS.items():
            if (message := compile_osl(source, self.folder, name)) is not None:
                raise RuntimeError(f"scene shader {name}: {message}")
        self.intensity = intensity
        self.radiance = radiance
        self.map_path = None
        if radiance is not None:
            self.map_path = os.path.join(self.folder, "environment.exr")
            write_map(radiance, self.map_path)

    def environment(self, constant: float | None = None) -> tuple[str, dict]:
        if constant is not None:
            return "constant_environment", {"radiance": f"color {constant:g} {constant:g} {constant:g}"}
        diagonal = " ".join(f"{c:g}" for c in ENV_DIAGONAL)
        return "latlong_environment", {"filename": self.map_path, "intensity": f"float {self.intensity:g}",
                                       "env_matrix_diagonal": f"vector {diagonal}"}

    def add_surface(self, source: str, name: str) -> str | None:
        """Compiles a surface shader into the folder; None, or oslc's message."""
        return compile_osl(source, self.folder, name)

    def render(self, surface: str, side: int, samples: int, constant: float | None = None,
               surface_params: dict | None = None, max_bounces: int = 16) -> np.ndarray:
        group = f'{parameters(surface_params)}<Shader name="{surface}" layer="surface"/>'
        return render(scene_xml(group, *self.environment(constant), max_bounces), self.folder, side, samples)

    def closure_output(self, name: str) -> str | None:
        """The name of compiled shader `name`'s first closure output parameter (oslinfo)."""
        done = subprocess.run([tool("oslinfo"), "-v", os.path.join(self.folder, f"{name}.oso")],
                              capture_output=True, text=True, timeout=60)
        for line in done.stdout.splitlines():
            words = line.split()  # '"name" "output pointer"': oslinfo's spelling of an output closure
            if len(words) >= 3 and words[0].startswith('"') and words[1:3] in (['"output', 'pointer"'], ['"output', 'closure']):
                return words[0].strip('"')
        return None

    def render_material(self, material: str, output: str, side: int, samples: int, cwd: str | None = None) -> np.ndarray:
        """The sphere's surface a group of two layers: compiled shader `material`, its closure
        output parameter `output` connected to closure_to_ci's input."""
        return render(scene_xml(self.material_group(material, output), *self.environment()), self.folder, side,
                      samples, cwd=cwd)

    @staticmethod
    def material_group(material: str, output: str) -> str:
        return (f'<Shader name="{material}" layer="material"/><Shader name="closure_to_ci" layer="surface"/>'
                f'<ConnectShaders srclayer="material" srcparam="{output}" dstlayer="surface" dstparam="surface"/>')

    def close(self):
        if self._tmp:
            self._tmp.cleanup()


def digest(*parts: bytes | str) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else p.encode())
        h.update(b"\0")
    return h.hexdigest()[:24]
