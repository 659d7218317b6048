"""Uploads that include documents from the server's include roots (SHADERGEN_INCLUDE_ROOTS: the
test server's is documents/included/): generated and drawn with the included file's textures
where its own folder puts them; an href leaving the roots refused with where; and an included
file edited between two byte-identical requests answered with its new content (the request
digest covers the upload's bytes only)."""
import os
import uuid

import pytest

from service_testing import DOCS, assert_error, document

XI = 'xmlns:xi="http://www.w3.org/2001/XInclude"'
ROOT = DOCS / "included"


def including(*hrefs: str) -> str:
    includes = "".join(f'<xi:include href="{href}" />' for href in hrefs)
    return f'<?xml version="1.0"?>\n<materialx version="1.39" {XI}>{includes}</materialx>'


def generate(client, text: str):
    return client.post("/v1/generate", json={"document": text, "target": "essl"})


def filenames(record: dict) -> list[str]:
    return [v["value"] for v in record["blocks"]["pixel"]["PublicUniforms"] if v["type"] == "filename"]


def test_a_look_includes_its_material_and_its_texture_is_where_the_included_file_says(client):
    r = generate(client, including("looks/checker_look.mtlx"))
    assert r.status_code == 200, r.text
    assert filenames(r.json()) == [os.path.join(os.path.realpath(DOCS), "checker.png")]


@pytest.mark.usefixtures("renderer_required")
def test_the_included_materials_thumbnail_is_the_inline_ones(client):
    inline = document("included/checker_material.mtlx").replace('fileprefix="../"', "")
    included = client.post("/v1/thumbnails", json={"document": including("looks/checker_look.mtlx"), "size": 64})
    direct = client.post("/v1/thumbnails", json={"document": inline, "size": 64})
    assert included.status_code == 200 and direct.status_code == 200, (included.text, direct.text)
    assert included.content == direct.content


@pytest.mark.parametrize("href", ["../textured.mtlx", "looks/../../marble.mtlx", str(DOCS / "marble.mtlx"),
                                  "file:///etc/passwd"])
def test_an_href_out_of_the_include_roots_is_refused(client, href):
    error = assert_error(generate(client, including(href)), 400, "include_refused")
    assert error["where"] == href


def test_a_missing_included_file_is_an_invalid_document(client):
    error = assert_error(generate(client, including("none.mtlx")), 400, "invalid_document")
    assert error["where"] == "none.mtlx"


def test_an_included_file_edited_between_two_identical_requests_is_read_again(client):
    name = f"edited-{uuid.uuid4().hex}.mtlx"
    path = ROOT / name
    material = document("included/checker_material.mtlx")
    try:
        path.write_text(material)
        first = generate(client, including(name))
        assert first.status_code == 200, first.text
        path.write_text(material.replace("checker.png", "quadrants.png"))
        second = generate(client, including(name))
        assert second.status_code == 200, second.text
        assert [os.path.basename(f) for f in filenames(second.json())] == ["quadrants.png"]
        path.unlink()
        assert_error(generate(client, including(name)), 400, "invalid_document")
    finally:
        path.unlink(missing_ok=True)
