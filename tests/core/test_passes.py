"""The passes of shadergen/passes/, each on small graphs, by what they fold, remove and keep."""
import os
import re
import subprocess
import sys

import pytest

from shadergen.code import ir
from shadergen.code.facts import early_exit_at_zero_weight
from shadergen.evaluate import NotFoldable, evaluate_outputs, f32

from .conftest import checked_code, doc, library_implementation


def record(gen, body, **kw):
    # document names: the checks read the code by the document's node names
    return gen.prepare(doc(body), **{"names": "document", **kw}).emit()


def main_of(rec) -> str:
    src = rec["stages"]["pixel"]
    return src[src.index("void main()"):]


def public_paths(rec) -> set:
    return {v["path"] for v in rec["blocks"]["pixel"]["PublicUniforms"]}


OUT = '<output name="o" type="{t}" nodename="{n}"/>'


# -- evaluate.py -------------------------------------------------------------------------------------
def test_evaluation_rounds_to_float32_and_gives_the_shortest_literal():
    value = evaluate_outputs("multiply", {"in1": 0.1, "in2": 3.0}, [("out", "float")])["out"]
    assert f32(value) == f32(0.1 * 3.0) and value == 0.3
    assert evaluate_outputs("add", {"in1": (1.0, 2.0, 3.0), "in2": 0.5}, [("out", "color3")]) == {"out": (1.5, 2.5, 3.5)}
    assert evaluate_outputs("convert", {"in": (0.25, 0.5, 1.0)}, [("out", "color4")])["out"] == (0.25, 0.5, 1.0, 1.0)
    assert evaluate_outputs("separate3", {"in": (1.0, 2.0, 3.0)},
                            [("outr", "float"), ("outg", "float"), ("outb", "float")]) == {"outr": 1.0, "outg": 2.0, "outb": 3.0}
    assert evaluate_outputs("ifgreater", {"value1": 2.0, "value2": 1.0, "in1": 5.0, "in2": 6.0},
                            [("out", "float")])["out"] == 5.0
    assert evaluate_outputs("switch", {"which": 1.5, "in1": 1.0, "in2": 2.0}, [("out", "float")])["out"] == 2.0


