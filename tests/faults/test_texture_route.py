"""Issue 27, item 2: GET /v1/textures gives the editor the images its documents name, from the
live service's texture roots only. Every name that leaves them (`..`, an absolute path, a
symbolic link out, a URL, a NUL) is refused 403 before anything is read; a file over
SHADERGEN_MAX_TEXTURE_BYTES, or whose header declares more than the renderer reads, is 413; a
file corrupted while the service runs is 422; a name that is no file, no image format or no name
the file system takes (longer than a file name may be) is 404; never a 500, and the next good file
is served."""
import os

import pytest

from hostile_packages import huge_png_header, png
from service_testing import Server, assert_error

MAX_BYTES = 4096
SECRET = b"the server's own file"


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    base = tmp_path_factory.mktemp("texture_route")
    root, outside = base / "root", base / "outside"
    (root / "sub").mkdir(parents=True)
    outside.mkdir()
    (outside / "secret.png").write_bytes(SECRET)
    (root / "sub" / "red.png").write_bytes(png(8, 8, (230, 20, 20)))
    (root / "huge.png").write_bytes(huge_png_header(60000, 60000))
    (root / "big.png").write_bytes(png(8, 8, (1, 2, 3)) + bytes(MAX_BYTES))
    (root / "notes.txt").write_text("not an image")
    os.symlink(outside / "secret.png", root / "link.png")
    return root, outside


@pytest.fixture(scope="module")
def server(tmp_path_factory, folders):
    root, _ = folders
    srv = Server(tmp_path_factory.mktemp("texture_serve"), workers=1, render_workers=1,
                 env={"SHADERGEN_TEXTURE_ROOTS": str(root), "SHADERGEN_MAX_TEXTURE_BYTES": str(MAX_BYTES)})
    yield srv
    srv.close()


def get(server, path: str):
    return server.client.get("/v1/textures", params={"path": path})


def test_a_file_in_a_root_is_served_as_it_is_on_disk(server, folders):
    root, _ = folders
    for name in ("sub/red.png", "sub/../sub/red.png", str(root / "sub" / "red.png")):
        r = get(server, name)
        assert r.status_code == 200, r.text
        assert r.headers["content-type"] == "image/png"
        assert r.content == (root / "sub" / "red.png").read_bytes()


@pytest.mark.parametrize("name", ["../outside/secret.png", "sub/../../outside/secret.png", "link.png",
                                  "{outside}/secret.png", "file:///etc/passwd", "sub/red.png\x00.png", "/etc/passwd"])
def test_a_name_that_leaves_the_roots_is_refused_before_it_is_read(server, folders, name):
    _, outside = folders
    name = name.format(outside=outside)
    r = get(server, name)
    error = assert_error(r, 403, "path_not_allowed")
    assert error["where"] == "path" and SECRET not in r.content
    # the answer quotes the name sent, never where it led (a link's target)
    assert repr(name) in error["message"] and (str(outside) in name or str(outside) not in error["message"])


def test_sizes_are_bounded_by_the_file_and_by_its_header(server):
    error = assert_error(get(server, "big.png"), 413, "too_large")
    assert error["where"] == "path" and str(MAX_BYTES) in error["message"]
    error = assert_error(get(server, "huge.png"), 413, "too_large")
    assert error["where"] == "path" and "limit" in error["message"]


def test_what_is_no_image_file_is_refused_with_its_reason(server):
    error = assert_error(get(server, "notes.txt"), 404, "not_found")
    assert error["where"] == "path" and "not an image format" in error["message"]
    assert assert_error(get(server, "sub/missing.png"), 404, "not_found")["where"] == "path"
    assert_error(server.client.get("/v1/textures"), 422, "invalid_request")
    # a name the file system refuses outright (a name longer than a file name may be) is no file: not a 500
    assert assert_error(get(server, "0" * 300), 404, "not_found")["where"] == "path"
    assert assert_error(get(server, "0" * 300 + ".png"), 404, "not_found")["where"] == "path"


def test_a_texture_corrupted_while_served_is_refused_then_served_again(server, folders):
    root, _ = folders
    target = root / "sub" / "red.png"
    good = target.read_bytes()
    target.write_bytes(good[:20] + b"\xff" * 40)  # the signature kept, the header chunk broken
    try:
        error = assert_error(get(server, "sub/red.png"), 422, "invalid_image")
        assert error["where"] == "path" and str(root) not in error["message"]
    finally:
        target.write_bytes(good)
    assert get(server, "sub/red.png").content == good
    assert "Traceback" not in server.log_text()


def textured_layer(name: str) -> str:
    """A USD layer whose material's colour is the texture `name`."""
    return f"""#usda 1.0
def Material "M"
{{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor.connect = </M/T.outputs:rgb>
        token outputs:surface
    }}
    def Shader "T"
    {{
        uniform token info:id = "UsdUVTexture"
        asset inputs:file = @{name}@
        float3 outputs:rgb
    }}
}}
"""


def answer(response, name: str) -> tuple:
    """Status and body, the name the body quotes (a refusal's) written as <name>."""
    return response.status_code, response.content.replace(name.encode(), b"<name>")


def test_what_lies_outside_the_roots_changes_no_answer(server, folders):
    """A name may climb out of a root and back in (`../outside/x/../../root/sub/red.png`), or reach
    a root from outside (`/outside/x/sub/red.png`). Resolved by the file system, what `x` is outside
    the roots (a folder, a symbolic link and where it leads, nothing) decided whether the name was
    served or refused, for the editor's texture route and a USD upload's thumbnail alike: an
    answer that told a client about the server's files. The name is made normal as written first,
    so all three spellings give one answer: served when it lands in a root, refused when not."""
    root, outside = folders
    (outside / "plain" / "deeper").mkdir(parents=True, exist_ok=True)
    for link, target in (("link", outside / "plain" / "deeper"), ("into_root", root)):
        if not (outside / link).is_symlink():
            os.symlink(target, outside / link)
    climbing = {via: f"../outside/{via}/../../root/sub/red.png" for via in ("plain", "link", "nosuch")}
    reaching = {via: f"{outside}/{via}/sub/red.png" for via in ("into_root", "nosuch")}
    for names, status in ((climbing, 200), (reaching, 403)):
        answers = {via: answer(get(server, name), name) for via, name in names.items()}
        assert {a[0] for a in answers.values()} == {status}, answers
        assert len(set(answers.values())) == 1, answers
        # the same picture (the red texture) or the same refusal
        thumbnails = {via: answer(server.client.post("/v1/thumbnails", params={"size": 32},
                                                     content=textured_layer(name),
                                                     headers={"content-type": "model/vnd.usda"}, timeout=120), name)
                      for via, name in names.items()}
        assert len(set(thumbnails.values())) == 1, thumbnails
