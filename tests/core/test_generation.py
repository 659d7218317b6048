"""Each generation mechanism, checked on the code and listings it produces."""
from pathlib import Path

import pytest

from shadergen.errors import ShaderGenError
from shadergen.types import parse_ui_hint

from .conftest import doc, glslang, needs_glslang

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def first(gen, body, **kw):
    # document names: the checks read the code by the document's node names (test_names.py checks
    # the structural names every other generation gets)
    return gen.prepare(doc(body), **{"names": "document", **kw}).emit()


def pixel(rec):
    return rec["stages"]["pixel"]


def public(rec):
    return {v["path"]: v for v in rec["blocks"]["pixel"]["PublicUniforms"]}


def test_inline_expression_substitutes_inputs(gen):
    rec = first(gen, '<add name="a" type="float"><input name="in1" type="float" value="0.25"/>'
                     '<input name="in2" type="float" value="-0.5"/></add><output name="o" type="float" nodename="a"/>')
    assert "float a_out = a_in1 + a_in2;" in pixel(rec)
    assert public(rec)["a/in2"]["value"] == -0.5


def test_reduced_interface_writes_constants_and_keeps_negative_literals_safe(gen):
    rec = first(gen, '<texcoord name="t" type="vector2"/><subtract name="s" type="vector2">'
                     '<input name="in1" type="vector2" nodename="t"/><input name="in2" type="float" value="-0.5"/>'
                     '</subtract><output name="o" type="vector2" nodename="s"/>', interface="reduced")
    assert "vec2 s_out = t_out - (-0.5);" in pixel(rec)
    assert rec["blocks"]["pixel"]["PublicUniforms"] == []


def test_source_function_is_emitted_once_with_its_includes(gen):
    body = ''.join(f'<noise3d name="n{i}" type="float"/>' for i in range(2))
    body += '<add name="a" type="float"><input name="in1" type="float" nodename="n0"/><input name="in2" type="float" nodename="n1"/></add>'
    rec = first(gen, body + '<output name="o" type="float" nodename="a"/>')
    src = pixel(rec)
    assert src.count("uint mx_hn_final(") == 1
    assert "n0_out" in src and "n1_out" in src


def test_nodegraph_implementation_used_twice_becomes_a_function(gen):
    rec = first(gen, '<safepower name="p" type="float"><input name="in1" type="float" value="-2"/></safepower>'
                     '<safepower name="q" type="float"><input name="in1" type="float" nodename="p"/></safepower>'
                     '<output name="o" type="float" nodename="q"/>')
    assert pixel(rec).count("void NG_safepower_float(") == 1
    assert "NG_safepower_float(p_in1, p_in2, p_out);" in pixel(rec)
    assert "NG_safepower_float(p_out, q_in2, q_out);" in pixel(rec)


def test_nodegraph_implementation_used_once_is_written_in_place(gen):
    rec = first(gen, '<safepower name="p" type="float"><input name="in1" type="float" value="-2"/></safepower>'
                     '<output name="o" type="float" nodename="p"/>')
    src = pixel(rec)
    assert "NG_safepower_float" not in src
    main = src[src.index("void main()"):]
    assert "p_in1" in main and "p_in2" in main and main.count("p_N_") >= 3


def test_dynamic_texcoord_writes_both_stages(gen):
    rec = first(gen, '<texcoord name="t" type="vector2"><input name="index" type="integer" value="1"/></texcoord>'
                     '<output name="o" type="vector2" nodename="t"/>')
    assert "vd.texcoord_1 = i_texcoord_1;" in rec["stages"]["vertex"]
    assert "vec2 t_out = vd.texcoord_1;" in pixel(rec)
    assert [v["name"] for v in rec["blocks"]["vertex"]["AppData"]] == ["i_position", "i_texcoord_1"]


