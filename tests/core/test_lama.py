"""Pixar's Lama nodes (libraries/bxdf/lama_*.mtlx): every Lama node definition generates for glsl,
essl and wgsl, glslangValidator compiles the GLSL and ESSL, the WGSL validator accepts the WGSL, and
the complete interface publishes exactly the inputs the document sets on the node, as the reference
generator does (TestSuite/pbrlib/surfaceshader/lama sets each one)."""
import pytest

from .conftest import doc, glslang, needs_glslang
from .test_wgsl import validator  # noqa: F401  (the session's WGSL validator fixture)

CLOSURE_TYPES = {"BSDF", "EDF"}
# a closure input is fed by another Lama node of its type
FEEDERS = {"BSDF": '<LamaDiffuse name="feed_bsdf" type="BSDF"><input name="color" type="color3" value="0.5, 0.4, 0.3"/></LamaDiffuse>',
           "EDF": '<LamaEmission name="feed_edf" type="EDF"><input name="color" type="color3" value="0.2, 0.2, 0.1"/></LamaEmission>'}


def lama_nodedefs():
    from shadergen.library import default_library

    return sorted((nd for nd in default_library().nodedefs.values() if "lama_defs" in (nd.source or "")),
                  key=lambda nd: nd.name)


def set_inputs(nodedef) -> list:
    """The inputs a document sets: every one with a value (geometric ones keep their default geomprop)."""
    return [i for i in nodedef.children_of("input") if i.get("type") not in CLOSURE_TYPES and i.get("value") is not None]


def document_for(nodedef) -> str:
    """The node `n` with every input set, closures fed by other Lama nodes, under a material."""
    out_type = nodedef.children_of("output")[0].get("type")
    inputs, feeders = [], set()
    for i in nodedef.children_of("input"):
        if i.get("type") in CLOSURE_TYPES:
            feeders.add(i.get("type"))
            inputs.append(f'<input name="{i.name}" type="{i.get("type")}" nodename="feed_{i.get("type").lower()}"/>')
    inputs += [f'<input name="{i.name}" type="{i.get("type")}" value="{i.get("value")}"/>' for i in set_inputs(nodedef)]
    node = f'<{nodedef.get("node")} name="n" type="{out_type}" nodedef="{nodedef.name}">{"".join(inputs)}</{nodedef.get("node")}>'
    body = "".join(FEEDERS[t] for t in sorted(feeders)) + node
    if out_type != "material":
        body += (f'<surface name="srf" type="surfaceshader"><input name="{out_type.lower()}" type="{out_type}" nodename="n"/></surface>'
                 '<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="srf"/>'
                 '</surfacematerial>')
    return doc(body)


def test_every_lama_node_of_pixar_has_a_definition():
    names = {nd.get("node") for nd in lama_nodedefs()}
    assert names == {"LamaAdd", "LamaConductor", "LamaDielectric", "LamaDiffuse", "LamaEmission", "LamaGeneralizedSchlick",
                     "LamaIridescence", "LamaLayer", "LamaMix", "LamaSheen", "LamaSSS", "LamaSurface", "LamaTranslucent"}
    assert len(lama_nodedefs()) == 15  # LamaAdd and LamaMix for BSDF and EDF


@needs_glslang
@pytest.mark.parametrize("target", ["glsl", "essl"])
def test_every_lama_node_compiles(gen, target):
    failures = []
    for nd in lama_nodedefs():
        rec = gen.prepare(document_for(nd), target=target).emit()
        for stage in ("vertex", "pixel"):
            ok, log = glslang(rec["stages"][stage], stage)
            if not ok:
                failures.append(f"{nd.name} {stage}: {log[:300]}")
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("interface", ["complete", "specialized"])
def test_every_lama_node_validates_as_wgsl(gen, validator, interface):  # noqa: F811
    sources = {}
    for nd in lama_nodedefs():
        rec = gen.prepare(document_for(nd), target="wgsl", interface=interface).emit()
        sources.update({f"{nd.name}.{stage}": text for stage, text in rec["stages"].items()})
    assert len(sources) == 2 * len(lama_nodedefs())
    errors = validator(sources)
    assert not errors, "\n".join(f"{k}: {v[:300]}" for k, v in errors.items())


@pytest.mark.parametrize("target", ["glsl", "wgsl"])
def test_the_complete_interface_lists_the_inputs_the_document_sets(gen, target):
    for nd in lama_nodedefs():
        rec = gen.prepare(document_for(nd), target=target, interface="complete").emit()
        listed = {(u["path"], u["type"]) for u in rec["blocks"]["pixel"]["PublicUniforms"] if u["path"].startswith("n/")}
        assert listed == {(f"n/{i.name}", i.get("type")) for i in set_inputs(nd)}, nd.name
