"""The ground-truth scene (tools/ground_truth_scene.py) rendered by OSL's testrender at low
resolution against answers known without a path tracer: a white furnace, a mirror sphere, and our
GL thumbnail of a diffuse material (the camera, field of view and environment orientation)."""
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.required_tools import missing, require_renderer

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import ground_truth_scene as gts  # noqa: E402

DIFFUSE = '''<?xml version="1.0"?>
<materialx version="1.39">
  <oren_nayar_diffuse_bsdf name="diffuse" type="BSDF"><input name="color" type="color3" value="0.8, 0.8, 0.8"/></oren_nayar_diffuse_bsdf>
  <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="diffuse"/></surface>
  <surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>
</materialx>
'''


@pytest.fixture(scope="module")
def world():
    for name in ("oslc", "testrender"):
        if gts.tool(name) is None:
            missing(name, "scripts/osl.sh builds it")
    from shadergen.render.environment import Environment

    scene = gts.Scene(radiance=Environment.procedural().radiance)
    yield scene
    scene.close()


@pytest.mark.parametrize("albedo", [1.0, 0.5])
def test_white_furnace(world, albedo):
    """A Lambertian sphere of albedo a in a constant environment of radiance 1 is a everywhere
    (away from the silhouette, where testrender's pixel filter blends it with the environment)."""
    image = world.render("white_lambert", 16, 16, constant=1.0, surface_params={"albedo": f"color {albedo} {albedo} {albedo}"})
    sphere = image[gts.sphere_mask(16, 2.0)]
    np.testing.assert_allclose(sphere.mean(axis=0), albedo, rtol=0.01)
    background = image[~gts.sphere_mask(16, -2.0)]  # the environment itself, seen past the sphere
    np.testing.assert_allclose(background, 1.0, rtol=1e-3)


def test_mirror_shows_the_environment(world):
    side = 32
    image = world.render("mirror", side, 4)
    direct = gts.mirror_image(world.radiance, side)
    assert gts.psnr_viewed(image, direct, gts.sphere_mask(side, 2.0)) > 33.0


def test_orientation_matches_our_thumbnail(world):
    """Our GL image of Oren-Nayar 0.8 against testrender's of the same closure: close as drawn,
    far when the ground truth is mirrored or turned upside down."""
    require_renderer()
    from shadergen.api import Generator
    from shadergen.render import Renderer

    side = 32
    mean = gts.pixel_mean(world.render("white_lambert", 2 * side, 64, surface_params={"albedo": "color 0.8 0.8 0.8"}))
    ours = Renderer(confined=False).render(Generator().prepare(DIFFUSE).emit(), size=side, env_samples=256).rgba
    mask = gts.sphere_mask(side, 2.0)
    as_drawn = gts.psnr_viewed(ours, mean, mask)
    assert as_drawn > 30.0
    assert as_drawn - gts.psnr_viewed(ours, mean[:, ::-1], mask) > 10.0
    assert as_drawn - gts.psnr_viewed(ours, mean[::-1], mask) > 10.0


def test_noise_estimated_from_a_quarter_of_the_samples(world):
    """The mirror sphere (the map's detail inside every pixel, noise from the pixel filter's jitter
    only): the noise of a render estimated against the same pixels at a quarter of the samples is
    near its error against a render of 64 times its samples (within 2 dB above, 12 below: the
    scrambled sequence converges faster than independent samples), where two of the four pixels
    of a block differ by the detail between them (their PSNR 32 and 35 dB, flat)."""
    side = 16
    mask = gts.sphere_mask(side, 2.0)
    means = {aa: gts.pixel_mean(world.render("mirror", 2 * side, aa * aa)) for aa in (2, 4, 8, 32)}
    for coarse, fine in ((2, 4), (4, 8)):
        error = gts.psnr_viewed(means[fine], means[32], mask)
        estimate = gts.nested_noise_psnr(means[coarse], means[fine], mask)
        assert error - 12.0 < estimate < error + 2.0, (fine, estimate, error)


def test_a_material_shaders_closure_output_is_the_surface(world):
    """A material shader (as the OSL target writes one: its closure an output parameter, no Ci)
    drawn through render_material gives what the same closure as Ci gives."""
    source = "shader material(output closure color result = 0)\n{\n    result = oren_nayar_diffuse_bsdf(N, color(0.5), 0.0);\n}\n"
    assert world.add_surface(source, "material_probe") is None
    output = world.closure_output("material_probe")
    assert output == "result"
    layered = world.render_material("material_probe", output, 16, 16)
    direct = world.render("white_lambert", 16, 16, surface_params={"albedo": "color 0.5 0.5 0.5"})
    mask = gts.sphere_mask(16)
    assert layered[mask].mean() > 0.05
    np.testing.assert_allclose(layered, direct, atol=1e-6)