def test_default_geomprop_is_connected_once(gen):
    rec = first(gen, '<image name="a" type="color3"/><image name="b" type="color3"/>'
                     '<add name="s" type="color3"><input name="in1" type="color3" nodename="a"/>'
                     '<input name="in2" type="color3" nodename="b"/></add><output name="o" type="color3" nodename="s"/>')
    assert pixel(rec).count("= vd.texcoord_0;") == 1
    assert public(rec)["UV0"]["name"] == "geomprop_UV0_index"


def test_constant_nodes_fold_into_their_consumers(gen):
    rec = first(gen, '<constant name="c" type="float"><input name="value" type="float" value="3"/></constant>'
                     '<sin name="s" type="float"><input name="in" type="float" nodename="c"/></sin>'
                     '<output name="o" type="float" nodename="s"/>')
    assert "c_out" not in pixel(rec)
    assert public(rec)["c/value"]["name"] == "s_in"


def test_unused_nodes_are_pruned(gen):
    rec = first(gen, '<sin name="used" type="float"/><cos name="unused" type="float"/>'
                     '<output name="o" type="float" nodename="used"/>')
    assert "unused" not in pixel(rec)


def test_cycle_is_an_error_naming_the_nodes(gen):
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(doc('<sin name="a" type="float"><input name="in" type="float" nodename="b"/></sin>'
                        '<cos name="b" type="float"><input name="in" type="float" nodename="a"/></cos>'
                        '<output name="o" type="float" nodename="a"/>'))
    assert e.value.code == "cycle" and "a" in e.value.message and "b" in e.value.message


def test_branch_only_nodes_are_computed_inside_their_branch(gen):
    rec = first(gen, '<noise2d name="expensive" type="float"/>'
                     '<ifgreater name="pick" type="float"><input name="in1" type="float" nodename="expensive"/>'
                     '<input name="in2" type="float" value="0.5"/></ifgreater><output name="o" type="float" nodename="pick"/>')
    src = pixel(rec)
    branch = src[src.index("if (pick_value1 > pick_value2)"):src.index("else")]
    assert "expensive_out" in branch and "mx_noise2d" in branch


def test_unknown_node_and_type_mismatch(gen):
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(doc('<frobnicate name="f" type="float"/><output name="o" type="float" nodename="f"/>'))
    assert e.value.code == "unknown_node" and e.value.where == "f"
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(doc('<add name="a" type="float"><input name="in1" type="color3" value="1,1,1"/></add>'
                        '<output name="o" type="float" nodename="a"/>'))
    assert e.value.code == "type_mismatch"


def test_dangling_connection(gen):
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(doc('<sin name="a" type="float"><input name="in" type="float" nodename="nowhere"/></sin>'
                        '<output name="o" type="float" nodename="a"/>'))
    assert e.value.code == "dangling_connection" and e.value.where == "a/in"


COLORED = ('<multiply name="m" type="color3"><input name="in1" type="color3" value="0.5,0.5,0.5" '
           'colorspace="gamma22"/></multiply><output name="o" type="color3" nodename="m"/>')


def test_colorspace_inserts_a_transform_into_the_working_space(gen):
    rec = gen.prepare(doc(COLORED, colorspace="lin_rec709"), names="document").emit()
    assert "m_in1_cm" in pixel(rec) and "pow(" in pixel(rec)  # gamma22 is MaterialX's name for g22_rec709
    assert public(rec)["m/in1"]["colorspace"] == "gamma22"


def test_a_document_without_colorspace_is_not_colour_managed(gen):
    assert "_cm" not in pixel(gen.prepare(doc(COLORED), names="document").emit())


def test_units_insert_a_conversion_whose_factor_is_code_not_a_uniform(gen):
    def multiply(unit):
        return doc('<multiply name="m" type="float"><input name="in1" type="float" value="10" unit="' + unit + '" '
                   'unittype="distance"/></multiply><output name="o" type="float" nodename="m"/>')

    rec = gen.prepare(multiply("centimeter")).emit()
    uniforms = rec["blocks"]["pixel"]["PublicUniforms"]
    # the factor is no input of the document: a client could not say what it binds to
    assert [v["path"] for v in uniforms] == ["m/in1", "m/in2"]
    assert "0.01" in pixel(rec)
    # ... so the unit, which decides it, is part of the topology
    assert rec["topology_hash"] != gen.prepare(multiply("meter")).emit()["topology_hash"]
    assert rec["topology_hash"] == gen.prepare(multiply("centimeter")).emit()["topology_hash"]


