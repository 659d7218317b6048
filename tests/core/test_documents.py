import pytest

from shadergen.document import parse_document, read_document
from shadergen.errors import ShaderGenError

from .conftest import doc, glslang


def test_entity_expansion_is_refused():
    bomb = ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;">]>'
            '<materialx version="1.39"><input name="x" type="string" value="&b;"/></materialx>')
    with pytest.raises(ShaderGenError) as e:
        parse_document(bomb)
    assert e.value.code == "unsafe_xml"


def test_external_entity_is_refused():
    xxe = ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
           '<materialx version="1.39"><input name="x" type="string" value="&x;"/></materialx>')
    with pytest.raises(ShaderGenError) as e:
        parse_document(xxe)
    assert e.value.code == "unsafe_xml"


def test_malformed_xml_names_the_line():
    with pytest.raises(ShaderGenError) as e:
        parse_document('<?xml version="1.0"?>\n<materialx>\n<add name="a" type="float">\n</materialx>')
    assert e.value.code == "invalid_document"
    assert e.value.where.startswith("<document>:4")


def test_xinclude_resolves_relative_to_the_document(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "defs.mtlx").write_text(doc('<constant name="c" type="float"><input name="value" type="float" value="2"/></constant>'))
    main = tmp_path / "main.mtlx"
    main.write_text(doc('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="sub/defs.mtlx"/>'))
    d = read_document(str(main))
    assert d.root.child("c").category == "constant"


def test_xinclude_refused_for_uploads():
    text = doc('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="/etc/passwd"/>')
    with pytest.raises(ShaderGenError) as e:
        parse_document(text, allow_includes=False)
    assert e.value.code == "include_refused"


def test_udim_token_in_attribute_is_accepted():
    d = parse_document(doc('<image name="i" type="color3"><input name="file" type="filename" value="a.<UDIM>.png"/></image>'))
    assert d.root.child("i").child("file").get("value") == "a.<UDIM>.png"


def test_upgrade_from_1_38_renames_swizzle():
    d = parse_document(doc('<constant name="c" type="color3"><input name="value" type="color3" value="1,2,3"/></constant>'
                           '<swizzle name="s" type="float"><input name="in" type="color3" nodename="c"/>'
                           '<input name="channels" type="string" value="g"/></swizzle>', version="1.38"))
    s = d.root.child("s")
    assert s.category == "extract" and s.child("index").get("value") == "1"


def test_upgrade_from_1_38_swizzles_a_value_into_a_constant():
    d = parse_document(doc('<swizzle name="s" type="color4"><input name="in" type="color3" value="0.4, 0.5, 0.6"/>'
                           '<input name="channels" type="string" value="bgr1"/></swizzle>', version="1.38"))
    s = d.root.child("s")
    assert s.category == "constant" and s.child("value").get("value") == "0.6, 0.5, 0.4, 1.0"


def test_upgrade_from_1_38_reads_several_channels_through_one_separate(gen):
    text = doc('<constant name="c" type="color3"><input name="value" type="color3" value="0.1, 0.2, 0.3"/></constant>'
               '<swizzle name="s" type="color4"><input name="in" type="color3" nodename="c"/>'
               '<input name="channels" type="string" value="bgr1"/></swizzle>'
               '<output name="o" type="color4" nodename="s"/>', version="1.38")
    d = parse_document(text)
    assert d.root.child("s").category == "combine4" and d.root.child("s_separate").category == "separate3"
    assert [i.get("output") or i.get("value") for i in d.root.child("s").children] == ["outb", "outg", "outr", "1.0"]
    public = {v["path"] for v in gen.prepare(text).emit()["blocks"]["pixel"]["PublicUniforms"]}
    assert "s/in4" in public and not any("index" in p for p in public)


def test_upgrade_from_1_38_decodes_object_space_normal_maps():
    d = parse_document(doc('<normalmap name="n" type="vector3" nodedef="ND_normalmap">'
                           '<input name="in" type="vector3" value="0.5, 0.5, 1"/>'
                           '<input name="space" type="string" value="object"/></normalmap>', version="1.38"))
    n, scaled, shifted = d.root.child("n"), d.root.child("multiply"), d.root.child("subtract")
    assert n.category == "normalize" and n.child("in").get("nodename") == "subtract"
    assert scaled.child("in1").get("value") == "0.5, 0.5, 1" and scaled.child("in2").get("value") == "2.0"
    assert shifted.child("in1").get("nodename") == "multiply" and shifted.child("in2").get("value") == "1.0"


def test_fileprefix_of_an_included_document_applies_to_its_elements(tmp_path, gen):
    (tmp_path / "inc.mtlx").write_text(
        '<?xml version="1.0"?>\n<materialx version="1.39" fileprefix="tex/">'
        '<image name="img" type="color3"><input name="file" type="filename" value="a.png"/></image>'
        '<output name="o" type="color3" nodename="img"/></materialx>')
    main = tmp_path / "main.mtlx"
    main.write_text(doc('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="inc.mtlx"/>'))
    for path in (main, tmp_path / "inc.mtlx"):
        rec = gen.prepare(path).emit()
        files = [v["value"] for v in rec["blocks"]["pixel"]["PublicUniforms"] if v["type"] == "filename"]
        assert files == ["tex/a.png"], path.name


