"""Issue 21, item 1: a USD upload opens no file outside itself, whatever field names it. Each arc
kind is aimed, in a text layer and in a usdz package, at a secret file outside the upload (whose
every line quotes a secret, so any error usd-core made of it would carry it), at a FIFO (which
blocks whoever opens it) and at a path that does not exist: the three answers must be the same
refusal apart from the path, and the secret appears in no answer and no server log. A search path
that holds the secret is set too, for the paths usd-core would look up there. Uploads whose arcs
stay inside still compose."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import os
import re
from pathlib import Path

import pytest
from pxr import Sdf

from service_testing import Server

SECRET = "SECRET-d41c-confinement"
USDA = {"content-type": "model/vnd.usda"}
USDZ = {"content-type": "model/vnd.usdz+zip"}
NAMES = ("secret", "fifo", "nosuchfile")  # an existing file, one that blocks its reader, none


@pytest.fixture(scope="module")
def outside(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("outside")
    for stem in ("secret", "secret.1"):  # `secret.1` is what the clip template `secret.#` expands to
        (folder / f"{stem}.usda").write_text(f'#usda 1.0\ndef "Leak" {{\n    {SECRET} {SECRET}\n}}\n')
        (folder / f"{stem}.mtlx").write_text(f"<{SECRET}>\n")
    for stem in ("fifo", "fifo.1"):
        os.mkfifo(folder / f"{stem}.usda")
        os.mkfifo(folder / f"{stem}.mtlx")
    return folder


@pytest.fixture(scope="module")
def server(tmp_path_factory, outside):
    srv = Server(tmp_path_factory.mktemp("confine"), workers=1, render_workers=1,
                 env={"PXR_AR_DEFAULT_SEARCH_PATH": str(outside)})
    yield srv
    srv.close()


def material(prim_metadata: str = "", body: str = "", layer_metadata: str = "") -> str:
    """A layer with one UsdPreviewSurface material; the shader prim carries the arc under test."""
    return f"""#usda 1.0
(
{layer_metadata}
)
def Material "M"
{{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S" (
{prim_metadata}
    )
    {{
        uniform token info:id = "UsdPreviewSurface"
        token outputs:surface
        float inputs:roughness = 0.5
{body}
    }}
}}
"""


def clips(entries: str) -> str:
    return f"""        clips = {{
            dictionary default = {{
                string primPath = "/M/S"
{entries}
            }}
        }}"""


# Each arc kind: a layer naming `path` in that field. The path is a whole file path; the clip
# template names its files by pattern (`secret.#.usda`), which the template kind writes itself.
ARCS = {
    "sublayer": lambda p: material(layer_metadata=f"    subLayers = [@{p}@]"),
    "reference": lambda p: material(f"        references = @{p}@</Leak>"),
    "payload": lambda p: material(f"        payload = @{p}@</Leak>"),
    "clip_asset_paths": lambda p: material(clips(f"""                asset[] assetPaths = [@{p}@]
                double2[] active = [(0, 0)]
                double2[] times = [(0, 0)]""")),
    "clip_manifest": lambda p: material(clips(f"""                asset manifestAssetPath = @{p}@
                asset[] assetPaths = []""")),
    "clip_template": lambda p: material(clips(f"""\
                string templateAssetPath = "{p.replace('.usda', '.#.usda')}"
                double templateStartTime = 1
                double templateEndTime = 1
                double templateStride = 1""")),
    "asset_metadata": lambda p: material(f"        assetInfo = {{ asset identifier = @{p}@ }}"),
    "custom_data_asset": lambda p: material(layer_metadata=f"    customLayerData = {{ asset notes = @{p}@ }}"),
    "variant": lambda p: material(
        '        variants = { string look = "outside" }\n        prepend variantSets = "look"',
        f'        variantSet "look" = {{\n            "outside" ( references = @{p}@</Leak> ) {{ }}\n        }}'),
    "package_relative_texture": lambda p: material(
        body=f"        asset inputs:file = @{p.replace('.usda', '.usdz')}[t.png]@"),
    "reference_spelled_as_textures": lambda p: material(f"        references = @{p}@</Leak>",
                                                        f"        asset[] inputs:t = [@{p}@, @{p}@]"),
    "expression": lambda p: material(f'        references = @`"${{DIR}}/{Path(p).name}"`@</Leak>',
                                     layer_metadata=f'    expressionVariables = {{ string DIR = "{Path(p).parent}" }}'),
    "mtlx_reference": lambda p: material(
        f"        references = @{p.replace('.usda', '.mtlx')}@</MaterialX/Materials/M>"),
}


def package(folder: Path, members: list[tuple[str, bytes | str]]) -> bytes:
    """A usdz of these members, the first its root layer."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "upload.usdz"
    writer = Sdf.ZipFileWriter.CreateNew(str(path))
    for name, data in members:
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_bytes(data.encode() if isinstance(data, str) else data)
        writer.AddFile(str(folder / name), name)
    writer.Save()
    return path.read_bytes()