def test_an_input_an_implementation_adds_is_listed_at_its_node(gen):
    rec = gen.prepare(doc('<image name="i" type="color3"/><output name="o" type="color3" nodename="i"/>')).emit()
    paths = {v["name"]: v["path"] for v in rec["blocks"]["pixel"]["PublicUniforms"]}
    assert all(paths.values()), paths
    assert {"i/uv_scale", "i/uv_offset"} <= set(paths.values())


def test_a_geometric_input_bound_to_an_interface_value_reads_that_value(gen):
    """A nodegraph drawn as its nodedef: an input that would read the geometry (image's texcoord,
    defaultgeomprop UV0) bound to a nodedef input with a value reads the value, a uniform listed at
    the nodedef's input, as MaterialX publishes it; unbound, it reads the geometry."""
    def graph(bound):
        texcoord = '<input name="texcoord" type="vector2" interfacename="at"/>' if bound else ''
        return doc('<nodedef name="ND_probe" node="probe"><input name="at" type="vector2" value="0.25, 0.75"/>'
                   '<output name="out" type="color3"/></nodedef><nodegraph name="NG_probe" nodedef="ND_probe">'
                   f'<image name="i" type="color3">{texcoord}</image><output name="out" type="color3" nodename="i"/>'
                   '</nodegraph>')

    bound, unbound = (gen.prepare(graph(b), element="NG_probe/out").emit() for b in (True, False))
    def appdata(rec):
        return [v["name"] for v in rec["blocks"]["vertex"]["AppData"]]

    assert public(bound)["ND_probe/at"]["value"] == [0.25, 0.75]
    assert appdata(bound) == ["i_position"]
    assert "ND_probe/at" not in public(unbound) and "i_texcoord_0" in appdata(unbound)

def test_enum_strings_become_integer_uniforms(gen):
    rec = first(gen, '<image name="i" type="color3"><input name="uaddressmode" type="string" value="mirror"/></image>'
                     '<output name="o" type="color3" nodename="i"/>')
    v = public(rec)["i/uaddressmode"]
    assert (v["type"], v["value"]) == ("integer", 3)
    assert "uniform int i_uaddressmode = 2;" in pixel(rec)  # the source starts from the nodedef's periodic
    in_source = first(gen, '<image name="i" type="color3"><input name="uaddressmode" type="string" value="mirror"/>'
                           '</image><output name="o" type="color3" nodename="i"/>', values="source")
    assert "uniform int i_uaddressmode = 3;" in pixel(in_source)


def test_reserved_words_are_renamed(gen):
    rec = first(gen, '<sin name="out" type="float"/><output name="o" type="float" nodename="out"/>')
    assert "float out_out" in pixel(rec) or "float out_out1" in pixel(rec)


def test_hash_ignores_formatting_order_and_unused_nodes_but_not_values(gen):
    a = doc('<sin name="s" type="float"><input name="in" type="float" value="0.5"/></sin><output name="o" type="float" nodename="s"/>')
    b = doc('<output name="o"   type="float" nodename="s"/>\n\n<cos name="spare" type="float"/>'
            '<sin type="float" name="s"><input value="0.5" name="in" type="float"/></sin>')
    c = a.replace('0.5', '0.6')
    ha, hb, hc = (gen.prepare(x).hash for x in (a, b, c))
    assert ha == hb != hc
    assert gen.prepare(a).emit()["stages"] == gen.prepare(b).emit()["stages"]