def test_the_pbr_parameter_conversions_evaluate_as_the_library_computes_them():
    alpha = evaluate_outputs("roughness_anisotropy", {"roughness": 0.5, "anisotropy": 0.0}, [("out", "vector2")])["out"]
    assert alpha == (0.25, 0.25)
    stretched = evaluate_outputs("roughness_anisotropy", {"roughness": 0.5, "anisotropy": 0.5},
                                 [("out", "vector2")])["out"]
    assert stretched[0] == pytest.approx(0.25 / 0.5 ** 0.5, rel=1e-6) and stretched[1] == pytest.approx(0.25 * 0.5 ** 0.5, rel=1e-6)
    assert evaluate_outputs("roughness_dual", {"roughness": (0.5, -1.0)}, [("out", "vector2")])["out"] == (0.25, 0.25)
    reflectivity, edge = (0.9, 0.5, 0.2), (0.1, 0.6, 1.0)
    nk = evaluate_outputs("artistic_ior", {"reflectivity": reflectivity, "edge_color": edge},
                          [("ior", "color3"), ("extinction", "color3")])
    for r, n, k in zip(reflectivity, nk["ior"], nk["extinction"]):
        # Gulbrandsen's (n, k) reflect exactly the reflectivity at normal incidence, whatever the edge tint
        assert ((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2) == pytest.approx(r, rel=1e-5)


def test_compositing_guards_give_what_the_library_gives():
    """compositing_impl.mtlx selects the guard's value where a division would be by (near) zero."""
    def one(category, **inputs):
        return evaluate_outputs(category, inputs, [("out", "color4" if category in ("unpremult", "disjointover") else "float")])["out"]
    assert one("burn", fg=0.0, bg=0.5, mix=0.5) == 0.0 and one("dodge", fg=1.0, bg=0.5, mix=0.5) == 0.0
    assert one("burn", fg=0.5, bg=0.5, mix=1.0) == 0.0 and one("dodge", fg=0.5, bg=0.25, mix=1.0) == 0.5
    assert one("unpremult", **{"in": (1.0, 0.5, 0.25, 0.0)}) == (1.0, 0.5, 0.25, 0.0)
    assert one("unpremult", **{"in": (1.0, 0.5, 0.25, 0.5)}) == (2.0, 1.0, 0.5, 0.5)
    # coverage over one with a transparent background: black, and alpha one
    assert one("disjointover", fg=(0.5, 0.5, 0.5, 1.5), bg=(1.0, 1.0, 1.0, 0.0), mix=1.0) == (0.0, 0.0, 0.0, 1.0)
    assert one("disjointover", fg=(0.5, 0.5, 0.5, 0.75), bg=(1.0, 1.0, 1.0, 0.5), mix=1.0) == (1.0, 1.0, 1.0, 1.0)


@pytest.mark.parametrize("category,inputs", [
    ("divide", {"in1": 1.0, "in2": 0.0}),  # infinity: no literal holds it
    ("sqrt", {"in": -1.0}),
    ("noise3d", {"amplitude": 1.0}),  # not computable here
])
def test_what_cannot_be_computed_is_not_folded(category, inputs):
    with pytest.raises(NotFoldable):
        evaluate_outputs(category, inputs, [("out", "float")])


def test_round_folds_as_the_library_rounds_a_tie_to_even():
    values = (0.4, 0.6, -1.7, 0.5, -0.5, 1.5, -2.5)
    assert [evaluate_outputs("round", {"in": x}, [("out", "float")])["out"] for x in values] == [
        0.0, 1.0, -2.0, 0.0, 0.0, 2.0, -2.0]


# -- fold ----------------------------------------------------------------------------------------------
def test_constant_math_folds_into_its_reader_in_specialized(gen):
    body = ('<add name="a" type="float"><input name="in1" type="float" value="0.25"/>'
            '<input name="in2" type="float" value="0.5"/></add>'
            '<position name="p" type="vector3"/><multiply name="m" type="vector3">'
            '<input name="in1" type="vector3" nodename="p"/><input name="in2" type="float" nodename="a"/></multiply>'
            + OUT.format(t="vector3", n="m"))
    specialized = record(gen, body, interface="specialized")
    assert "vec3 m_out = p_out * 0.75;" in main_of(specialized)
    assert "a_out" not in specialized["stages"]["pixel"]
    assert specialized["passes"]["fold"] == 1 and specialized["blocks"]["pixel"]["PublicUniforms"] == []
    complete = record(gen, body)
    assert "a_out" in main_of(complete) and complete["passes"]["fold"] == 0  # every input is live


@pytest.mark.parametrize("category", ["burn", "dodge"])
def test_a_guarded_blend_at_mix_zero_is_its_bg_only_where_fg_misses_the_guard(gen, category):
    """burn and dodge give 0 where fg would divide by zero, whatever the mix: with fg live (read
    from the position), mix 0 must not let bg stand for the node; with a constant fg clear of the
    guard it does."""
    def body(fg):
        return ('<position name="p" type="vector3"/><extract name="x" type="float">'
                '<input name="in" type="vector3" nodename="p"/><input name="index" type="integer" value="0"/></extract>'
                f'<{category} name="b" type="float">{fg}<input name="bg" type="float" nodename="x"/>'
                f'<input name="mix" type="float" value="0"/></{category}>' + OUT.format(t="float", n="b"))
    live = main_of(record(gen, body('<input name="fg" type="float" nodename="x"/>'), interface="specialized"))
    assert "b_out" in live and "1.0e-8" in live
    clear = main_of(record(gen, body('<input name="fg" type="float" value="0.5"/>'), interface="specialized"))
    assert "1.0e-8" not in clear


def test_a_constant_node_driving_the_output_becomes_its_value(gen):
    """Left unfolded it would be an expression of literals alone, computed for every pixel (and in
    WGSL abstract-typed, which only constant expressions may be)."""
    body = ('<mix name="m" type="float"><input name="fg" type="float" value="1"/><input name="bg" type="float" value="0"/>'
            '<input name="mix" type="float" value="0.25"/></mix>' + OUT.format(t="float", n="m"))
    specialized = record(gen, body, interface="specialized")
    assert "float m_out = 0.25;" in main_of(specialized) and specialized["passes"]["fold"] == 1
    wgsl = record(gen, body, interface="specialized", target="wgsl")["stages"]["pixel"]
    assert "var m_out: f32 = 0.25;" in wgsl
    assert "m_out = mix(" in main_of(record(gen, body))  # complete: its inputs are live


@pytest.mark.parametrize("node,gone", [
    ('<multiply name="m" type="vector3"><input name="in1" type="vector3" nodename="p"/>'
     '<input name="in2" type="vector3" value="1, 1, 1"/></multiply>', "m_out"),
    ('<add name="m" type="vector3"><input name="in1" type="vector3" value="0, 0, 0"/>'
     '<input name="in2" type="vector3" nodename="p"/></add>', "m_out"),
    ('<mix name="m" type="vector3"><input name="fg" type="vector3" value="1, 0, 0"/>'
     '<input name="bg" type="vector3" nodename="p"/><input name="mix" type="float" value="0"/></mix>', "m_out"),
    ('<ifgreater name="m" type="vector3"><input name="value1" type="float" value="1"/>'
     '<input name="value2" type="float" value="0"/><input name="in1" type="vector3" nodename="p"/>'
     '<input name="in2" type="vector3" value="0, 0, 1"/></ifgreater>', "m_out"),
    ('<switch name="m" type="vector3"><input name="which" type="float" value="1"/>'
     '<input name="in1" type="vector3" value="0, 0, 1"/><input name="in2" type="vector3" nodename="p"/></switch>', "m_out"),
    ('<rotate3d name="m" type="vector3"><input name="in" type="vector3" nodename="p"/>'
     '<input name="amount" type="float" value="0"/><input name="axis" type="vector3" value="0, 1, 0"/></rotate3d>', "m_out"),
])
def test_identities_let_the_live_input_stand_for_the_node(gen, node, gone):
    body = ('<position name="p" type="vector3"/>' + node
            + '<normalize name="n" type="vector3"><input name="in" type="vector3" nodename="m"/></normalize>'
            + OUT.format(t="vector3", n="n"))
    rec = record(gen, body, interface="specialized")
    assert gone not in rec["stages"]["pixel"]
    assert "vec3 n_out = normalize(p_out);" in main_of(rec)
    assert rec["passes"]["fold"] == 1


def test_times_zero_is_the_zero_of_the_type(gen):
    body = ('<position name="p" type="vector3"/><multiply name="m" type="vector3">'
            '<input name="in1" type="vector3" nodename="p"/><input name="in2" type="float" value="0"/></multiply>'
            '<cos name="c" type="vector3"><input name="in" type="vector3" nodename="m"/></cos>' + OUT.format(t="vector3", n="c"))
    rec = record(gen, body, interface="specialized")
    # cos of that zero is a constant too: cos(0) in every component
    assert "vec3 c_out = vec3(1.0, 1.0, 1.0);" in main_of(rec) and "p_out" not in rec["stages"]["pixel"]


# -- closures ------------------------------------------------------------------------------------------
def surface(bsdf: str, edf: str = "") -> str:
    edf_input = '<input name="edf" type="EDF" nodename="e"/>' if edf else ""
    return (bsdf + edf + '<surface name="srf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="top"/>'
            + edf_input + '</surface><surfacematerial name="mat" type="material">'
            '<input name="surfaceshader" type="surfaceshader" nodename="srf"/></surfacematerial>')


def lobe(name: str, category: str, weight: str, extra: str = "") -> str:
    return f'<{category} name="{name}" type="BSDF"><input name="weight" type="float" value="{weight}"/>{extra}</{category}>'


DIFFUSE = lobe("diffuse", "oren_nayar_diffuse_bsdf", "1")
COAT_OFF = lobe("coat", "dielectric_bsdf", "0")
LAYER = ('<layer name="top" type="BSDF"><input name="top" type="BSDF" nodename="coat"/>'
         '<input name="base" type="BSDF" nodename="diffuse"/></layer>')


def test_a_zero_weight_lobe_is_removed_and_its_layer_is_the_base(gen):
    body = surface(COAT_OFF + DIFFUSE + LAYER)
    specialized = main_of(record(gen, body, interface="specialized"))
    assert "mx_dielectric_bsdf(" not in specialized and "mx_layer_bsdf(" not in specialized
    assert "mx_oren_nayar_diffuse_bsdf(" in specialized
    assert "mx_dielectric_bsdf(" in main_of(record(gen, body))  # complete: the weight is a live uniform


def test_a_layer_with_a_removed_base_is_its_top(gen):
    coat = lobe("coat", "dielectric_bsdf", "1")
    body = surface(coat + lobe("diffuse", "sheen_bsdf", "0") + LAYER)
    main = main_of(record(gen, body, interface="specialized"))
    assert "mx_layer_bsdf(" not in main and "mx_sheen_bsdf(" not in main and "mx_dielectric_bsdf(" in main


def test_add_of_a_removed_operand_is_the_other(gen):
    body = surface(COAT_OFF + DIFFUSE + '<add name="top" type="BSDF"><input name="in1" type="BSDF" nodename="coat"/>'
                   '<input name="in2" type="BSDF" nodename="diffuse"/></add>')
    rec = record(gen, body, interface="specialized")
    assert "mx_add_bsdf(" not in main_of(rec) and rec["passes"]["prune_closures"] == 2


@pytest.mark.parametrize("weight,kept,dropped", [("0", "mx_oren_nayar_diffuse_bsdf(", "mx_sheen_bsdf("),
                                                  ("1", "mx_sheen_bsdf(", "mx_oren_nayar_diffuse_bsdf(")])
def test_mix_at_zero_or_one_keeps_one_side(gen, weight, kept, dropped):
    body = surface(DIFFUSE + lobe("sheen", "sheen_bsdf", "1")
                   + f'<mix name="top" type="BSDF"><input name="fg" type="BSDF" nodename="sheen"/>'
                   f'<input name="bg" type="BSDF" nodename="diffuse"/><input name="mix" type="float" value="{weight}"/></mix>')
    main = main_of(record(gen, body, interface="specialized"))
    assert kept in main and dropped not in main and "mx_mix_bsdf(" not in main


def test_multiply_of_a_removed_closure_is_removed_and_by_one_is_the_closure(gen):
    scaled = ('<multiply name="top" type="BSDF"><input name="in1" type="BSDF" nodename="coat"/>'
              '<input name="in2" type="float" value="{w}"/></multiply>')
    removed = record(gen, surface(COAT_OFF + scaled.format(w="0.5")), interface="specialized")
    assert "BSDF" not in main_of(removed) and "CLOSURE_TYPE" not in main_of(removed)
    kept = main_of(record(gen, surface(lobe("coat", "dielectric_bsdf", "1") + scaled.format(w="1")), interface="specialized"))
    assert "mx_multiply_bsdf" not in kept and "mx_dielectric_bsdf(" in kept


def test_transmission_context_only_with_a_transmitting_lobe(gen):
    def main(mode):
        glass = lobe("top", "dielectric_bsdf", "1", f'<input name="scatter_mode" type="string" value="{mode}"/>')
        return main_of(record(gen, surface(glass), interface="specialized"))
    assert "CLOSURE_TYPE_TRANSMISSION" not in main("R")
    assert "CLOSURE_TYPE_TRANSMISSION" in main("RT")
    assert "CLOSURE_TYPE_TRANSMISSION" not in main_of(record(gen, surface(lobe("top", "oren_nayar_diffuse_bsdf", "1"))))
    # what a lobe answers, read from its IR: whether it (or what it calls) reads the context's constant
    assert library_implementation("ND_dielectric_bsdf").handles_transmission
    assert not library_implementation("ND_oren_nayar_diffuse_bsdf").handles_transmission


def test_no_emission_code_without_an_emitter(gen):
    emitter = '<uniform_edf name="e" type="EDF"><input name="color" type="color3" value="{c}"/></uniform_edf>'
    diffuse = lobe("top", "oren_nayar_diffuse_bsdf", "1")
    assert "CLOSURE_TYPE_EMISSION" not in main_of(record(gen, surface(diffuse)))
    assert "CLOSURE_TYPE_EMISSION" not in main_of(record(gen, surface(diffuse, emitter.format(c="0, 0, 0")),
                                                         interface="specialized"))
    assert "CLOSURE_TYPE_EMISSION" in main_of(record(gen, surface(diffuse, emitter.format(c="1, 0, 0")),
                                                     interface="specialized"))


LOBE_TYPES = "struct ClosureData { int closureType; };\nstruct BSDF { vec3 response; vec3 throughput; };\n" \
             "const float MX_EPS = 1.0e-8;\n"


def test_the_closure_facts_read_what_a_lobe_gives_at_zero_weight():
    """Read from the lobe's IR (code/facts.py): a return under its weight before any throughput is
    written leaves the closure's zero; a lobe that marks itself opaque first does not."""
    empty = "void f(ClosureData c, float weight, inout BSDF bsdf)\n{\n    if (weight < MX_EPS)\n        return;\n" \
            "    bsdf.throughput = vec3(0.5);\n}\n"
    opaque = "void f(ClosureData c, float weight, inout BSDF bsdf)\n{\n    bsdf.throughput = vec3(0.0);\n" \
             "    if (weight < MX_EPS)\n        return;\n}\n"

    def lobe_function(source):
        items, _ = checked_code(LOBE_TYPES + source, "")
        return next(i for i in items if isinstance(i, ir.Function) and i.name == "f")

    assert early_exit_at_zero_weight(lobe_function(empty)) and not early_exit_at_zero_weight(lobe_function(opaque))
    assert library_implementation("ND_sheen_bsdf").empty_at_zero_weight
    assert not library_implementation("ND_burley_diffuse_bsdf").empty_at_zero_weight


def test_an_opaque_lobe_at_zero_weight_is_kept_where_its_throughput_is_seen(gen):
    opaque = lobe("coat", "burley_diffuse_bsdf", "0")
    body = surface(opaque + lobe("diffuse", "sheen_bsdf", "1") + LAYER)
    assert not library_implementation("ND_burley_diffuse_bsdf").empty_at_zero_weight  # marks itself opaque first
    assert "mx_burley_diffuse_bsdf(" in main_of(record(gen, body, interface="specialized"))


# -- thin_film -------------------------------------------------------------------------------------
def film(name: str, base: str | None, thickness: str = "400") -> str:
    link = f'<input name="base" type="BSDF" nodename="{base}"/>' if base else ""
    return (f'<thinfilmbxdf name="{name}" type="BSDF"><input name="thickness" type="float" value="{thickness}"/>'
            f'<input name="ior" type="float" value="1.3"/>{link}</thinfilmbxdf>')


def lobe_calls(rec, function: str) -> list[str]:
    """The calls that set a lobe up: its parameters are passed once per shading point."""
    # one line each, however the printer wrapped the argument list
    calls = [" ".join(c.split()) for c in re.findall(rf"{function}_prepare\(\w+, [^;]*;", main_of(rec))]
    assert calls, f"no {function} in the shader"
    return calls


def test_a_film_reaches_every_microfacet_lobe_under_it_and_disappears(gen):
    coat, metal = lobe("coat", "dielectric_bsdf", "1"), lobe("metal", "conductor_bsdf", "1")
    under = ('<mix name="under" type="BSDF"><input name="fg" type="BSDF" nodename="metal"/>'
             '<input name="bg" type="BSDF" nodename="diffuse"/><input name="mix" type="float" value="0.5"/></mix>'
             '<layer name="stack" type="BSDF"><input name="top" type="BSDF" nodename="coat"/>'
             '<input name="base" type="BSDF" nodename="under"/></layer>')
    rec = record(gen, surface(coat + metal + DIFFUSE + under + film("top", "stack")))
    assert "error" not in rec, rec.get("error")
    assert rec["passes"]["thin_film"] == 2 and not rec["warnings"]
    # complete: the film's thickness is one uniform both lobes read; theirs are no uniforms any more
    assert {"top/thickness", "top/ior"} <= public_paths(rec)
    assert not {"coat/thinfilm_thickness", "metal/thinfilm_thickness"} & public_paths(rec)
    for function in ("mx_dielectric_bsdf", "mx_conductor_bsdf"):
        assert all("top_thickness, top_ior" in call for call in lobe_calls(rec, function))
    specialized = record(gen, surface(coat + metal + DIFFUSE + under + film("top", "stack")), interface="specialized")
    assert all(", 400.0, 1.3, " in call for call in lobe_calls(specialized, "mx_dielectric_bsdf"))


def test_the_film_nearest_a_lobe_wins(gen):
    own = lobe("coat", "dielectric_bsdf", "1", '<input name="thinfilm_thickness" type="float" value="250"/>')
    body = (own + lobe("metal", "conductor_bsdf", "1") + film("inner", "metal", "700")
            + '<add name="both" type="BSDF"><input name="in1" type="BSDF" nodename="coat"/>'
              '<input name="in2" type="BSDF" nodename="inner"/></add>' + film("top", "both"))
    rec = record(gen, surface(body), interface="specialized")
    assert rec["passes"]["thin_film"] == 1  # the conductor, from the inner film; the coat keeps its own
    assert all(", 250.0, 1.5, " in call for call in lobe_calls(rec, "mx_dielectric_bsdf"))
    assert all(", 700.0, 1.3, " in call for call in lobe_calls(rec, "mx_conductor_bsdf"))
    assert any("top" in w and "no microfacet lobe" in w for w in rec["warnings"])


def test_a_film_without_a_base_scatters_nothing(gen):
    rec = record(gen, surface(film("top", None)), interface="specialized")
    assert "error" not in rec and "CLOSURE_TYPE" not in main_of(rec)
    assert any("no base BSDF" in w for w in rec["warnings"])


# -- thin_surface ----------------------------------------------------------------------------------
@pytest.mark.parametrize("sides,shared", [(("frontbsdf",), 1), (("backbsdf",), 1), (("frontbsdf", "backbsdf"), 0)])
def test_one_connected_bsdf_serves_both_sides_of_a_thin_surface(gen, sides, shared):
    links = "".join(f'<input name="{s}" type="BSDF" nodename="diffuse"/>' for s in sides)
    rec = record(gen, DIFFUSE + f'<thinsurface name="srf" type="surfaceshader">{links}</thinsurface>'
                 '<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" '
                 'nodename="srf"/></surfacematerial>', interface="specialized")
    assert rec["passes"]["thin_surface"] == shared
    assert "mx_mix_bsdf(closureData, diffuse_out, diffuse_out, " in main_of(rec)  # back side, front side


# -- specialized, keep ---------------------------------------------------------------------------------
STANDARD = ('<standard_surface name="SR" type="surfaceshader"><input name="base_color" type="color3" value="0.2, 0.4, 0.8"/>'
            '<input name="coat" type="float" value="0"/></standard_surface>'
            '<surfacematerial name="M" type="material"><input name="surfaceshader" type="surfaceshader" nodename="SR"/>'
            '</surfacematerial>')


def test_keep_leaves_an_input_live_with_its_lobe(gen):
    plain = record(gen, STANDARD, interface="specialized")
    kept = record(gen, STANDARD, interface="specialized", keep=["SR/coat", "SR/base_color"])
    assert public_paths(plain) == set()
    assert public_paths(kept) == {"SR/coat", "SR/base_color"}
    assert "SR_coat" in main_of(kept)
    assert main_of(kept).count("mx_dielectric_bsdf(") > main_of(plain).count("mx_dielectric_bsdf(")
    assert plain["hash"] != kept["hash"]


def test_keep_naming_nothing_is_a_warning(gen):
    rec = record(gen, STANDARD, interface="specialized", keep=["SR/no_such_input"])
    assert any("SR/no_such_input" in w for w in rec["warnings"])


def test_specialized_is_smaller_and_emits_only_what_it_calls(gen):
    complete, specialized = record(gen, STANDARD), record(gen, STANDARD, interface="specialized")
    assert len(specialized["stages"]["pixel"]) < len(complete["stages"]["pixel"])
    for rec in (complete, specialized):
        src = rec["stages"]["pixel"]
        defined = set(re.findall(r"^\w+ (\w+)\(", src, re.M)) - {"main"}
        for name in defined:
            assert len(re.findall(rf"\b{name}\b", src)) > 1, f"{name} is defined but never called"
    assert "struct VDF" not in specialized["stages"]["pixel"]
    read = specialized["stages"]["pixel"]
    for block in ("PrivateUniforms", "PublicUniforms"):
        for v in specialized["blocks"]["pixel"][block]:
            assert len(re.findall(rf"\b{v['name']}\b", read)) > 1, f"uniform {v['name']} is never read"


# -- determinism ---------------------------------------------------------------------------------------
def test_generation_is_deterministic_across_processes(tmp_path):
    path = tmp_path / "m.mtlx"
    path.write_text(doc(STANDARD))
    script = ("import json, sys; from pathlib import Path; from shadergen.api import Generator; "
              "r = Generator().prepare(Path(sys.argv[1]), interface='specialized').emit(); "
              "print(json.dumps([r['hash'], r['stages'], r['blocks']]))")
    runs = [subprocess.run([sys.executable, "-c", script, str(path)], capture_output=True, text=True, check=True,
                           env=dict(os.environ, PYTHONHASHSEED=seed)).stdout for seed in ("1", "2")]
    assert runs[0] == runs[1] and runs[0]
