"""The WGSL target: the libraries' typed IR printed as WGSL (targets/wgsl/printer.py), uniform
buffers laid out by WGSL's rules, and every generated module accepted by the validator: wgpu
creating the shader module (naga inside wgpu-native, on Mesa's Vulkan driver), as a WebGPU
implementation does."""
import pytest

from shadergen.code import ir
from shadergen.code.check import flat_items
from shadergen.errors import ShaderGenError
from shadergen.targets.wgsl.printer import WgslPrinter, function_names, helpers

from .conftest import checked_code, doc
from .test_stdlib_compiles import stdlib_nodedefs


@pytest.fixture(scope="session")
def validator():
    """name -> source => name -> message of every module the validator rejects."""
    from required_tools import require_wgpu
    return require_wgpu()


def test_every_generated_stdlib_nodedef_validates(gen, validator):
    nodedefs = stdlib_nodedefs()
    sources, not_generated = {}, []
    for nd in nodedefs:
        t = nd.children_of("output")[0].get("type")
        text = doc(f'<{nd.get("node")} name="n" type="{t}" nodedef="{nd.name}"/><output name="o" type="{t}" nodename="n"/>')
        try:
            rec = gen.prepare(text, target="wgsl").emit()
        except Exception as e:  # noqa: BLE001 - counted and reported below
            not_generated.append(f"{nd.name}: {e}")
            continue
        for stage, source in rec["stages"].items():
            sources[f"{nd.name}.{stage}"] = source
    generated = len(nodedefs) - len(not_generated)
    assert generated / len(nodedefs) >= 0.98, "\n".join(not_generated[:20])
    errors = validator(sources)
    assert not errors, f"{len(errors)} modules rejected:\n" + "\n".join(f"{k}: {v}" for k, v in list(errors.items())[:10])


@pytest.mark.parametrize("interface", ["complete", "reduced", "specialized"])
def test_interface_modes_validate(gen, validator, interface):
    text = doc('<nodegraph name="g"><position name="p" type="vector3"/>'
               '<multiply name="m" type="vector3"><input name="in1" type="vector3" nodename="p"/>'
               '<input name="in2" type="float" value="0.5"/></multiply>'
               '<clamp name="c" type="vector3"><input name="in" type="vector3" nodename="m"/></clamp>'
               '<output name="out" type="vector3" nodename="c"/></nodegraph>')
    rec = gen.prepare(text, target="wgsl", interface=interface).emit()
    assert "@fragment" in rec["stages"]["pixel"] and "@vertex" in rec["stages"]["vertex"]
    assert not validator(rec["stages"])
    public = {m["name"] for m in rec["layout"]["pixel"]["members"]}
    assert bool(public) == (interface == "complete")  # the others fold values that no interface exposes


def test_uniform_offsets_follow_wgsl_alignment(gen):
    text = doc('<nodegraph name="g">'
               '<add name="a" type="float"><input name="in1" type="float" value="1"/><input name="in2" type="float" value="2"/></add>'
               '<add name="b" type="color3"><input name="in1" type="color3" value="1,1,1"/>'
               '<input name="in2" type="float" nodename="a"/></add>'
               '<output name="out" type="color3" nodename="b"/></nodegraph>')
    rec = gen.prepare(text, target="wgsl").emit()
    members = {m["name"]: m for m in rec["layout"]["pixel"]["members"]}
    offsets = [(m["wgsl"], m["offset"]) for m in rec["layout"]["pixel"]["members"]]
    # f32 at 0 and 4, the vec3f aligned to 16
    assert offsets == [("f32", 0), ("f32", 4), ("vec3f", 16)], offsets
    assert rec["layout"]["pixel"]["size"] == 32
    for name in members:  # the same names as GLSL's listing, read through the buffer
        assert f"pu.{name}" in rec["stages"]["pixel"]


def translate(text: str) -> str:
    """GLSL-subset library source parsed and checked, its items printed as WGSL as the target
    prints a stage's (overloads named apart over all of them, the helpers they call after)."""
    items, _ = checked_code(text, "")
    printer = WgslPrinter(function_names([i for i in flat_items(items) if isinstance(i, ir.Function)]))
    return "\n".join([line for item in items for line in printer.item(item)] + helpers(items))


