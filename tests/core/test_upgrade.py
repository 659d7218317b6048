"""Document upgrades, one test per version step: an old document generates exactly what the 1.39
document the standard makes of it generates (the `specialized` interface folds every value into
the code, so a value in the wrong input or a missing swap changes the source). The 1.39 forms
below are the standard's (bench/upgrade.py checks our upgrades' listings against the reference
generator's over the corpus)."""
import pytest

from shadergen.document import parse_document

from .conftest import doc


def same_shader(gen, old: str, version: str, upgraded: str, element: str) -> None:
    ours = gen.prepare(doc(old, version=version), element=element, interface="specialized").emit()
    standard = gen.prepare(doc(upgraded), element=element, interface="specialized").emit()
    assert ours["stages"]["pixel"] == standard["stages"]["pixel"]
    assert ours["blocks"]["pixel"] == standard["blocks"]["pixel"]


def test_1_22_opgraph_and_shader_become_a_nodegraph_and_a_shader_node(gen):
    old = '''<opgraph name="g">
      <constant name="c" type="color3"><parameter name="color" type="color3" value="0.1, 0.6, 0.8"/></constant>
      <output name="o" type="color3"><parameter name="in" type="opgraphnode" value="c"/></output>
    </opgraph>
    <shader name="s" shadertype="surface" shadername="standard_surface">
      <input name="base_color" type="color3" graphname="g" graphoutput="o"/>
    </shader>
    <material name="m"><shaderref name="s" shadertype="surface"/></material>'''
    upgraded = '''<nodegraph name="g">
      <constant name="c" type="color3"><input name="value" type="color3" value="0.1, 0.6, 0.8"/></constant>
      <output name="o" type="color3" nodename="c"/>
    </nodegraph>
    <standard_surface name="s" type="surfaceshader"><input name="base_color" type="color3" nodegraph="g" output="o"/></standard_surface>
    <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/></surfacematerial>'''
    same_shader(gen, old, "1.22", upgraded, "m")


def test_1_25_material_overrides_set_the_shader_inputs_they_name(gen):
    old = '''<shader name="s" shadertype="surface" shaderprogram="standard_surface">
      <input name="base" type="float" value="1.0" publicname="base_public"/>
      <input name="coat" type="float" value="0.0" publicname="coat_public"/>
    </shader>
    <material name="m"><shaderref name="s" shadertype="surface"/>
      <override name="base_public" type="float" value="0.5"/><override name="coat_public" type="float" value="1.0"/>
    </material>'''
    upgraded = '''<standard_surface name="s" type="surfaceshader">
      <input name="base" type="float" value="0.5"/><input name="coat" type="float" value="1.0"/></standard_surface>
    <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/></surfacematerial>'''
    same_shader(gen, old, "1.25", upgraded, "m")


