"""One compiled program per topology: a record that differs only in values reuses the program of
the first, and the new values are bound from the listing (the pixels follow the value)."""
from shadergen.api import Generator
from shadergen.render import Renderer

GEN = Generator()


def red_material(red: float) -> str:
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <standard_surface name="SR_reuse" type="surfaceshader">
    <input name="base_color" type="color3" value="{red}, 0.2, 0.2" />
    <input name="specular" type="float" value="0" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_reuse" />
  </surfacematerial>
</materialx>"""


def mean_red(result) -> float:
    covered = result.rgba[..., 3] > 0.5
    return float(result.rgba[..., 0][covered].mean())


def test_a_value_change_reuses_the_program_and_binds_the_new_value(renderer):
    dark, bright = (GEN.prepare(red_material(red)).emit() for red in (0.1, 0.9))
    assert dark["stages"] == bright["stages"]
    first = renderer.render(dark, size=32)
    compiled = renderer.program_counts["compiled"]
    second = renderer.render(bright, size=32)
    assert second.program_reused and renderer.program_counts["compiled"] == compiled
    assert mean_red(second) > 2 * mean_red(first)
    again = renderer.render(dark, size=32)  # the reused program forgets the bright value
    assert again.program_reused and abs(mean_red(again) - mean_red(first)) < 1e-4


def test_without_program_reuse_every_render_compiles_and_draws_the_same():
    """max_programs=0 (the service's SHADERGEN_TOPOLOGY_SHARING=false): the baseline of bench/editing.py."""
    record = GEN.prepare(red_material(0.5)).emit()
    compiling = Renderer(max_programs=0)
    first, second = (compiling.render(record, size=32) for _ in range(2))
    assert not first.program_reused and not second.program_reused
    assert compiling.program_counts == {"compiled": 2, "reused": 0}
    assert abs(mean_red(second) - mean_red(first)) < 1e-6