def test_out_parameters_become_pointers_and_overloads_get_suffixes():
    out = translate("float f(float x) { return x; }\nfloat f(vec2 x) { return x.x; }\n"
                    "void g(vec2 p, out float r) { r = f(p) + f(p.y); }")
    assert "fn f_float(x: f32) -> f32" in out and "fn f_vec2(x: vec2f) -> f32" in out
    assert "fn g(p: vec2f, r: ptr<function, f32>)" in out
    assert "*r = f_vec2(p) + f_float(p.y);" in out


def test_glsl_implicit_conversions_are_spelled_out():
    out = translate("vec3 h(vec3 c, int n, float x) { x = mod(x, 2.0); return clamp(c, 0.0, 1.0) * n + x; }")
    assert "clamp(c, vec3f(0.0), vec3f(1.0))" in out  # WGSL has no scalar bounds for a vector
    assert "f32(n)" in out  # nor int -> float conversions
    assert "var x: f32 = x__in;" in out  # nor writable parameters (a copy no uniform is named like)
    assert "floor(" in out  # GLSL's mod floors; WGSL's % truncates


def test_a_store_to_several_components_goes_through_a_copy():
    """WGSL assigns one component at a time (no `v.xy =`); through a pointer, `(*v).x`."""
    out = translate("void f(out vec3 v) { v.xy = vec2(1.0); }")
    assert "    let swizzled_0 = vec2f(1.0);\n    (*v).x = swizzled_0.x;\n    (*v).y = swizzled_0.y;" in out


def test_what_it_cannot_take_is_reported():
    with pytest.raises(ShaderGenError) as error:
        translate("void f(float a[]) { }")
    assert error.value.code == "unsupported_node" and "no WGSL form" in error.value.message


def test_a_lit_standard_surface_validates(gen, validator):
    """Closures in every shading context, the light loop with its dispatch, the environment's
    textures, LightData in the uniform buffer."""
    text = doc('<standard_surface name="ss" type="surfaceshader"><input name="coat" type="float" value="0.5"/>'
               '<input name="transmission" type="float" value="0.2"/></standard_surface>'
               '<surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="ss"/>'
               '</surfacematerial>')
    rec = gen.prepare(text, target="wgsl").emit()
    pixel = rec["stages"]["pixel"]
    assert "sampleLightSource(pu.u_lightData[activeLightIndex]" in pixel
    assert not validator(rec["stages"])
    members = {m["name"]: m for m in rec["layout"]["pixel"]["members"]}
    assert members["u_lightData"]["wgsl"] == "array<LightData, MAX_LIGHT_SOURCES>"
    assert members["u_lightData"]["offset"] % 16 == 0
    assert {t["name"] for t in rec["layout"]["pixel"]["textures"]} >= {"u_envRadiance", "u_envIrradiance"}


def test_the_validator_rejects_invalid_wgsl_with_its_line(validator):
    errors = validator({"bad": "fn f() -> f32 {\n    let x: i32 = 1.5;\n    return x;\n}\n"})
    assert "bad" in errors and "i32" in errors["bad"], errors
    from shadergen.render.errors import RenderError
    from shadergen.render.wgpu_device import shader_module, wgpu_device
    with pytest.raises(RenderError) as caught:
        shader_module(wgpu_device(), "fn f() -> f32 {\n    return undefined_name;\n}\n", "pixel")
    assert caught.value.where == "pixel:2"


def test_arrays_initialised_and_passed():
    out = translate("float g(vec3 t[3], int i) { return t[i].x; }\n"
                    "float f(vec3 a) { const float P[3] = float[3](1.0, 2.0, 3.0);\n"
                    "    vec3 ts[3] = vec3[3](a, a, a); return g(ts, 1) * P[2]; }")
    assert "fn g(t: array<vec3f, 3>, i: i32) -> f32" in out
    assert "var P: array<f32, 3> = array<f32, 3>(1.0, 2.0, 3.0);" in out  # indexed in place, not copied
    assert "var ts: array<vec3f, 3> = array<vec3f, 3>(a, a, a);" in out and "g(ts, 1)" in out