STEP_1_37 = [
    ("compare: intest and cutoff are value1 and value2, in1 and in2 trade places",
     '<compare name="n" type="color3"><input name="intest" type="float" value="0.5"/>'
     '<parameter name="cutoff" type="float" value="0.6"/><input name="in1" type="color3" value="1, 0, 0"/>'
     '<input name="in2" type="color3" value="0, 0, 1"/></compare>',
     '<ifgreatereq name="n" type="color3"><input name="value1" type="float" value="0.5"/>'
     '<input name="value2" type="float" value="0.6"/><input name="in2" type="color3" value="1, 0, 0"/>'
     '<input name="in1" type="color3" value="0, 0, 1"/></ifgreatereq>'),
    ("invert of a matrix is invertmatrix",
     '<invert name="n" type="matrix33"><input name="in" type="matrix33" value="2,0,0, 0,4,0, 0,0,1"/></invert>',
     '<invertmatrix name="n" type="matrix33"><input name="in" type="matrix33" value="2,0,0, 0,4,0, 0,0,1"/></invertmatrix>'),
    ("rotate of a vector2 is rotate2d",
     '<rotate name="n" type="vector2"><input name="in" type="vector2" value="1, 0"/>'
     '<input name="amount" type="float" value="30"/></rotate>',
     '<rotate2d name="n" type="vector2"><input name="in" type="vector2" value="1, 0"/>'
     '<input name="amount" type="float" value="30"/></rotate2d>'),
    ("rotate of a vector3 is rotate3d",
     '<rotate name="n" type="vector3"><input name="in" type="vector3" value="1, 0, 0"/>'
     '<input name="amount" type="float" value="30"/><parameter name="axis" type="vector3" value="0, 1, 1"/></rotate>',
     '<rotate3d name="n" type="vector3"><input name="in" type="vector3" value="1, 0, 0"/>'
     '<input name="amount" type="float" value="30"/><input name="axis" type="vector3" value="0, 1, 1"/></rotate3d>'),
    ("transformpoint by a matrix is transformmatrix",
     '<transformpoint name="n" type="vector3"><input name="in" type="vector3" value="1, 2, 3"/>'
     '<input name="mat" type="matrix44" value="1,0,0,0, 0,1,0,0, 0,0,1,0, 4,5,6,1"/></transformpoint>',
     '<transformmatrix name="n" type="vector3"><input name="in" type="vector3" value="1, 2, 3"/>'
     '<input name="mat" type="matrix44" value="1,0,0,0, 0,1,0,0, 0,0,1,0, 4,5,6,1"/></transformmatrix>'),
    ("combine of a color2 is combine2 of a vector2",
     '<combine name="n" type="color2"><input name="in1" type="float" value="0.25"/>'
     '<input name="in2" type="float" value="0.75"/></combine>',
     '<combine2 name="n" type="vector2"><input name="in1" type="float" value="0.25"/>'
     '<input name="in2" type="float" value="0.75"/></combine2>'),
    ("separate of a color2 is separate2 of a vector2, its outr and outa outx and outy",
     '<constant name="k" type="color2"><parameter name="value" type="color2" value="0.2, 0.7"/></constant>'
     '<separate name="s" type="multioutput"><input name="in" type="color2" nodename="k"/></separate>'
     '<subtract name="n" type="float"><input name="in1" type="float" nodename="s" output="outa"/>'
     '<input name="in2" type="float" nodename="s" output="outr"/></subtract>',
     '<constant name="k" type="vector2"><input name="value" type="vector2" value="0.2, 0.7"/></constant>'
     '<separate2 name="s" type="multioutput"><input name="in" type="vector2" nodename="k"/></separate2>'
     '<subtract name="n" type="float"><input name="in1" type="float" nodename="s" output="outy"/>'
     '<input name="in2" type="float" nodename="s" output="outx"/></subtract>'),
    ("geomattrvalue is geompropvalue",
     '<geomattrvalue name="n" type="float" attrname="wetness"><parameter name="default" type="float" value="0.25"/>'
     '</geomattrvalue>',
     '<geompropvalue name="n" type="float" geomprop="wetness"><input name="default" type="float" value="0.25"/>'
     '</geompropvalue>'),
]


@pytest.mark.parametrize("rule, old, upgraded", STEP_1_37, ids=[r[0].split(":")[0] for r in STEP_1_37])
def test_1_36_nodes_are_their_1_37_signatures(gen, rule, old, upgraded):
    same_shader(gen, old, "1.36", upgraded, "n")


def test_1_36_corpus_document_generates_every_node(gen):
    """The TestSuite's syntax_1_36 shape: every node of a 1.36 document has a 1.39 definition."""
    text = doc("".join(old for _, old, _ in STEP_1_37), version="1.36")
    nodes = [e.name for e in parse_document(text).root.children]
    for name in nodes:
        rec = gen.prepare(text, element=name).emit()
        assert rec["stages"]["pixel"], name
    assert parse_document(text).root.child("s").category == "separate2"