def test_generation_is_deterministic(gen):
    body = '<fractal3d name="f" type="color3"/><output name="o" type="color3" nodename="f"/>'
    r1, r2 = first(gen, body), first(gen, body)
    assert r1["stages"] == r2["stages"] and r1["blocks"] == r2["blocks"] and r1["hash"] == r2["hash"]


def test_unknown_target(gen):
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(doc('<sin name="s" type="float"/><output name="o" type="float" nodename="s"/>'), target="mdl")
    assert e.value.code == "unsupported_target"


@needs_glslang
@pytest.mark.parametrize("target", ["glsl", "essl"])
def test_generated_shaders_compile(gen, target):
    body = ('<position name="p" type="vector3"/><noise3d name="n" type="color3"><input name="position" type="vector3" nodename="p"/></noise3d>'
            '<image name="i" type="color3"/><ifgreater name="c" type="color3"><input name="value1" type="float" value="0.5"/>'
            '<input name="in1" type="color3" nodename="n"/><input name="in2" type="color3" nodename="i"/></ifgreater>'
            '<output name="o" type="color3" nodename="c"/>')
    rec = first(gen, body, target=target)
    for stage, src in rec["stages"].items():
        ok, log = glslang(src, stage)
        assert ok, log


def test_derivative_nodes_stay_in_uniform_control_flow(gen):
    rec = first(gen, '<heighttonormal name="h" type="vector3"><input name="in" type="float" value="0.5"/></heighttonormal>'
                     '<ifgreater name="pick" type="vector3"><input name="in1" type="vector3" nodename="h"/>'
                     '</ifgreater><output name="o" type="vector3" nodename="pick"/>')
    src = pixel(rec)
    assert src.index("mx_heighttonormal_vector3(") < src.index("pick_out")
    assert "if (" not in src[src.index("void main()"):]


def test_deep_chains_generate(gen):
    n = 3000
    body = '<add name="n0" type="float"/>' + ''.join(
        f'<add name="n{i}" type="float"><input name="in1" type="float" nodename="n{i - 1}"/></add>' for i in range(1, n))
    rec = first(gen, body + f'<output name="o" type="float" nodename="n{n - 1}"/>')
    assert f"float n{n - 1}_out = n{n - 2}_out + n{n - 1}_in2;" in pixel(rec)


def test_text_is_never_read_as_a_path(gen):
    with pytest.raises(ShaderGenError) as e:
        gen.prepare("/etc/passwd")
    assert e.value.code == "invalid_document"


@pytest.mark.parametrize("value", ["1" + "0" * 400, "2147483648", "-2147483649"])
def test_integer_out_of_the_shading_languages_range_is_invalid(gen, value):
    text = doc(f'<switch name="s" type="float"><input name="which" type="integer" value="{value}"/></switch>'
               '<output name="o" type="float" nodename="s"/>')
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(text).emit()
    assert e.value.code == "invalid_value" and e.value.where == "s/which"


def test_float_that_overflows_to_infinity_is_invalid(gen):
    text = doc('<add name="a" type="float"><input name="in1" type="float" value="1e400"/></add>'
               '<output name="o" type="float" nodename="a"/>')
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(text).emit()
    assert e.value.code == "invalid_value"


def test_connection_between_different_types_names_the_input(gen):
    text = doc('<constant name="c" type="color3"><input name="value" type="color3" value="1,0,0"/></constant>'
               '<add name="a" type="float"><input name="in1" type="float" nodename="c"/></add>'
               '<output name="o" type="float" nodename="a"/>')
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(text).emit()
    assert e.value.code == "type_mismatch" and e.value.where == "a/in1"
    assert "color3" in e.value.message and "in1" in e.value.message