def test_comments_that_explain_are_kept_where_they_were():
    out = translate("// Why f exists\nfloat f(float x)\n{\n    // square it\n    float y = x * x; // and why\n"
                    "    if (y > 1.0) y = 1.0; // clamped\n    return y;\n}\n")
    lines = out.splitlines()
    assert lines[0] == "// Why f exists" and lines[1].startswith("fn f(")
    assert "    // square it" in lines and "    var y: f32 = x * x;  // and why" in lines
    assert "    if (y > 1.0) {" in lines and "        y = 1.0;  // clamped" in lines  # braces around every body


def test_a_files_detached_comment_blocks_are_left_out_as_in_glsl():
    out = translate("// The file's header.\n\n// Why f exists\nfloat f(float x)\n{\n    // a step\n\n"
                    "    return x;\n}\n")
    assert "header" not in out
    assert out.splitlines()[0] == "// Why f exists" and "    // a step" in out.splitlines()


def test_inverse_is_a_helper_of_the_target(gen, validator):
    text = doc('<nodegraph name="g"><invertmatrix name="i" type="matrix33"><input name="in" type="matrix33" '
               'value="1,0,0, 0,2,0, 0,0,4"/></invertmatrix><transformmatrix name="t" type="vector3">'
               '<input name="in" type="vector3" value="1,1,1"/><input name="mat" type="matrix33" nodename="i"/>'
               '</transformmatrix><output name="out" type="vector3" nodename="t"/></nodegraph>')
    pixel = gen.prepare(text, target="wgsl", names="document").emit()["stages"]["pixel"]
    assert "mx_inverse_mat3(pu.i_in)" in pixel and "fn mx_inverse_mat3(" in pixel
    assert "fn mx_inverse_mat4(" not in pixel  # helpers nothing calls are dropped
    assert not validator({"pixel": pixel})


def test_an_out_argument_into_a_member_goes_through_a_copy():
    """naga's SPIR-V writer in wgpu 0.32 panics on a pointer into a struct member (`&p.a`)."""
    out = translate("struct P { vec3 a; };\nvoid g(out vec3 r) { r = vec3(1.0); }\n"
                    "vec3 f() { P p; g(p.a); return p.a; }")
    assert "var written_0: vec3f = p.a;" in out and "g(&written_0);" in out and "p.a = written_0;" in out
    assert out.index("g(&written_0);") < out.index("p.a = written_0;") < out.index("return p.a;")


def test_a_library_file_translated_again_for_other_features_validates(gen, validator):
    """A file met again with its feature sections resolved otherwise (shadergen/features.py) keeps
    one signature per function and its own #ifndef-guarded constants."""
    surface = ('<standard_surface name="ss" type="surfaceshader"><input name="coat" type="float" value="0.5"/>'
               '<input name="transmission" type="float" value="{t}"/></standard_surface>'
               '<surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" '
               'nodename="ss"/></surfacematerial>')
    smooth = gen.prepare(doc(surface.format(t=0)), target="wgsl", interface="specialized").emit()["stages"]
    every = gen.prepare(doc(surface.format(t=0.2)), target="wgsl").emit()["stages"]
    assert "mx_surface_transmission" not in smooth["pixel"] and "mx_surface_transmission" in every["pixel"]
    assert not validator({"smooth": smooth["pixel"], "every": every["pixel"]})


COMPOSITING = [  # (node, output type, inputs): each folds to one value, guarded divisions included
    ("mix", "float", {"fg": "0.4", "bg": "0.3", "mix": "0.5"}),
    ("burn", "float", {"fg": "0", "bg": "0.5", "mix": "0.5"}),  # a division by zero, guarded
    ("dodge", "float", {"fg": "1", "bg": "0.5", "mix": "0.5"}),
    ("unpremult", "color4", {"in": "1, 0, 0.5, 0.5"}),  # naga's constant evaluator panicked on this one
    ("disjointover", "color4", {"fg": "1, 1, 1, 0.5", "bg": "1, 1, 0, 0", "mix": "0.5"}),
]