def test_build_time_is_read_beside_the_cache_bin(tmp_path, monkeypatch):
    """scripts/osl.sh writes build-time.txt at the cache folder's top, testrender lies in its bin/."""
    (tmp_path / "bin").mkdir()
    program = tmp_path / "bin" / "testrender"
    program.write_text("")
    monkeypatch.setattr(gts, "testrender", lambda: str(program))
    assert gts.build_time().startswith("not recorded")
    (tmp_path / "build-time.txt").write_text("osl: built in 428 s at -j2 on 2 cores, 2026-12-02\n")
    assert gts.build_time() == "osl: built in 428 s at -j2 on 2 cores, 2026-12-02"


@pytest.mark.parametrize("absorption", [0.0, 0.7])
def test_glass_sphere_series_in_a_constant_environment(absorption):
    """The directly computed glass sphere in radiance 1: F + (1 - F)^2 t / (1 - F t) with t the
    chord's transmittance (1 without a medium: a lossless sphere returns all the light)."""
    side = 24
    image = gts.glass_sphere_image(np.ones((16, 32, 3)), side, 1.5, (absorption,) * 3, internal=200)
    mask = gts.sphere_mask(side)
    d, n = gts.camera_rays(side)[mask], gts.sphere_normals(side)[mask]
    cosine = np.clip(-(d * n).sum(-1), 0.0, 1.0)
    f = gts.fresnel_dielectric(cosine, 1.5)
    t = np.exp(-absorption * 2.0 * np.sqrt(1.0 - (1.0 - cosine ** 2) / 2.25))
    expected = f + (1.0 - f) ** 2 * t / (1.0 - f * t)
    np.testing.assert_allclose(image[mask][:, 0], expected, atol=1e-6)
    if absorption == 0.0:
        np.testing.assert_allclose(image[mask], 1.0, atol=1e-6)


def test_fresnel_dielectric_known_values():
    assert gts.fresnel_dielectric(np.array(1.0), 1.5) == pytest.approx(0.04)
    assert gts.fresnel_dielectric(np.array(0.0), 1.5) == pytest.approx(1.0)
    assert gts.fresnel_dielectric(np.array(0.5), 1.0 / 1.5) == 1.0  # beyond the critical angle


def test_our_absorbing_glass_sphere_against_the_sphere_computed_directly():
    """OpenPBR glass holding an amber medium (transmission_color at depth 1) drawn by our GL
    thumbnail against every internal path of the same sphere: our media take the transmittance
    along the refracted chord, not over a unit distance (which was 20 dB from it, too yellow)."""
    require_renderer()
    sys.path.insert(0, str(ROOT / "bench"))
    import ground_truth
    from shadergen.api import Generator
    from shadergen.render import Renderer
    from shadergen.render.environment import Environment

    side, amber = 64, (0.9, 0.55, 0.15)
    document = ground_truth.GLASS_CHECK.format(color=", ".join(map(str, amber)), depth="1")
    ours = Renderer(search_paths=[]).render(Generator().prepare(document).emit(), size=side, env_samples=64).rgba[..., :3]
    exact = gts.glass_sphere_image(Environment.procedural().radiance, side, 1.5, -np.log(np.asarray(amber)))
    assert gts.psnr_viewed(ours, exact, gts.sphere_mask(side, 2.0)) > 33.0


def test_a_truth_short_of_convergence_is_converged_on_from_its_cache(world, tmp_path):
    """bench/ground_truth.py's cache: a truth stopped by --max-samples before --converged-db is
    picked up by a later run with more samples, which renders only the next count (its first
    quarter is the cached render) and gives the very image a fresh run at that count gives."""
    sys.path.insert(0, str(ROOT / "bench"))
    import ground_truth
    from types import SimpleNamespace

    side, counts = 8, []

    def render(s, samples):
        counts.append(samples)
        return world.render("mirror", s, samples)

    def args(cache, max_samples):
        return SimpleNamespace(cache=str(cache), start_samples=4, max_samples=max_samples, converged_db=200.0)

    short = ground_truth.cached_truth("mirror", render, side, args(tmp_path / "a", 4))
    assert (short["samples"], short["cached"], counts) == (16, False, [1, 4])
    again = ground_truth.cached_truth("mirror", render, side, args(tmp_path / "a", 4))
    assert again["cached"] and counts == [1, 4]  # converged as far as asked: read, not rendered
    counts.clear()
    resumed = ground_truth.cached_truth("mirror", render, side, args(tmp_path / "a", 16))
    assert (resumed["samples"], resumed["cached"], counts) == (64, False, [16])
    fresh = ground_truth.cached_truth("mirror", render, side, args(tmp_path / "b", 16))
    assert np.array_equal(resumed["rgb"], fresh["rgb"]) and resumed["noise_db"] == fresh["noise_db"]