def crate(folder: Path, text: str) -> bytes:
    """The layer as a binary crate file (usdc)."""
    layer = Sdf.Layer.CreateAnonymous(".usda")
    layer.ImportFromString(text)
    folder.mkdir(parents=True, exist_ok=True)
    assert layer.Export(str(folder / "root.usdc"))
    return (folder / "root.usdc").read_bytes()


def answers(server, bodies: dict[str, tuple[str, bytes | str, dict]]) -> dict[str, tuple[int, str]]:
    """Each upload's (status, body with the outside path it names written as <path>)."""
    out = {}
    for name, (path, body, headers) in bodies.items():
        r = server.client.post("/v1/generate", content=body, headers=headers, timeout=60)
        assert SECRET not in r.text and "shadergen-usdz-" not in r.text, (name, r.text)  # nor the server's folders
        assert 400 <= r.status_code < 500 and set(r.json()) == {"document", "element", "target", "error"}, r.text
        out[name] = r.status_code, r.text
    return {name: (status, text.replace(bodies[name][0].replace(".usda", ""), "<path>"))
            for name, (status, text) in out.items()}


def assert_same_refusal(server, bodies) -> None:
    got = answers(server, bodies)
    first = next(iter(got.values()))
    assert all(answer == first for answer in got.values()), got
    assert SECRET not in server.log_text()


@pytest.mark.parametrize("kind", sorted(ARCS))
def test_uploaded_layer_opens_nothing_outside(server, outside, kind):
    paths = {name: str(outside / f"{name}.usda") for name in NAMES}
    assert_same_refusal(server, {name: (p, ARCS[kind](p), USDA) for name, p in paths.items()})


@pytest.mark.parametrize("kind", sorted(ARCS))
@pytest.mark.parametrize("spelling", ["absolute", "relative"])
def test_package_opens_nothing_outside(server, outside, tmp_path, kind, spelling):
    """The root layer of a usdz names the outside file by its absolute path or by climbing out."""
    bodies = {}
    for name in NAMES:
        path = str(outside / f"{name}.usda")
        if spelling == "relative":
            path = "../" * 12 + path.lstrip("/")
        bodies[name] = path, package(tmp_path / name, [("root.usda", ARCS[kind](path))]), USDZ
    assert_same_refusal(server, bodies)


@pytest.mark.parametrize("kind", ["reference", "clip_asset_paths", "clip_template", "sublayer"])
def test_crate_layer_in_a_package_opens_nothing_outside(server, outside, tmp_path, kind):
    bodies = {}
    for name in NAMES:
        path = str(outside / f"{name}.usda")
        bodies[name] = path, package(tmp_path / name, [("root.usdc", crate(tmp_path / name, ARCS[kind](path)))]), USDZ
    assert_same_refusal(server, bodies)


def test_nested_package_opens_nothing_outside(server, outside, tmp_path):
    """A package inside the package, whose layer climbs out of both."""
    bodies = {}
    for name in NAMES:
        path = "../" * 12 + str(outside / f"{name}.usda").lstrip("/")
        inner = package(tmp_path / name / "inner", [("inner.usda", ARCS["reference"](path))])
        root = '#usda 1.0\ndef "Top" ( references = @./inner.usdz@ ) { }\n'
        bodies[name] = path, package(tmp_path / name, [("root.usda", root), ("inner.usdz", inner)]), USDZ
    assert_same_refusal(server, bodies)


def test_member_no_arc_names_is_checked_too(server, outside, tmp_path):
    """A layer member that only a clip template would reach (`clip.1.usda` of `clip.#.usda`)."""
    bodies = {}
    for name in NAMES:
        path = str(outside / f"{name}.usda")
        template = material(clips('''                string templateAssetPath = "./clip.#.usda"
                double templateStartTime = 1
                double templateEndTime = 1
                double templateStride = 1'''))
        bodies[name] = path, package(tmp_path / name, [("root.usda", template),
                                                      ("clip.1.usda", ARCS["sublayer"](path))]), USDZ
    assert_same_refusal(server, bodies)


@pytest.mark.parametrize("kind", ["reference", "sublayer", "clip_asset_paths"])
def test_search_path_is_not_looked_up(server, outside, tmp_path, kind):
    """`secret.usda`, no member of the package, is in the server's search path (and `fifo.usda`)."""
    bodies = {name: (f"{name}.usda", package(tmp_path / name, [("root.usda", ARCS[kind](f"{name}.usda"))]), USDZ)
              for name in NAMES}
    assert_same_refusal(server, bodies)


BRICK_MTLX = """<?xml version="1.0"?>
<materialx version="1.39">
  <standard_surface name="surface" type="surfaceshader">
    <input name="base_color" type="color3" value="0.6, 0.2, 0.1" />
  </standard_surface>
  <surfacematerial name="Brick" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="surface" />
  </surfacematerial>
</materialx>
"""


