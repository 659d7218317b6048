"""Issue 21, item 2 (sizes): what an upload makes the live service read is bounded before it is read.
A usdz whose texture is a deflate bomb (256 MiB of zeros in a 260 kB body) is refused as not a
valid usdz, and no process of the server reaches a higher peak of memory by anything like the
bomb's size; a package whose directory lies about a member's size is refused; a PNG whose header
declares 60000 x 60000 pixels is refused as too_large, in a package and in the texture roots; a
deep image is refused unread; a legitimate package still renders its own texture. Member names
that usd-core and zipfile read differently (twice the same, or holding a NUL byte, which answered
500) are refused before either reads the package."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import pytest

from faults_testing import poll_job, processes, wait_ready
from hostile_packages import LAYER, deep_exr, deflate_bomb_package, huge_png_header, nested_references, png, \
    textured_layer, usdz, with_directory_size
from processes import descendants, peak_rss_kib
from service_testing import Server, assert_error, is_png

pytestmark = pytest.mark.usefixtures("renderer_required")

USDZ = {"content-type": "model/vnd.usdz+zip"}
TEXTURE = "textures/wood.png"
BOMB_BYTES = 256 << 20
HUGE = 60000


@pytest.fixture(scope="module")
def roots(tmp_path_factory):
    folder = tmp_path_factory.mktemp("roots")
    (folder / "huge.png").write_bytes(huge_png_header(HUGE, HUGE))
    return folder


@pytest.fixture(scope="module")
def server(tmp_path_factory, roots):
    srv = Server(tmp_path_factory.mktemp("uploadbounds"), workers=1, render_workers=1,
                 env={"SHADERGEN_TEXTURE_ROOTS": str(roots)})
    yield srv
    srv.close()


@pytest.fixture(scope="module")
def warm(server) -> None:
    """A legitimate package drawn first: every process that reads uploads is started and has read
    one, so that peaks measured afterwards are the hostile uploads' alone."""
    wait_ready(server.client)
    assert_renders(server, textured_package(png(8, 8, (230, 20, 20))))


def peak_rss_kibs(server) -> dict[int, int]:
    """VmHWM (peak resident memory) of the server and of every process under it."""
    peaks = {pid: peak_rss_kib(pid) for pid in [server.proc.pid, *descendants(server.proc.pid)]}
    return {pid: peak for pid, peak in peaks.items() if peak is not None}  # none: gone since the listing


def textured_package(texture: bytes) -> bytes:
    return usdz([(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, texture)])


def assert_renders(server, package: bytes) -> bytes:
    r = server.client.post("/v1/thumbnails", params={"size": 48}, content=package, headers=USDZ)
    assert r.status_code == 200 and is_png(r.content, 48), r.text
    return r.content


def test_a_stored_package_renders_its_own_texture(server, warm):
    """Two packages that differ only in their texture's colour give two thumbnails (each its own)."""
    red = assert_renders(server, textured_package(png(8, 8, (230, 20, 20))))
    blue = assert_renders(server, textured_package(png(8, 8, (20, 20, 230))))
    assert red != blue


def test_a_deflate_bomb_member_is_refused_unread(server, warm):
    bomb = deflate_bomb_package(TEXTURE, BOMB_BYTES)
    assert len(bomb) < 1 << 20
    before = peak_rss_kibs(server)
    for route in ("/v1/generate", "/v1/thumbnails"):
        error = assert_error(server.client.post(route, content=bomb, headers=USDZ), 400, "invalid_document")
        assert error["where"] == TEXTURE and "compressed" in error["message"]
    after = peak_rss_kibs(server)
    assert set(after) == set(before)  # no process died or was replaced on the way
    growth_kib = {pid: after[pid] - before[pid] for pid in before}
    assert max(growth_kib.values()) * 1024 < BOMB_BYTES // 8, growth_kib
    assert "Traceback" not in server.log_text()


@pytest.mark.parametrize("local_header_too", [False, True])
def test_a_directory_that_understates_a_member_is_refused(server, warm, local_header_too):
    """In the directory only, the directory and the member's header disagree; in both, the rest of
    the member lies unlisted before the directory: either way found before usd-core reads the upload."""
    lying = with_directory_size(textured_package(png(64, 64, (20, 20, 230))), TEXTURE, 100, local_header_too)
    error = assert_error(server.client.post("/v1/thumbnails", content=lying, headers=USDZ), 400, "invalid_document")
    assert error["where"] == TEXTURE


def test_a_huge_image_header_is_refused_in_a_package(server, warm):
    package = textured_package(huge_png_header(HUGE, HUGE))
    error = assert_error(server.client.post("/v1/thumbnails", content=package, headers=USDZ), 413, "too_large")
    assert error["where"] == TEXTURE and "limit" in error["message"]
    # as a job: failed with the same error, and its thumbnail answered as that error
    accepted = server.client.post("/v1/thumbnails", params={"async": "true", "size": 40}, content=package,
                                  headers=USDZ)
    assert accepted.status_code == 202, accepted.text
    status = poll_job(server.client, accepted.json()["id"])
    assert status["state"] == "failed" and status["error"]["code"] == "too_large", status
    assert_error(server.client.get(f"/v1/jobs/{status['id']}/thumbnail"), 413, "too_large")


