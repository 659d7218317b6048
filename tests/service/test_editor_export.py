"""Issue 27, item 4, in a real browser (editor_testing.py): the edited .mtlx and the preview's PNG
downloaded, the material written as .usda (UsdShade with MaterialX nodes, and UsdPreviewSurface
where the model allows) that our own USD reader reads back into the same record and the same
picture, dropped on the editor again, and a link that reopens the same document from its
fragment alone."""
import time
from pathlib import Path

import numpy as np
import pytest
from selenium.webdriver.support.select import Select

from editor_testing import browser, canvas_pixels, console_problems, drop_files, editor, js, poll_js, psnr, \
    screenshot, wait_for_draw  # noqa: F401 (fixtures)
from service_testing import wait_until

USDA = {"content-type": "model/vnd.usda"}


def open_example(driver, name: str) -> None:
    if js(driver, "document.getElementById('example').value") == name:
        return  # the page opened with it
    runs = js(driver, "window.shaderxEditor.runs")
    Select(driver.find_element("id", "example")).select_by_value(name)
    wait_until(lambda: (poll_js(driver, "window.shaderxEditor.runs") or 0) > runs, 60, name)


def listing(record: dict) -> list[tuple]:
    """The public uniforms as a renderer binds them, names aside (the USD reader names nodes by
    their prim paths)."""
    def value(v):  # numbers as float32 holds them (JavaScript gives 0 for 0.0)
        if isinstance(v, list):
            return tuple(value(x) for x in v)
        return float(np.float32(v)) if isinstance(v, (int, float)) and not isinstance(v, bool) else v

    return sorted((v["type"], repr(value(v["value"]))) for v in record["blocks"]["pixel"]["PublicUniforms"])


def downloaded(folder: Path, name: str) -> bytes:
    path = folder / name
    wait_until(lambda: path.exists() and path.stat().st_size > 0, 30, f"the download {name}")
    time.sleep(0)  # the file is written whole before Chromium renames it from .crdownload
    return path.read_bytes()


@pytest.mark.usefixtures("renderer_required")
@pytest.mark.parametrize("example", ["gold.mtlx", "marble.mtlx"])
def test_the_usda_reads_back_into_the_same_record_and_picture(editor, server, tmp_path, example):
    import OpenImageIO as oiio

    open_example(editor, example)
    usda = js(editor, "window.shaderxEditor.exports.usda()")
    assert 'uniform token info:id = "ND_' in usda and "outputs:mtlx:surface.connect" in usda
    if example == "gold.mtlx":  # a standard_surface of values: UsdPreviewSurface carries it too
        assert 'info:id = "UsdPreviewSurface"' in usda and "color3f inputs:diffuseColor = (0.94, 0.78, 0.37)" in usda
    else:
        assert 'def NodeGraph "NG_marble"' in usda
    record = js(editor, "window.shaderxEditor.state.record")
    answer = server.client.post("/v1/generate", content=usda.encode(), headers=USDA,
                                params={"target": "essl", "interface": "complete"})
    assert answer.status_code == 200, answer.text
    read_back = answer.json()
    assert listing(read_back) == listing(record)
    assert len(read_back["blocks"]["pixel"]["PublicUniforms"]) == len(record["blocks"]["pixel"]["PublicUniforms"])
    document = editor.find_element("id", "document").get_attribute("value")
    pictures = []
    for answer in (server.client.post("/v1/thumbnails", content=usda.encode(), headers=USDA, params={"size": 128}),
                   server.client.post("/v1/thumbnails", json={"document": document, "size": 128})):
        assert answer.status_code == 200, answer.text
        (tmp_path / "t.png").write_bytes(answer.content)
        pictures.append(oiio.ImageBuf(str(tmp_path / "t.png")).get_pixels(oiio.FLOAT)[..., :3])
    assert psnr(*pictures) > 50
    # dropped on the editor, it is generated as it is and drawn as the document was
    preview = canvas_pixels(editor, tmp_path)
    runs = js(editor, "window.shaderxEditor.runs")
    drop_files(editor, [(example.replace(".mtlx", ".usda"), usda.encode())])
    wait_until(lambda: (poll_js(editor, "window.shaderxEditor.runs") or 0) > runs, 60, "the usda generated")
    assert js(editor, "window.shaderxEditor.state.record.element").startswith("/MaterialX/")
    wait_until(lambda: psnr(canvas_pixels(editor, tmp_path), preview) > 40, 60, "the usda drawn as the document")
    assert console_problems(editor) == []


def test_the_mtlx_and_the_png_download_as_the_page_shows_them(editor, tmp_path):
    import OpenImageIO as oiio

    editor.execute_cdp_cmd("Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(tmp_path)})
    editor.find_element("id", "save-mtlx").click()
    assert downloaded(tmp_path, "gold.mtlx").decode() == editor.find_element("id", "document").get_attribute("value")
    editor.find_element("id", "save-png").click()
    downloaded(tmp_path, "gold.png")
    png = oiio.ImageBuf(str(tmp_path / "gold.png")).get_pixels(oiio.FLOAT)[..., :3]
    assert png.shape == (256, 256, 3) and psnr(png, canvas_pixels(editor, tmp_path)) > 60
    assert console_problems(editor) == []


def test_a_link_reopens_the_edited_document_from_its_fragment(editor, server, tmp_path):
    from selenium.webdriver import Keys

    editor.find_element("css selector", '#graph [data-box="SR_gold"]').click()
    field = editor.find_element("css selector", '#inspector [data-input="specular_roughness"] input')
    draws = js(editor, "window.shaderxEditor.preview.stats.draws")
    field.send_keys(Keys.CONTROL, "a")
    field.send_keys("0.65\n")
    wait_for_draw(editor, draws)
    text, picture = editor.find_element("id", "document").get_attribute("value"), canvas_pixels(editor, tmp_path)
    assert 'value="0.65"' in text
    editor.find_element("id", "share").click()
    link_field = editor.find_element("id", "link")
    wait_until(lambda: link_field.get_attribute("value"), 10, "the link")
    link = link_field.get_attribute("value")
    address, fragment = link.split("#", 1)
    assert address == server.url + "/editor/" and fragment.startswith("doc=")
    assert "SR_gold" not in fragment and len(fragment) < len(text)  # compressed, not the text itself
    editor.get("about:blank")
    editor.get(link)
    wait_until(lambda: poll_js(editor, "window.shaderxEditor && window.shaderxEditor.ready"), 120, "the linked editor")
    assert editor.find_element("id", "document").get_attribute("value") == text
    assert psnr(canvas_pixels(editor, tmp_path), picture) > 50
    assert console_problems(editor) == []
    screenshot(editor, "editor-link.png", tmp_path)