@pytest.mark.parametrize("category,type_name,inputs", COMPOSITING, ids=[c[0] for c in COMPOSITING])
def test_a_specialized_compositing_element_validates(gen, validator, category, type_name, inputs):
    """All-constant nodes that drive the output are folded to a constant too: left as they were,
    they were expressions of abstract-typed literals, or divisions by zero, that naga rejects."""
    values = "".join(f'<input name="{n}" type="{"float" if n == "mix" else type_name}" value="{v}"/>' for n, v in inputs.items())
    text = doc(f'<nodegraph name="g"><{category} name="n" type="{type_name}">{values}</{category}>'
               f'<output name="out" type="{type_name}" nodename="n"/></nodegraph>')
    rec = gen.prepare(text, target="wgsl", interface="specialized").emit()
    assert rec["passes"]["fold"] == 1
    assert not validator(rec["stages"])


PANICS = """@fragment
fn fragmentMain() -> @location(0) vec4f {
    let c = select(vec4f(vec4f(1.0, 0.0, 0.5, 0.5).rgb / 0.5, 0.5), vec4f(1.0), vec4f(1.0).a == 0.0);
    return c;
}
"""


def test_a_validator_panic_is_one_rejected_module(validator):
    """naga 29's constant evaluator panics on a select() of constant vectors; a panic through
    wgpu-native's C interface aborts the process, so validation runs in a child process and the
    module is rejected with the panic's message, the modules after it still validated."""
    good = "@fragment\nfn fragmentMain() -> @location(0) vec4f {\n    return vec4f(1.0);\n}\n"
    errors = validator({"before": good, "panics": PANICS, "after": good, "bad": good.replace("vec4f(1.0)", "1.5i")})
    assert set(errors) == {"panics", "bad"}, errors
    assert "panicked" in errors["panics"] and "constant_evaluator" in errors["panics"], errors["panics"]


NOT_FINITE = [  # nodes of literals whose value WGSL's compiler cannot hold: no Python evaluator folds them
    '<divide name="n" type="float"><input name="in1" type="float" value="1"/><input name="in2" type="float" value="0"/></divide>',
    '<divide name="n" type="vector3"><input name="in1" type="vector3" value="1, 0, 1"/><input name="in2" type="float" value="0"/></divide>',
    '<modulo name="n" type="float"><input name="in1" type="float" value="1"/><input name="in2" type="float" value="0"/></modulo>',
    '<remap name="n" type="float"><input name="in" type="float" value="1"/><input name="inlow" type="float" value="0.5"/>'
    '<input name="inhigh" type="float" value="0.5"/></remap>',
    '<sqrt name="n" type="float"><input name="in" type="float" value="-1"/></sqrt>',
    '<ln name="n" type="float"><input name="in" type="float" value="0"/></ln>',
    '<normalize name="n" type="vector3"><input name="in" type="vector3" value="0, 0, 0"/></normalize>',
    '<exp name="n" type="float"><input name="in" type="float" value="100"/></exp>',
]


@pytest.mark.parametrize("node", NOT_FINITE, ids=["divide", "divide_vector3", "modulo", "remap", "sqrt", "ln", "normalize", "exp"])
def test_literals_whose_value_is_not_finite_are_computed_at_run_time(gen, validator, node):
    """WGSL rejects a constant expression whose value is infinite or undefined; GLSL computes it.
    The literals go through an identity function, which no compiler evaluates."""
    t = node.split('type="')[1].split('"')[0]
    text = doc(f'<nodegraph name="g">{node}<output name="out" type="{t}" nodename="n"/></nodegraph>')
    rec = gen.prepare(text, target="wgsl", interface="specialized").emit()
    assert f"mx_runtime_{'vec3f' if t == 'vector3' else 'f32'}(" in rec["stages"]["pixel"]
    assert not validator(rec["stages"])
    literal = gen.prepare(doc(f'<nodegraph name="g"><constant name="n" type="{t}"><input name="value" type="{t}" '
                              f'value="{"1, 2, 3" if t == "vector3" else "1"}"/></constant>'
                              f'<output name="out" type="{t}" nodename="n"/></nodegraph>'), target="wgsl", interface="specialized").emit()
    assert "mx_runtime" not in literal["stages"]["pixel"]  # a literal alone is finite: written as it is
