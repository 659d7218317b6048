"""Issue 21, names and values on the live service: a USD prim named `Ω材質` answered 200 with GLSL
that did not compile, and its thumbnail 422 `compile_error`, blaming the client; a value of 1e39
answered 200 with WGSL that naga refuses. Now every record the service answers for hostile names
compiles with its target's checker and draws, and a value beyond 32 bits is the client's
`invalid_value`, naming the input."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import pytest
from pxr import Sdf, Usd, UsdShade

from name_cases import CONTENT_TYPES, TARGETS, ShaderChecker, name_cases
from service_testing import Server, assert_error, document, is_png

USDA = {"content-type": "model/vnd.usda"}


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("names"), workers=1, render_workers=1)
    yield srv
    srv.close()


@pytest.fixture(scope="module")
def checker():
    from required_tools import missing
    return ShaderChecker(on_missing=missing)


def unicode_layer() -> bytes:
    stage = Usd.Stage.CreateInMemory()
    material = UsdShade.Material.Define(stage, "/World/Ω材質")
    surface = UsdShade.Shader.Define(stage, "/World/Ω材質/Surface")
    surface.CreateIdAttr("UsdPreviewSurface")
    surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.25)
    surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set((0.8, 0.2, 0.1))
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    return stage.GetRootLayer().ExportToString().encode()


def test_a_unicode_prim_generates_code_that_compiles_in_every_target(server, checker):
    records = []
    for target in TARGETS:
        r = server.client.post("/v1/generate", params={"target": target, "names": "document"}, content=unicode_layer(),
                               headers=USDA)
        assert r.status_code == 200, r.text
        records.append(("Ω材質", r.json()))
    assert not checker.problems(records)
    assert records[0][1]["element"] == "/World/Ω材質"


def test_a_unicode_prim_draws_a_thumbnail(server, renderer_required):
    r = server.client.post("/v1/thumbnails", params={"size": 32}, content=unicode_layer(), headers=USDA)
    assert r.status_code == 200, r.text
    assert is_png(r.content, 32)


def test_hostile_names_over_http_generate_compile_and_draw(server, checker, renderer_required):
    cases = list(name_cases(seed=2121, count=8))
    records = []
    for case in cases:
        headers = {"content-type": CONTENT_TYPES[case.format]}
        for target in TARGETS:
            # document names: the hostile names reach the source only so
            r = server.client.post("/v1/generate", params={"target": target, "interface": "specialized",
                                                           "names": "document"},
                                   content=case.document, headers=headers)
            assert r.status_code == 200, f"{case.label}: {r.text[:500]}"
            records.append((case.label, r.json()))
        if case.format == "mtlx":  # thumbnails take MaterialX in JSON
            r = server.client.post("/v1/thumbnails", json={"document": case.document.decode(), "size": 16})
        else:
            r = server.client.post("/v1/thumbnails", params={"size": 16}, content=case.document, headers=headers)
        assert r.status_code == 200, f"{case.label}: {r.text[:500]}"
        assert is_png(r.content, 16)
    assert not checker.problems(records)


@pytest.mark.parametrize("interface", ["complete", "specialized"])
def test_a_value_beyond_float32_is_the_clients_invalid_value(server, interface):
    text = document("ramp.mtlx")
    assert 'value="0.5"' in text
    r = server.client.post("/v1/generate", json={"document": text.replace('value="0.5"', 'value="1e39"', 1),
                                                 "target": "wgsl", "interface": interface})
    error = assert_error(r, 422, "invalid_value")
    assert "32-bit float" in error["message"] and error["where"]
