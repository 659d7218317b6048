"""Closures (seed 3.5, 4): BSDF graphs evaluated once per shading context by the surface node."""
from .conftest import doc, glslang, needs_glslang

MATERIAL = '''
<noise2d name="pattern" type="float"/>
<oren_nayar_diffuse_bsdf name="diffuse" type="BSDF"><input name="roughness" type="float" nodename="pattern"/></oren_nayar_diffuse_bsdf>
<dielectric_bsdf name="coat" type="BSDF"><input name="weight" type="float" value="0.5"/></dielectric_bsdf>
<layer name="layered" type="BSDF"><input name="top" type="BSDF" nodename="coat"/><input name="base" type="BSDF" nodename="diffuse"/></layer>
<uniform_edf name="glow" type="EDF"><input name="color" type="color3" value="0.1, 0.2, 0.3"/></uniform_edf>
<surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="layered"/><input name="edf" type="EDF" nodename="glow"/></surface>
<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>
'''


def main_of(rec):
    src = rec["stages"]["pixel"]
    return src[src.index("void main()"):]


def test_each_context_evaluates_the_closures_data_nodes_once(gen):
    rec = gen.prepare(doc(MATERIAL), names="document").emit()
    main = main_of(rec)
    assert main.count("mx_noise2d") == 1  # data feeding the BSDFs: computed once, before the contexts
    for context in ("CLOSURE_TYPE_INDIRECT", "CLOSURE_TYPE_TRANSMISSION", "CLOSURE_TYPE_EMISSION"):
        assert f"ClosureData({context}" in main
    contexts = main.count("ClosureData(CLOSURE_TYPE_") - main.count("ClosureData(CLOSURE_TYPE_DEFAULT")
    assert main.count("mx_oren_nayar_diffuse_bsdf(closureData") == contexts - 1  # every BSDF context but emission
    assert main.count("mx_uniform_edf(closureData") == 1
    assert main.index("mx_noise2d") < main.index("ClosureData(")


def test_a_lobe_with_a_preparation_is_prepared_once_before_the_contexts(gen):
    main = main_of(gen.prepare(doc(MATERIAL), names="document").emit())
    assert main.count("mx_dielectric_bsdf_prepare(pointData, coat_weight,") == 1
    prepared = main.index("mx_dielectric_bsdf_prepare(")
    assert prepared < main.index("ClosureData(CLOSURE_TYPE_REFLECTION")
    calls = [line.strip() for line in main.splitlines() if "mx_dielectric_bsdf(" in line]
    assert len(calls) == 3 and all(c == "mx_dielectric_bsdf(closureData, coat_lobe, coat_out);" for c in calls)
    assert main.count("mx_oren_nayar_diffuse_bsdf_prepare") == 0  # a lobe without one takes its inputs per context


def test_unconnected_closures_write_no_context(gen):
    rec = gen.prepare(doc('<surface name="surf" type="surfaceshader"/>'
                          '<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" '
                          'nodename="surf"/></surfacematerial>')).emit()
    assert "ClosureData(" not in main_of(rec)


@needs_glslang
def test_closure_shaders_compile(gen):
    for target in ("glsl", "essl"):
        rec = gen.prepare(doc(MATERIAL), target=target).emit()
        for stage, src in rec["stages"].items():
            ok, log = glslang(src, stage)
            assert ok, log
