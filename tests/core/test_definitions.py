"""Definitions a document brings: implementations by nodegraph name, inheritance, self-reference."""
import time

import pytest

from shadergen.errors import ShaderGenError

from .conftest import doc

TINT = ('<nodedef name="ND_tint" node="tint"><input name="in" type="float" value="1"/>'
        '<output name="out" type="float"/></nodedef>')


def error_of(gen, text: str) -> ShaderGenError:
    with pytest.raises(ShaderGenError) as e:
        gen.prepare(text).emit()
    return e.value


def test_implementation_naming_a_nodegraph(gen):
    text = doc(TINT + '<nodegraph name="NG_half"><multiply name="m" type="float">'
               '<input name="in1" type="float" interfacename="in"/><input name="in2" type="float" value="0.5"/>'
               '</multiply><output name="out" type="float" nodename="m"/></nodegraph>'
               '<implementation name="IM_tint" nodedef="ND_tint" nodegraph="NG_half"/>'
               '<tint name="t" type="float"><input name="in" type="float" value="3"/></tint>'
               '<output name="o" type="float" nodename="t"/>')
    pixel = gen.prepare(text, element="o").emit()["stages"]["pixel"]
    assert "* 0.5" in pixel


def test_implementation_naming_a_missing_nodegraph(gen):
    text = doc(TINT + '<implementation name="IM_tint" nodedef="ND_tint" nodegraph="NG_nowhere"/>'
               '<tint name="t" type="float"/><output name="o" type="float" nodename="t"/>')
    err = error_of(gen, text)
    assert err.code == "unknown_implementation" and "NG_nowhere" in err.message


def test_both_standard_surface_versions_share_one_network(gen):
    from shadergen.library import default_library
    lib = default_library()
    scope_graph = {nd: gen.prepare(doc(
        f'<standard_surface name="s" type="surfaceshader" nodedef="{nd}"/>'
        '<surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/>'
        '</surfacematerial>')).graph for nd in ("ND_standard_surface_surfaceshader",
                                                "ND_standard_surface_surfaceshader_100")}
    impls = {nd: next(n.instance.graph_elem for n in g.nodes if n.instance is not None)  # the expanded body
             for nd, g in scope_graph.items()}
    assert impls["ND_standard_surface_surfaceshader"] is impls["ND_standard_surface_surfaceshader_100"]
    assert sum(1 for g in lib.nodegraphs.values() if g.name.startswith("NG_standard_surface")) == 1


@pytest.mark.parametrize("nodedefs, named", [
    ('<nodedef name="ND_self" node="selfish" inherit="ND_self"><output name="out" type="float"/></nodedef>',
     "ND_self -> ND_self"),
    ('<nodedef name="ND_a" node="selfish" inherit="ND_b"><output name="out" type="float"/></nodedef>'
     '<nodedef name="ND_b" node="other" inherit="ND_a"><output name="out" type="float"/></nodedef>',
     "ND_a -> ND_b -> ND_a"),
])
def test_inheritance_cycle_is_found_at_once(gen, nodedefs, named):
    text = doc(nodedefs + '<selfish name="n" type="float"/><output name="o" type="float" nodename="n"/>')
    t0 = time.perf_counter()
    err = error_of(gen, text)
    assert err.code == "cycle" and named in err.message
    assert time.perf_counter() - t0 < 0.5  # not a bound on speed: the old code spent seconds before a too_large


SELF_GRAPH = ('<nodegraph name="NG_tint" nodedef="ND_tint"><tint name="again" type="float">'
              '<input name="in" type="float" interfacename="in"/></tint>'
              '<output name="out" type="float" nodename="again"/></nodegraph>')


@pytest.mark.parametrize("uses", [1, 2])  # written in place, or as a function
def test_nodegraph_that_instantiates_its_own_node_is_a_cycle(gen, uses):
    nodes = "".join(f'<tint name="t{i}" type="float"/>' for i in range(uses))
    add = '<add name="sum" type="float"><input name="in1" type="float" nodename="t0"/>' + (
        '<input name="in2" type="float" nodename="t1"/>' if uses == 2 else '') + '</add>'
    err = error_of(gen, doc(TINT + SELF_GRAPH + nodes + add + '<output name="o" type="float" nodename="sum"/>'))
    assert err.code == "cycle" and "NG_tint -> NG_tint" in err.message


def test_nodegraph_that_reaches_itself_through_another_definition_is_a_cycle(gen):
    other = ('<nodedef name="ND_shade" node="shade"><input name="in" type="float" value="1"/>'
             '<output name="out" type="float"/></nodedef>'
             '<nodegraph name="NG_shade" nodedef="ND_shade"><tint name="inner" type="float">'
             '<input name="in" type="float" interfacename="in"/></tint>'
             '<output name="out" type="float" nodename="inner"/></nodegraph>'
             '<nodegraph name="NG_tint" nodedef="ND_tint"><shade name="inner" type="float">'
             '<input name="in" type="float" interfacename="in"/></shade>'
             '<output name="out" type="float" nodename="inner"/></nodegraph>')
    err = error_of(gen, doc(TINT + other + '<tint name="t" type="float"/><output name="o" type="float" nodename="t"/>'))
    assert err.code == "cycle" and "NG_tint -> NG_shade -> NG_tint" in err.message