def test_1_37_shaderref_bsdfs_and_channels_become_1_38_nodes(gen):
    old = '''<nodedef name="ND_paint" node="paint">
      <input name="tint" type="color3" value="0.18, 0.18, 0.18"/><input name="ior" type="float" value="1.5"/>
      <output name="out" type="surfaceshader"/></nodedef>
    <nodegraph name="NG_paint" nodedef="ND_paint">
      <diffuse_brdf name="diffuse" type="BSDF"><input name="color" type="color3" interfacename="tint"/></diffuse_brdf>
      <multiply name="f0" type="float"><input name="in1" type="float" interfacename="ior"/><input name="in2" type="float" value="0.1"/></multiply>
      <generalized_schlick_brdf name="spec" type="BSDF"><input name="color0" type="color3" nodename="f0" channels="rrr"/>
        <input name="base" type="BSDF" nodename="diffuse"/></generalized_schlick_brdf>
      <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="spec"/></surface>
      <output name="out" type="surfaceshader" nodename="surf"/></nodegraph>
    <material name="m"><shaderref name="sr" node="paint"><bindinput name="tint" type="color3" value="0.2, 0.2, 0.6"/></shaderref></material>'''
    upgraded = '''<nodedef name="ND_paint" node="paint">
      <input name="tint" type="color3" value="0.18, 0.18, 0.18"/><input name="ior" type="float" value="1.5"/>
      <output name="out" type="surfaceshader"/></nodedef>
    <nodegraph name="NG_paint" nodedef="ND_paint">
      <oren_nayar_diffuse_bsdf name="diffuse" type="BSDF"><input name="color" type="color3" interfacename="tint"/></oren_nayar_diffuse_bsdf>
      <multiply name="f0" type="float"><input name="in1" type="float" interfacename="ior"/><input name="in2" type="float" value="0.1"/></multiply>
      <convert name="f0_rrr" type="color3"><input name="in" type="float" nodename="f0"/></convert>
      <generalized_schlick_bsdf name="spec_top" type="BSDF"><input name="color0" type="color3" nodename="f0_rrr"/></generalized_schlick_bsdf>
      <layer name="spec" type="BSDF"><input name="top" type="BSDF" nodename="spec_top"/><input name="base" type="BSDF" nodename="diffuse"/></layer>
      <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="spec"/></surface>
      <output name="out" type="surfaceshader" nodename="surf"/></nodegraph>
    <paint name="sr" type="surfaceshader"><input name="tint" type="color3" value="0.2, 0.2, 0.6"/></paint>
    <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="sr"/></surfacematerial>'''
    same_shader(gen, old, "1.37", upgraded, "m")


def test_atan2_inputs_across_1_38_and_1_39(gen):
    """1.38 swapped atan2's inputs and 1.39 named them: a 1.37 in1 is x, a 1.38 in1 is y."""
    node = '<atan2 name="n" type="float"><input name="in1" type="float" value="0.5"/><input name="in2" type="float" value="1.0"/></atan2>'
    same_shader(gen, node, "1.37", '<atan2 name="n" type="float"><input name="inx" type="float" value="0.5"/>'
                '<input name="iny" type="float" value="1.0"/></atan2>', "n")
    same_shader(gen, node, "1.38", '<atan2 name="n" type="float"><input name="iny" type="float" value="0.5"/>'
                '<input name="inx" type="float" value="1.0"/></atan2>', "n")


def test_1_38_thin_film_layer_and_subsurface_radius_become_1_39_inputs(gen):
    old = '''<thin_film_bsdf name="film" type="BSDF"><input name="thickness" type="float" value="550"/>
      <input name="ior" type="float" value="1.4"/></thin_film_bsdf>
    <dielectric_bsdf name="glass" type="BSDF"><input name="ior" type="float" value="1.6"/></dielectric_bsdf>
    <layer name="coated" type="BSDF"><input name="top" type="BSDF" nodename="film"/><input name="base" type="BSDF" nodename="glass"/></layer>
    <subsurface_bsdf name="sss" type="BSDF"><input name="radius" type="vector3" value="1.0, 0.5, 0.25"/></subsurface_bsdf>
    <mix name="b" type="BSDF"><input name="fg" type="BSDF" nodename="coated"/><input name="bg" type="BSDF" nodename="sss"/>
      <input name="mix" type="float" value="0.5"/></mix>
    <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="b"/></surface>
    <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>'''
    upgraded = '''<dielectric_bsdf name="glass" type="BSDF"><input name="ior" type="float" value="1.6"/>
      <input name="thinfilm_thickness" type="float" value="550"/><input name="thinfilm_ior" type="float" value="1.4"/></dielectric_bsdf>
    <convert name="radius" type="color3"><input name="in" type="vector3" value="1.0, 0.5, 0.25"/></convert>
    <subsurface_bsdf name="sss" type="BSDF"><input name="radius" type="color3" nodename="radius"/></subsurface_bsdf>
    <mix name="b" type="BSDF"><input name="fg" type="BSDF" nodename="glass"/><input name="bg" type="BSDF" nodename="sss"/>
      <input name="mix" type="float" value="0.5"/></mix>
    <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="b"/></surface>
    <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>'''
    same_shader(gen, old, "1.38", upgraded, "m")
    upgraded_doc = parse_document(doc(old, version="1.38"))
    assert upgraded_doc.root.child("film") is None and upgraded_doc.root.child("coated") is None


def test_a_lobe_alone_is_an_error_record_not_a_crash(gen):
    """A BSDF node as the element once raised a KeyError in emission (TestSuite's lama documents)."""
    from shadergen.errors import ShaderGenError
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(doc('<dielectric_bsdf name="d" type="BSDF"/>'), element="d").emit()
    assert e.value.code == "unsupported_output"
