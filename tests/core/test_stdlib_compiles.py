"""Every standard-library node definition generates a shader that glslangValidator accepts, for
both targets: one document per nodedef, all inputs left at their defaults."""
import pytest

from .conftest import doc, glslang, needs_glslang

# closures and shaders belong to the PBR library; a texture or string is not a drawable output
SKIP_TYPES = {"BSDF", "EDF", "VDF", "lightshader", "material", "volumeshader", "displacementshader", "filename",
              "string"}


def stdlib_nodedefs():
    from shadergen.library import default_library

    lib = default_library()
    out = []
    for nd in lib.nodedefs.values():
        if "stdlib" not in (nd.source or "") and "cmlib" not in (nd.source or ""):
            continue
        outs = nd.children_of("output")
        if len(outs) != 1 or outs[0].get("type") in SKIP_TYPES | {"surfaceshader"} and nd.get("node") != "surface_unlit":
            continue
        out.append(nd)
    return out


@needs_glslang
@pytest.mark.parametrize("target", ["glsl", "essl"])
def test_every_stdlib_nodedef_compiles(gen, target):
    failures = []
    nodedefs = stdlib_nodedefs()
    assert len(nodedefs) > 600
    for nd in nodedefs:
        t = nd.children_of("output")[0].get("type")
        text = doc(f'<{nd.get("node")} name="n" type="{t}" nodedef="{nd.name}"/><output name="o" type="{t}" nodename="n"/>')
        try:
            rec = gen.prepare(text, target=target).emit()
        except Exception as e:  # noqa: BLE001 - collected and reported below
            failures.append(f"{nd.name}: {e}")
            continue
        ok, log = glslang(rec["stages"]["pixel"], "pixel")
        if not ok:
            failures.append(f"{nd.name}: {log[:300]}")
    assert not failures, f"{len(failures)} failures:\n" + "\n".join(failures[:20])