V1_22 = '''<opgraph name="paint_graph">
  <constant name="base_constant" type="float"><parameter name="color" type="float" value="0.5"/></constant>
  <output name="base_output" type="float"><parameter name="in" type="opgraphnode" value="base_constant"/></output>
</opgraph>
<shader name="paint_shader" shadertype="surface" shadername="standard_surface">
  <input name="base" graphoutput="base_output" graphname="paint_graph" type="float"/>
</shader>
<material name="paint_material"><shaderref name="paint_shader" shadertype="surface"/></material>'''

V1_25 = '''<shader name="surf" shadertype="surface" shaderprogram="standard_surface">
  <input name="base" type="float" value="1.0" publicname="base_public"/>
</shader>
<material name="paint"><shaderref name="surf" shadertype="surface"/>
  <override name="base_public" type="float" value="0.25"/></material>'''

V1_37 = '''<nodedef name="ND_old_surface" node="old_surface">
  <input name="tint" type="color3" value="0.18, 0.18, 0.18"/><input name="ior" type="float" value="1.5"/>
  <output name="out" type="surfaceshader"/>
</nodedef>
<nodegraph name="NG_old_surface" nodedef="ND_old_surface">
  <diffuse_brdf name="diffuse" type="BSDF"><input name="color" type="color3" interfacename="tint"/></diffuse_brdf>
  <dielectric_btdf name="transmission" type="BSDF"><input name="ior" type="float" interfacename="ior"/></dielectric_btdf>
  <multiply name="f0" type="float"><input name="in1" type="float" interfacename="ior"/><input name="in2" type="float" value="0.1"/></multiply>
  <generalized_schlick_brdf name="specular" type="BSDF">
    <input name="color0" type="color3" nodename="f0" channels="rrr"/><input name="base" type="BSDF" nodename="diffuse"/>
  </generalized_schlick_brdf>
  <conductor_brdf name="metal" type="BSDF"><input name="reflectivity" type="color3" interfacename="tint"/></conductor_brdf>
  <mix name="blend" type="BSDF"><input name="fg" type="BSDF" nodename="metal"/><input name="bg" type="BSDF" nodename="specular"/></mix>
  <mix name="clear" type="BSDF"><input name="fg" type="BSDF" nodename="transmission"/><input name="bg" type="BSDF" nodename="blend"/></mix>
  <surface name="surface" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="clear"/></surface>
  <output name="out" type="surfaceshader" nodename="surface"/>
</nodegraph>
<material name="M_old"><shaderref name="SR_old" node="old_surface">
  <bindinput name="tint" type="color3" value="0.2, 0.2, 0.6"/></shaderref></material>
<atan2 name="angle" type="float"><input name="in1" type="float" value="0.5"/><input name="in2" type="float" value="1.0"/></atan2>'''


@pytest.mark.parametrize("version, body, element, path, value", [
    ("1.22", V1_22, "paint_material", "paint_graph/base_constant/value", 0.5),
    ("1.25", V1_25, "paint", "surf/base", 0.25),
    ("1.37", V1_37, "M_old", "SR_old/tint", [0.2, 0.2, 0.6]),
])
def test_old_documents_are_upgraded_and_generate(gen, glslang_validator, version, body, element, path, value):
    rec = gen.prepare(doc(body, version=version)).emit()
    assert rec["element"] == element
    public = {v["path"]: v["value"] for v in rec["blocks"]["pixel"]["PublicUniforms"]}
    assert public[path] == pytest.approx(value)
    ok, log = glslang(rec["stages"]["pixel"], "pixel")
    assert ok, log


def test_1_37_atan2_inputs_are_swapped_then_named():
    """1.38 swapped atan2's inputs, 1.39 named them y and x: a 1.37 in1 is x (test_upgrade.py)."""
    d = parse_document(doc(V1_37, version="1.37"))
    angle = d.root.child("angle")
    assert angle.child("inx").get("value") == "0.5" and angle.child("iny").get("value") == "1.0"


def test_nodes_of_another_namespace_are_written_with_an_undeclared_prefix(gen):
    text = doc('<nodedef name="ND_tint" node="tint" namespace="mine"><input name="in" type="float" value="1"/>'
               '<output name="out" type="float"/></nodedef>'
               '<nodegraph name="NG_tint" namespace="mine" nodedef="ND_tint"><multiply name="m" type="float">'
               '<input name="in1" type="float" interfacename="in"/><input name="in2" type="float" value="0.5"/>'
               '</multiply><output name="out" type="float" nodename="m"/></nodegraph>'
               '<mine:tint name="t" type="float"><input name="in" type="float" value="3"/></mine:tint>'
               '<output name="o" type="float" nodename="t"/>')
    assert parse_document(text).root.child("t").category == "mine:tint"
    rec = gen.prepare(text, element="o").emit()
    assert "* 0.5" in rec["stages"]["pixel"]
