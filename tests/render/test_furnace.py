"""A fast subset of bench/stress.py: a few materials per BSDF and per shading model drawn by our
renderer in a white furnace (radiance 1 everywhere). Energy conservation: nothing returns more
than 1 (+1 %); no NaN, Inf or negative pixel anywhere, even for inputs at their edges."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
import stress  # noqa: E402  (the benchmark's document builder and furnace statistics)

FURNACE_CASES = (
    "diel_r0.5_ior1_RT", "diel_r1_ior1.5_RT", "diel_aniso_ior3_T", "diel_r0_ior0_RT", "diel_r1e-6_film3000_ior1.5",
    "cond_r1_zero_film0", "cond_aniso_n100_film0", "cond_r0.5_gold_film500",
    "gs_r1_white_RT", "gs_aniso_white_R", "gs_r0.5_film500_exp0",
    "on_r1_qon_c1", "on_r1_eon_c1", "burley_r1_c1", "sheen_r0_conty_kulla", "sheen_r0.5_zeltner",
    "sss_radius0", "hair_r0.5", "layer_coat_r1", "layer_sheen_r0.5",
    "ss_m1_r1_t0_c1_ior1.5", "ss_film500_aniso0.8_sheen1", "opbr_m0_r1_t1_c1_ior3",
)
EDGE_WEIGHTS = ("dielectric_w10", "conductor_w-1", "sheen_w10")
# an ior or roughness a graph computes (a divide node giving NaN, +-Inf or -1 at run time)
GRAPH_VALUES = (
    "graph_dielectric_bsdf_ior_nan", "graph_dielectric_bsdf_roughness_inf", "graph_dielectric_bsdf_thinfilm_ior_-inf",
    "graph_conductor_bsdf_ior_inf", "graph_conductor_bsdf_extinction_nan", "graph_chiang_hair_bsdf_ior_inf",
    "graph_sheen_bsdf_roughness_nan", "graph_oren_nayar_diffuse_bsdf_roughness_-inf",
    "graph_standard_surface_specular_IOR_inf", "graph_standard_surface_coat_IOR_neg", "graph_open_pbr_surface_coat_ior_nan",
)


RIG = Path(__file__).parent / "data" / "rig.mtlx"


@pytest.fixture(scope="module")
def records():
    wanted = set(FURNACE_CASES) | set(EDGE_WEIGHTS) | set(GRAPH_VALUES)
    chosen = [c for c in stress.cases() if c.name in wanted]
    assert {c.name for c in chosen} == wanted
    return chosen, stress.our_records(chosen)


@pytest.fixture(scope="module")
def furnace(renderer, records):
    chosen, by_name = records
    return {c: stress.render_records(renderer, {c.name: by_name[c.name]}, 32, 32, stress.white_furnace())[c.name]
            for c in chosen}


def test_white_furnace_returns_at_most_what_arrives(furnace):
    over = {case.name: stats.get("p999") for case, stats in furnace.items()
            if case.plausible and not stats.get("p999", 0.0) <= stress.LIMIT}
    assert not over


def test_no_nan_inf_or_negative_pixels_at_the_edges(furnace):
    bad = {case.name: stats for case, stats in furnace.items()
           if "nan" not in stats or stats["nan"] or stats["negative"]}
    assert not bad


def test_a_lossless_dielectric_keeps_most_of_the_light(furnace):
    """Reflection plus refraction of a clear interface: as close to 1 as the model allows."""
    stats = next(s for c, s in furnace.items() if c.name == "diel_r1_ior1.5_RT")
    assert stats["p999"] > 0.9


def test_lights_at_the_edges_make_no_nan_inf_or_negative_pixels(renderer, records):
    """The same materials under a light rig: the REFLECTION context of every closure."""
    chosen, by_name = records
    bad = {}
    for case in chosen:
        rgba = renderer.render(stress.without_initialisers(by_name[case.name]), size=32, env_samples=8, lights=str(RIG)).rgba
        stats = stress.furnace_stats(rgba)
        if stats["nan"] or stats["negative"]:
            bad[case.name] = stats
    assert not bad
