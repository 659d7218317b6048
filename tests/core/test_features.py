"""Generation-time features of the libraries (shadergen/features.py): sections a shader keeps only
when one of its nodes can take them, resolved on the IR before any target prints the library's
code (shadergen/code/passes/sections.py)."""
import pytest

from shadergen.code import ir
from shadergen.code.parse import parse_module
from shadergen.code.passes import sections
from shadergen.errors import ShaderGenError
from shadergen.targets.glsl.printer import GlslPrinter

from .conftest import checked_code, doc, glslang, material, needs_glslang

CALLED = "".join(f"void {name}() {{}}\n" for name in ("a", "prefiltered", "sampled", "notA", "notB"))
SECTIONS = CALLED + """#pragma shadergen feature A unless x == 0
float f()
{
#ifdef MX_FEATURE_A
    a();
#ifdef MX_ENV_PREFILTER
    prefiltered();
#else
    sampled();
#endif
#else
    notA();
#endif
#ifndef MX_FEATURE_B
    notB();
#endif
    return 0.0;
}"""


def resolve(source: str, features: frozenset | None, macros: frozenset = frozenset()) -> str:
    """The last function of `source` with its sections resolved, printed as GLSL."""
    items, _ = checked_code(source, "")
    resolved, _ = sections.run(items, features, macros)
    function = [i for i in resolved if isinstance(i, ir.Function)][-1]
    return "\n".join(GlslPrinter().item(function))


def test_a_needed_section_stays_without_its_directives_and_the_compilers_own_conditionals_stay():
    out = resolve(SECTIONS, frozenset({"A", "B"}))
    assert "a();" in out and "notA();" not in out and "notB();" not in out
    assert "#ifdef MX_ENV_PREFILTER" in out and "sampled();" in out and "#endif" in out
    assert "MX_FEATURE" not in out and "#pragma" not in out


def test_a_section_no_node_needs_is_dropped_with_what_it_holds_and_its_else_side_stays():
    out = resolve(SECTIONS, frozenset())
    assert "notA();" in out and "notB();" in out
    assert "a();" not in out.replace("notA();", "") and "MX_ENV_PREFILTER" not in out and "sampled();" not in out


def test_an_unasked_stage_keeps_every_section():
    out = resolve(SECTIONS, None)
    assert "a();" in out and "prefiltered();" in out and "notB();" not in out


def test_the_sections_resolved_are_counted():
    items, _ = checked_code(SECTIONS, "")
    assert sections.run(items, frozenset({"A", "B"}))[1] == 2  # MX_FEATURE_A, MX_FEATURE_B; MX_ENV_PREFILTER stays
    assert sections.run(items, frozenset(), frozenset({("MX_ENV_PREFILTER", True)}))[1] == 2  # A's holds the other
    assert sections.run(items, frozenset({"A"}), frozenset({("MX_ENV_PREFILTER", True)}))[1] == 3


def test_elif_in_a_feature_section_is_refused():
    with pytest.raises(ShaderGenError) as error:
        parse_module("library.glsl", "#ifdef MX_FEATURE_A\n#elif X\n#endif")
    assert error.value.code == "invalid_source" and "library.glsl:2:" in error.value.message


def pixel(gen, document: str, **kw) -> str:
    return gen.prepare(document, **kw).emit()["stages"]["pixel"]


DIELECTRIC = '<dielectric_bsdf name="b" type="BSDF"><input name="thinfilm_thickness" type="float" value="{t}"/>' \
             '<input name="ior" type="float" value="{ior}"/><input name="scatter_mode" type="string" value="{mode}"/>' \
             '</dielectric_bsdf>'


@needs_glslang
def test_a_film_of_thickness_0_leaves_the_thin_film_out_of_specialized_code_and_it_still_compiles(gen):
    plain = pixel(gen, material(DIELECTRIC.format(t=0, ior=1.5, mode="R")), interface="specialized")
    assert "mx_fresnel_airy" not in plain and "mx_fresnel_dielectric(" in plain
    assert "mx_fresnel_conductor" not in plain and "mx_fresnel_f82" not in plain  # no closure of those models
    assert "mx_refraction_solid_sphere" not in plain and "MX_ALBEDO_DIELECTRIC_LEAVING" not in plain
    assert glslang(plain, "pixel")[0]
    film = pixel(gen, material(DIELECTRIC.format(t=500, ior=1.5, mode="R")), interface="specialized")
    assert "mx_fresnel_airy(" in film and glslang(film, "pixel")[0]