def test_document_ui_metadata_overrides_the_nodedefs(gen):
    rec = gen.prepare(Path(EXAMPLES / "marble_checker.mtlx")).emit()
    ui = {v["path"]: v.get("ui") for v in rec["blocks"]["pixel"]["PublicUniforms"]}
    assert ui["NG_marble_checker/scale"]["name"] == "Pattern scale"
    text = doc('<add name="a" type="float"><input name="in1" type="float" value="1" uiname="Brightness" uimax="4"/>'
               '</add><output name="o" type="float" nodename="a"/>')
    ui = {v["path"]: v.get("ui") for v in gen.prepare(text).emit()["blocks"]["pixel"]["PublicUniforms"]}
    assert ui["a/in1"]["name"] == "Brightness" and ui["a/in1"]["max"] == 4.0  # typed like the input


def test_ui_metadata_is_part_of_the_hash(gen):
    def hash_with(name):
        return gen.prepare(doc(f'<add name="a" type="float"><input name="in1" type="float" value="1" uiname="{name}"/>'
                               '</add><output name="o" type="float" nodename="a"/>')).hash
    assert hash_with("A") != hash_with("B")


def test_multi_output_image_node_decodes_its_colour_output(gen):
    def pixel(node):
        text = doc(f'<{node} name="img" type="multioutput"><input name="file" type="filename" value="a.png" '
                   'colorspace="srgb_texture"/></' + node + '>'
                   '<output name="o" type="color3" nodename="img" output="outcolor"/>', colorspace="lin_rec709")
        return gen.prepare(text, element="o", names="document").emit()["stages"]["pixel"]
    code = pixel("gltf_colorimage")
    assert "o = vec4(img_outcolor_cm_out, 1.0);" in code and "outa_cm" not in code


def test_light_shader_graph_is_not_renderable(gen):
    text = doc('<nodedef name="ND_lamp" node="lamp"><input name="color" type="color3"/><output name="out" type="lightshader"/>'
               '</nodedef><nodegraph name="NG_lamp" nodedef="ND_lamp"><uniform_edf name="e" type="EDF">'
               '<input name="color" type="color3" interfacename="color"/></uniform_edf><light name="l" type="lightshader">'
               '<input name="edf" type="EDF" nodename="e"/></light><output name="out" type="lightshader" nodename="l"/>'
               '</nodegraph>')
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(text)
    assert e.value.code == "no_renderable_element"


def test_listing_ui_hints_are_typed_like_their_input(gen):
    rec = first(gen, '<standard_surface name="s" type="surfaceshader"/>'
                     '<surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/>'
                     '</surfacematerial>')
    ui = {path: v.get("ui") for path, v in public(rec).items()}
    assert ui["s/base"]["min"] == 0.0 and ui["s/base"]["max"] == 1.0
    assert ui["s/base_color"]["max"] == [1.0, 1.0, 1.0]
    assert ui["s/base_color"]["folder"] == "Base"
    assert ui["s/diffuse_roughness"]["advanced"] is True


def test_enum_hints_are_lists_of_names_and_typed_values(gen):
    rec = first(gen, '<luminance name="l" type="color3"><input name="in" type="color3" value="0.5, 0.2, 0.1"/></luminance>'
                     '<image name="i" type="color3"/><multiply name="m" type="color3">'
                     '<input name="in1" type="color3" nodename="l"/><input name="in2" type="color3" nodename="i"/></multiply>'
                     '<output name="o" type="color3" nodename="m"/>')
    luma = public(rec)["l/lumacoeffs"]["ui"]
    assert luma["enum"] == ["acescg", "rec709", "rec2020", "rec2100"]
    assert luma["enumvalues"][1] == [0.2126, 0.7152, 0.0722] and len(luma["enumvalues"]) == 4
    address = public(rec)["i/uaddressmode"]
    assert address["type"] == "integer" and address["ui"]["enum"] == ["constant", "clamp", "periodic", "mirror"]
    assert address["ui"]["enum"][address["value"]] == "periodic"


def test_a_malformed_ui_hint_is_an_error_at_its_input():
    with pytest.raises(ShaderGenError) as err:
        parse_ui_hint("min", "float", "low", "ND_bad/x")
    assert err.value.code == "invalid_value" and err.value.where == "ND_bad/x"
