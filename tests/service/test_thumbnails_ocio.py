"""Thumbnails of OCIO records through the live server (issue 28, item 3): the PNG shows the
document's working space through the config's display and view, as `shadergen render --cms ocio`
does, with the real opencolorio package; `view` picks another view; an unknown view is a 422
naming the config's; a batch draws the same PNGs."""
import time

import numpy as np
import pytest

from required_tools import require_module
from service_testing import is_png

OCIO = require_module("PyOpenColorIO", "pip install -e '.[ocio]'")
pytestmark = pytest.mark.usefixtures("renderer_required")

CG = "ocio://cg-config-v2.1.0_aces-v1.3_ocio-v2.3"
VALUE = (0.25, 0.5, 0.75)
DOCUMENT = f"""<?xml version="1.0"?>
<materialx version="1.39" colorspace="ACEScg">
  <nodegraph name="g">
    <constant name="c" type="color3"><input name="value" type="color3" value="{', '.join(map(str, VALUE))}"
      colorspace="sRGB - Texture" /></constant>
    <output name="out" type="color3" nodename="c" />
  </nodegraph>
</materialx>"""
SIZE = 32


def centre(png: bytes, tmp_path) -> np.ndarray:
    from shadergen.render.imageio import read_image

    path = tmp_path / f"t{time.monotonic_ns()}.png"
    path.write_bytes(png)
    return read_image(str(path))[SIZE // 2, SIZE // 2, :3]


def shown(view: str | None) -> np.ndarray:
    """The document's colour in ACEScg through the CG config's sRGB display and `view`, by OCIO's CPU processor."""
    cfg = OCIO.Config.CreateFromFile(CG)
    colour = np.array([VALUE], "f4")
    cfg.getProcessor("sRGB - Texture", "ACEScg").getDefaultCPUProcessor().applyRGB(colour)
    display = cfg.getDefaultDisplay()
    transform = OCIO.DisplayViewTransform(src="ACEScg", display=display, view=view or cfg.getDefaultView(display))
    cfg.getProcessor(transform).getDefaultCPUProcessor().applyRGB(colour)
    return np.clip(colour[0], 0.0, 1.0)


def thumbnail(client, **params):
    return client.post("/v1/thumbnails", json={"document": DOCUMENT, "mesh": "plane", "size": SIZE,
                                               "cms": "ocio", "ocio_config": CG, **params})


def test_the_png_shows_the_working_space_through_the_default_view(client, tmp_path):
    r = thumbnail(client)
    assert r.status_code == 200, r.text
    assert is_png(r.content, SIZE)
    assert np.abs(centre(r.content, tmp_path) - shown(None)).max() <= 1.5 / 255.0


def test_a_view_is_chosen_and_cached_apart(client, tmp_path):
    tone_mapped = thumbnail(client).content
    r = thumbnail(client, view="Un-tone-mapped")
    assert r.status_code == 200, r.text
    pixel = centre(r.content, tmp_path)
    assert np.abs(pixel - shown("Un-tone-mapped")).max() <= 1.5 / 255.0
    assert np.abs(pixel - centre(tone_mapped, tmp_path)).max() > 5 / 255.0  # the two views differ here


def test_an_unknown_view_is_422_listing_the_views(client):
    r = thumbnail(client, view="Filmic")
    assert r.status_code == 422, r.text
    error = r.json()["error"]
    assert error["code"] == "unknown_view" and "Un-tone-mapped" in error["message"] and error["where"] == "view"
    builtin = client.post("/v1/thumbnails", json={"document": DOCUMENT, "view": "Raw"})
    assert builtin.status_code == 422 and builtin.json()["error"] | {"message": None} == {
        "code": "invalid_option", "message": None, "where": "view"}  # as ocio_config without ocio


def test_a_batch_draws_through_the_same_view(client):
    single = thumbnail(client, view="Un-tone-mapped").content
    accepted = client.post("/v1/thumbnails/batch", json={
        "documents": [{"document": DOCUMENT, "name": "a"}], "mesh": "plane", "size": SIZE, "interface": "specialized",
        "cms": "ocio", "ocio_config": CG, "view": "Un-tone-mapped"})
    assert accepted.status_code == 202, accepted.text
    url = accepted.json()["status_url"]
    deadline = time.monotonic() + 300
    status = client.get(url).json()
    while status["state"] != "done" and time.monotonic() < deadline:
        time.sleep(0.2)
        status = client.get(url).json()
    assert status["results"][0]["state"] == "done", status
    png = client.get(status["results"][0]["thumbnail_url"] if status["results"][0].get("thumbnail_url")
                     else f"{url}/0")
    assert png.status_code == 200 and png.content == single


def test_documents_differing_only_in_working_space_get_their_own_pngs(client, tmp_path):
    """Two documents of the same values in different working spaces share one record hash (no
    transform in either); the PNG cache must still keep their thumbnails apart."""
    plain = DOCUMENT.replace(' colorspace="sRGB - Texture"', "")
    pngs = {}
    for working in ("ACEScg", "Linear Rec.709 (sRGB)"):
        r = client.post("/v1/thumbnails", json={"document": plain.replace('colorspace="ACEScg"', f'colorspace="{working}"'),
                                                "mesh": "plane", "size": SIZE, "cms": "ocio", "ocio_config": CG,
                                                "view": "Un-tone-mapped"})
        assert r.status_code == 200, r.text
        pngs[working] = centre(r.content, tmp_path)
    cfg = OCIO.Config.CreateFromFile(CG)
    for working, pixel in pngs.items():
        colour = np.array([VALUE], "f4")
        cfg.getProcessor(OCIO.DisplayViewTransform(src=working, display=cfg.getDefaultDisplay(),
                                                   view="Un-tone-mapped")).getDefaultCPUProcessor().applyRGB(colour)
        assert np.abs(pixel - np.clip(colour[0], 0, 1)).max() <= 1.5 / 255.0, working