def test_every_target_resolves_the_same_sections(gen):
    """The sections are resolved on the IR that every target prints: ESSL and WGSL lose the thin
    film as GLSL does, with the same count."""
    for thickness in (0, 500):
        records = {t: gen.prepare(material(DIELECTRIC.format(t=thickness, ior=1.5, mode="R")), target=t,
                                  interface="specialized").emit() for t in ("glsl", "essl", "wgsl")}
        assert len({r["passes"]["sections"] for r in records.values()}) == 1
        for r in records.values():
            assert ("mx_fresnel_airy(" in r["stages"]["pixel"]) is (thickness > 0)
            assert "MX_FEATURE" not in r["stages"]["pixel"]


def test_each_setting_brings_back_its_section(gen):
    refracting = pixel(gen, material(DIELECTRIC.format(t=0, ior=1.5, mode="RT")), interface="specialized")
    assert "mx_surface_transmission(" in refracting and "mx_refraction_solid_sphere(" in refracting
    leaving = pixel(gen, material(DIELECTRIC.format(t=0, ior=0.7, mode="R")), interface="specialized")
    assert "MX_ALBEDO_DIELECTRIC_LEAVING" in leaving


def test_complete_and_kept_inputs_keep_every_section_their_uniform_can_reach(gen):
    document = material(DIELECTRIC.format(t=0, ior=1.5, mode="R"))
    complete = pixel(gen, document)
    assert all(name in complete for name in ("mx_fresnel_airy(", "MX_ALBEDO_DIELECTRIC_LEAVING"))
    assert "MX_FEATURE" not in complete and "#pragma" not in complete
    kept = pixel(gen, document, interface="specialized", keep=["b/thinfilm_thickness"])
    assert "mx_fresnel_airy(" in kept and "MX_ALBEDO_DIELECTRIC_LEAVING" not in kept


def test_smooth_diffuse_is_lambert_and_rough_diffuse_brings_its_models(gen):
    diffuse = '<oren_nayar_diffuse_bsdf name="b" type="BSDF"><input name="roughness" type="float" value="{r}"/>' \
              '</oren_nayar_diffuse_bsdf>'
    smooth = pixel(gen, material(diffuse.format(r=0)), interface="specialized")
    assert "mx_oren_nayar(" not in smooth and "MX_ALBEDO_OREN_NAYAR" not in smooth and "mx_eon" not in smooth
    rough = pixel(gen, material(diffuse.format(r=0.5)), interface="specialized")
    assert "mx_oren_nayar(" in rough and "mx_eon(" in rough


def test_an_environment_method_resolves_the_compilers_own_conditional(gen):
    document = material('<conductor_bsdf name="b" type="BSDF"/>')
    both = gen.prepare(document, interface="specialized").emit()
    fis = gen.prepare(document, interface="specialized", environment="fis").emit()
    prefilter = gen.prepare(document, interface="specialized", environment="prefilter").emit()
    assert "#ifdef MX_ENV_PREFILTER" in both["stages"]["pixel"] and "environment" not in both
    assert "#ifdef MX_ENV_PREFILTER" not in fis["stages"]["pixel"] and "MX_DFG_C1" not in fis["stages"]["pixel"]
    assert "mx_ggx_sample_visible_normal" in fis["stages"]["pixel"] and fis["environment"] == "fis"
    assert "MX_DFG_C1" in prefilter["stages"]["pixel"] and "mx_ggx_sample_visible_normal" not in prefilter["stages"]["pixel"]
    hybrid = gen.prepare(document, interface="specialized", environment="hybrid").emit()
    assert "#ifdef MX_ENV_" not in hybrid["stages"]["pixel"] + prefilter["stages"]["pixel"]
    assert "mx_environment_corrected_radiance(" in hybrid["stages"]["pixel"] and "MX_DFG_C1" in hybrid["stages"]["pixel"]
    assert "mx_environment_corrected_radiance(" not in prefilter["stages"]["pixel"] + fis["stages"]["pixel"]
    assert "#ifdef MX_ENV_HYBRID" in both["stages"]["pixel"] and hybrid["environment"] == "hybrid"
    assert len({both["hash"], fis["hash"], prefilter["hash"], hybrid["hash"]}) == 4
    with pytest.raises(ShaderGenError) as error:
        gen.prepare(document, environment="pathtrace")
    assert error.value.code == "unsupported_environment"


def test_decided_macros_resolve_like_features():
    text = CALLED + "void g()\n{\n#ifdef MX_ENV_PREFILTER\n    prefiltered();\n#else\n    sampled();\n#endif\n}"
    assert resolve(text, frozenset(), frozenset({("MX_ENV_PREFILTER", False)})) == "void g()\n{\n    sampled();\n}"
    assert resolve(text, frozenset(), frozenset({("MX_ENV_PREFILTER", True)})) == "void g()\n{\n    prefiltered();\n}"