def test_a_deep_image_in_a_package_shows_the_default_colour_and_kills_nothing(server, warm):
    """A deep EXR once aborted the render worker (OpenImageIO's binding corrupts the heap reading one)."""
    workers = processes(server, "service.workers.render_worker")
    package = usdz([(LAYER, textured_layer("textures/deep.exr").encode()), ("textures/deep.exr", deep_exr())])
    assert_renders(server, package)
    assert processes(server, "service.workers.render_worker") == workers


def test_a_huge_image_header_is_refused_in_the_texture_roots(server, warm, roots):
    document = """<?xml version="1.0"?>
<materialx version="1.39">
  <image name="tex" type="color3"><input name="file" type="filename" value="huge.png" /></image>
  <output name="out" type="color3" nodename="tex" />
</materialx>"""
    r = server.client.post("/v1/thumbnails", json={"document": document, "size": 32})
    error = assert_error(r, 413, "too_large")
    assert error["where"] == "huge.png" and "limit" in error["message"]
    assert str(roots) not in r.text  # named as the document names it, not where the server keeps it
    assert "Traceback" not in server.log_text()


def with_nul(package: bytes, name: str) -> bytes:
    """The package with the name's `#` made a NUL byte, in both headers (no checksum covers names)."""
    return package.replace(name.encode(), name.replace("#", "\x00").encode())


@pytest.mark.filterwarnings("ignore:Duplicate name")  # zipfile's, writing the two members on purpose
@pytest.mark.parametrize("names", [(TEXTURE, TEXTURE), (LAYER, LAYER), ("textures/a#b.png", TEXTURE)])
def test_member_names_both_readers_cannot_agree_on_are_refused(server, warm, names):
    """Two members of one name (zipfile finds the last, usd-core the first: the layer the
    confinement checked need not be the one composed, the texture checked not the one drawn), or
    a name holding a NUL (written here as `#`; zipfile cuts the name there)."""
    members = [(LAYER, textured_layer(TEXTURE).encode()), (names[0], png(8, 8, (230, 20, 20))),
               (names[1], png(8, 8, (20, 20, 230)) if names[1] != LAYER else textured_layer(TEXTURE).encode())]
    package = usdz(members)
    if "#" in names[0]:  # in both headers (no checksum covers names)
        package = package.replace(names[0].encode(), names[0].replace("#", "\x00").encode())
    for route in ("/v1/generate", "/v1/thumbnails"):
        error = assert_error(server.client.post(route, content=package, headers=USDZ), 400, "invalid_document")
        assert error["where"] == names[0].split("#")[0], error
    assert "Traceback" not in server.log_text()


def test_a_member_without_extension_is_no_layer(server, warm):
    """Asked for the file format of a name with no extension (`LICENSE`), usd-core raised: a 500."""
    package = textured_package(png(8, 8, (230, 20, 20)))
    licensed = usdz([(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(8, 8, (230, 20, 20))),
                     ("LICENSE", b"CC0")])
    assert assert_renders(server, licensed) == assert_renders(server, package)


def test_a_package_of_more_layers_than_the_limit_is_refused_before_they_are_walked(server, warm):
    """Each layer member is opened and walked before the stage composes: a package of 15,000
    empty layers held a generator child for its whole time limit (504). Over the limit, 413."""
    from shadergen.usd_confine import MAX_PACKAGE_LAYERS

    members = [(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(8, 8, (230, 20, 20)))]
    empties = [(f"layers/{i}.usda", b"#usda 1.0\n") for i in range(MAX_PACKAGE_LAYERS)]
    r = server.client.post("/v1/generate", content=usdz(members + empties), headers=USDZ)
    assert_error(r, 413, "too_large")
    assert f"{MAX_PACKAGE_LAYERS + 1} layers" in r.json()["error"]["message"]
    assert assert_renders(server, usdz(members + empties[:-1]))


def test_a_small_layer_that_composes_to_millions_of_prims_is_refused_before_it_composes(server, warm):
    """2.4 kB of nested references (2 ** 19 prims) held a generator child until its time limit
    (504), and minutes on the command line: counted from its specs, it is refused at once, as a
    layer and inside a package (where the root references a member that holds it)."""
    layer = nested_references(18)
    package = usdz([(LAYER, b'#usda 1.0\ndef "Scene" (\n    references = @./nested.usda@</L18>\n)\n{\n}\n'),
                    ("nested.usda", layer.encode())])
    for body, headers in ((layer.encode(), {"content-type": "model/vnd.usda"}), (package, USDZ)):
        for route in ("/v1/generate", "/v1/thumbnails"):
            error = assert_error(server.client.post(route, content=body, headers=headers), 413, "too_large")
            assert "compose" in error["message"], error
    assert "Traceback" not in server.log_text()