def generated(server, body: bytes, headers=USDZ) -> dict:
    r = server.client.post("/v1/generate", content=body, headers=headers, timeout=60)
    assert r.status_code == 200, r.text
    return r.json()


def test_arcs_inside_the_package_compose(server, tmp_path):
    """Sublayers, references (search-relative ones naming a member too, and one to a MaterialX
    document), a nested package and a clip whose layer is a member: all inside, so they generate."""
    looks = material().replace('def Material "M"', 'def Material "Looks"').replace("</M/S", "</Looks/S")
    cases = {
        "sublayer": [("root.usda", '#usda 1.0\n(\n    subLayers = [@./looks/looks.usda@]\n)\n'),
                     ("looks/looks.usda", looks)],
        "search_relative_member": [("root.usda", '#usda 1.0\ndef "World" ( references = @looks.usda@</Looks> ) { }\n'),
                                   ("looks.usda", looks)],
        "nested": [("root.usda", '#usda 1.0\ndef "World" ( references = @./inner.usdz@</Looks> ) { }\n'),
                   ("inner.usdz", package(tmp_path / "inner", [("inner.usda", looks)]))],
        "clip": [("root.usda", material(clips('''                asset[] assetPaths = [@./clip.usda@]
                double2[] active = [(0, 0)]
                double2[] times = [(0, 0)]'''))),
                 ("clip.usda", '#usda 1.0\nover "M"\n{\n    over "S"\n    {\n'
                               '        float inputs:roughness = 0.25\n    }\n}\n')],
        "mtlx": [("root.usda", '#usda 1.0\ndef Material "Brick" '
                               '( references = @./brick.mtlx@</MaterialX/Materials/Brick> ) { }\n'),
                 ("brick.mtlx", BRICK_MTLX)],
    }
    for name, members in cases.items():
        record = generated(server, package(tmp_path / name, members))
        assert "shadergen-usdz-" not in str(record["warnings"]), record["warnings"]
        assert record["element"] in ("/Looks", "/World", "/M", "/Brick"), (name, record["element"])


# an address in the server's heap as usd-core writes one (`anon:0x55d0c3a4b2c0:.usda`, `<0x55d0c3a4b2c0>`)
ADDRESS = re.compile(r"0x[0-9a-fA-F]{4,}")
COMPOSITION_ERRORS = {  # what each one still tells the client (each its own metallic: its own graph)
    "cycle": (material("        references = </M/S>", "        float inputs:metallic = 0.1"), "Cycle detected"),
    "unresolved": (material("        references = </Nowhere>", "        float inputs:metallic = 0.2"),
                   "Unresolved reference prim path"),
    "relocation": (material(body="        float inputs:metallic = 0.3",
                            layer_metadata="    relocates = { </M/S>: </M/S> }"), "Relocation from </M/S>"),
}


@pytest.mark.parametrize("kind", sorted(COMPOSITION_ERRORS))
def test_messages_hold_no_address_of_the_server(server, tmp_path, kind):
    """usd-core names an uploaded text layer, and every stage's session layer, by its address in the
    server's memory (`anon:0x55d0c3a4b2c0:.usda`); its composition errors, which a record lists as
    warnings, quoted those addresses, which tell a client where the generator's heap lies. The
    warning is still given, with the layer named as `anon:0x:.usda`."""
    layer, told = COMPOSITION_ERRORS[kind]
    for body, headers in [(layer, USDA), (package(tmp_path, [("root.usda", layer)]), USDZ)]:
        record = generated(server, body, headers)
        assert any(told in warning for warning in record["warnings"]), record["warnings"]
        assert not ADDRESS.search(str(record["warnings"])), record["warnings"]


def test_a_record_carries_no_other_uploads_warnings(server):
    """Records are cached by graph hash, which two uploads share when they translate to the same
    graph; a record's warnings are its own upload's, though (a composition error quotes that
    upload's layers). The second upload was answered with the first one's warnings, from the
    generator and then from the API's cache of byte-identical requests: one client reading what
    another client's layer said."""
    other = material("        references = </PlansOfAnotherClient>", "        float inputs:metallic = 0.7")
    own = material(body="        float inputs:metallic = 0.7")
    assert "PlansOfAnotherClient" in str(generated(server, other, USDA)["warnings"])
    for attempt in range(2):  # a new request, then the same bytes again
        record = generated(server, own, USDA)
        assert record["warnings"] == [], (attempt, record["warnings"])
    assert "PlansOfAnotherClient" in str(generated(server, other, USDA)["warnings"])
    # the shared record evicted and stored again by the other upload: the API's cache of the
    # first one's bytes still leads to that record
    from service.cache import open_store

    open_store(f"sqlite:///{server.cache_path}", 1 << 30).delete("rec:" + record["hash"])
    assert "PlansOfAnotherClient" in str(generated(server, other, USDA)["warnings"])
    assert generated(server, own, USDA)["warnings"] == []