def test_a_shader_for_a_scene_without_lights_has_no_light_loop(gen):
    document = material('<conductor_bsdf name="b" type="BSDF"/>')
    lit = gen.prepare(document).emit()
    unlit = gen.prepare(document, lights=False).emit()
    assert "numActiveLightSources" in lit["stages"]["pixel"] and "lights" not in lit
    assert "numActiveLightSources" not in unlit["stages"]["pixel"] and "u_lightData" not in unlit["stages"]["pixel"]
    assert unlit["lights"] is False and "CLOSURE_TYPE_INDIRECT, L" in unlit["stages"]["pixel"]
    assert lit["topology_hash"] != unlit["topology_hash"]


BSDFS = ('<sheen_bsdf name="sheen" type="BSDF"/><conductor_bsdf name="metal" type="BSDF"/>'
         '<generalized_schlick_bsdf name="schlick" type="BSDF"/><oren_nayar_diffuse_bsdf name="diffuse" type="BSDF"/>'
         '<layer name="top" type="BSDF"><input name="top" type="BSDF" nodename="sheen"/>'
         '<input name="base" type="BSDF" nodename="schlick"/></layer>'
         '<mix name="m1" type="BSDF"><input name="fg" type="BSDF" nodename="top"/>'
         '<input name="bg" type="BSDF" nodename="metal"/><input name="mix" type="float" value="0.5"/></mix>'
         '<layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="m1"/>'
         '<input name="base" type="BSDF" nodename="diffuse"/></layer>')


@needs_glslang
def test_a_shader_for_a_scene_without_lights_has_none_of_the_closures_code_for_lights(gen):
    lit = gen.prepare(material(BSDFS), interface="complete").emit()
    unlit = gen.prepare(material(BSDFS), interface="complete", lights=False).emit()
    source = unlit["stages"]["pixel"]
    assert "u_numActiveLightSources" in lit["stages"]["pixel"] and "lights" not in lit
    assert unlit["lights"] is False and unlit["hash"] != lit["hash"]
    # the sheen's lamp branch (its albedo towards L) goes; its lobe stays, which the environment
    # term samples (mx_sheen_environment)
    assert "albedoL" in lit["stages"]["pixel"] and "mx_sheen_environment" in source
    for light_code in ("u_numActiveLightSources", "u_lightData", "sampleLightSource", "LightData",
                       "mx_specular_reflection", "albedoL", "CLOSURE_TYPE_REFLECTION)\n",
                       "MX_FEATURE_LIGHTS"):
        assert light_code not in source, light_code
    names = {v["name"] for block in unlit["blocks"]["pixel"].values() for v in block}
    assert not {"u_numActiveLightSources", "u_lightData"} & names
    assert source.count("\n") < lit["stages"]["pixel"].count("\n")
    ok, log = glslang(source, "pixel")
    assert ok, log


def test_the_transmission_context_code_is_kept_only_for_surfaces_that_write_that_context(gen):
    opaque = pixel(gen, material(DIELECTRIC.format(t=0, ior=1.5, mode="R")), interface="specialized")
    clear = pixel(gen, material(DIELECTRIC.format(t=0, ior=1.5, mode="RT")), interface="specialized")
    assert "CLOSURE_TYPE_TRANSMISSION, L, V, N, P" not in opaque and "mx_specular_transmission_albedo" not in opaque
    assert "CLOSURE_TYPE_TRANSMISSION, L, V, N, P" in clear and "mx_specular_transmission_albedo(closureData" in clear


@needs_glslang
def test_retro_reflection_brings_its_own_samples_of_the_view_through_the_layer_only_where_it_can_be_set(gen):
    lobe = '<dielectric_bsdf name="b" type="BSDF"><input name="retroreflective" type="boolean" value="{r}"/>' \
           '<input name="scatter_mode" type="string" value="RT"/></dielectric_bsdf>'  # a transmission context
    folded = pixel(gen, material(lobe.format(r="false")), interface="specialized")
    retro = pixel(gen, material(lobe.format(r="true")), interface="specialized")
    live = pixel(gen, material(lobe.format(r="false")))  # a uniform in complete: either way at run time
    shading_model = pixel(gen, doc('<standard_surface name="s" type="surfaceshader"/><surfacematerial name="mat" '
                                   'type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/>'
                                   '</surfacematerial>'))  # its lobes' flags are constants of its nodegraph
    assert "if (lobe.retroreflective)" not in folded and "if (lobe.retroreflective)" not in shading_model
    assert "if (lobe.retroreflective)" in retro and "if (lobe.retroreflective)" in live
    assert glslang(shading_model, "pixel")[0] and glslang(retro, "pixel")[0]
