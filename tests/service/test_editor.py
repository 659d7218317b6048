"""The web editor in a real browser: Debian's Chromium, headless, WebGL2 on SwiftShader, driven by
Selenium through chromedriver against the session's live `shadergen serve` on 127.0.0.1.
Set SHADERGEN_SCREENSHOT_DIR to keep the screenshots (docs/editor holds the README's)."""
import base64
import os
import time
from pathlib import Path

import numpy as np
import pytest

from required_tools import missing
from service_testing import wait_until

CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"
CHROMIUM_FLAGS = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--disable-quic", "--no-first-run", "--window-size=1400,900"]
GOLD = Path(__file__).parents[2] / "service" / "static" / "editor" / "examples" / "gold.mtlx"


@pytest.fixture(scope="module")
def browser():
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing("selenium", "the [dev] extra installs it")
    for path in (CHROMIUM, CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            missing(path)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(60)
    driver.set_script_timeout(60)
    yield driver
    driver.quit()


@pytest.fixture
def editor(browser, server):
    """The editor freshly loaded (its first example shown), with the console read empty."""
    browser.get(server.url + "/")
    wait_until(lambda: poll_js(browser, "window.shaderxEditor && window.shaderxEditor.ready"),
               120, "the editor's first example")
    return browser


def console_problems(driver) -> list[dict]:
    return [entry for entry in driver.get_log("browser") if entry["level"] in ("SEVERE", "WARNING")]


def js(driver, expression: str):
    return driver.execute_script(f"return {expression}")


def poll_js(driver, expression: str):
    """`js` for polling: None while the page's renderer is too busy to answer in time (a software
    GPU compiling or drawing on a loaded machine), so the poll asks again."""
    from selenium.common.exceptions import TimeoutException

    try:
        return js(driver, expression)
    except TimeoutException:
        return None


def canvas_pixels(driver, tmp_path: Path) -> np.ndarray:
    import OpenImageIO as oiio

    url = js(driver, "document.getElementById('preview').toDataURL('image/png')")
    path = tmp_path / f"canvas-{time.monotonic_ns()}.png"
    path.write_bytes(base64.b64decode(url.split(",", 1)[1]))
    return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)[..., :3]


def wait_for_draw(driver, draws_before: int) -> None:
    wait_until(lambda: (poll_js(driver, "window.shaderxEditor.preview.stats.draws") or 0) > draws_before, 60,
               "a new frame")


def screenshot(driver, name: str, tmp_path: Path) -> None:
    folder = Path(os.environ.get("SHADERGEN_SCREENSHOT_DIR") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    assert driver.save_screenshot(str(folder / name))


def test_the_editor_loads_with_controls_from_the_listing_and_no_console_errors(editor, tmp_path):
    problems = console_problems(editor)
    assert problems == []
    assert js(editor, "window.shaderxEditor.preview !== null"), "no WebGL2 preview in Chromium"
    sections = js(editor, "[...document.querySelectorAll('#controls summary')].map(s => s.textContent)")
    assert {"Base", "Specular", "Coat"} <= set(sections)
    metalness = editor.find_element("css selector", "[data-path='SR_gold/metalness'] input[type=range]")
    assert (metalness.get_attribute("min"), metalness.get_attribute("max")) == ("0", "1")
    assert editor.find_elements("css selector", "[data-path='SR_gold/base_color'] input[type=color]")
    assert editor.find_elements("css selector", "[data-path='SR_gold/thin_walled'] input[type=checkbox]")
    uniform = editor.find_element("css selector", "[data-path='SR_gold/metalness']").get_attribute("data-uniform")
    assert f"uniform float {uniform};" in editor.find_element("id", "output").text  # the control binds by the listing
    assert js(editor, "window.shaderxEditor.preview.stats.compiles") == 1
    screenshot(editor, "editor.png", tmp_path)


def test_a_slider_changes_the_canvas_on_the_gpu_without_a_request(editor, tmp_path):
    from selenium.webdriver import ActionChains

    before = canvas_pixels(editor, tmp_path)
    requests, draws = js(editor, "window.shaderxEditor.traffic.generate"), js(editor, "window.shaderxEditor.preview.stats.draws")
    track = editor.find_element("css selector", "[data-path='SR_gold/specular_roughness'] input[type=range]")
    ActionChains(editor).move_to_element_with_offset(track, track.size["width"] // 2 - 4, 0).click().perform()
    wait_for_draw(editor, draws)
    after = canvas_pixels(editor, tmp_path)
    changed = float((np.abs(after - before).max(axis=2) > 2 / 255).mean())
    assert changed > 0.05, f"only {changed:.1%} of the pixels changed"
    assert js(editor, "window.shaderxEditor.traffic.generate") == requests
    roughness = float(editor.find_element("css selector", "[data-path='SR_gold/specular_roughness'] input[type=number]")
                      .get_attribute("value"))
    assert roughness > 0.9
    # the document follows the control; generating it again gives the same source: no recompile
    assert f'value="{roughness:g}"' in editor.find_element("id", "document").get_attribute("value")
    editor.find_element("id", "generate").click()
    wait_until(lambda: poll_js(editor, "window.shaderxEditor.traffic.generate") == requests + 1, 60,
               "the second request")
    wait_until(lambda: "no recompile" in editor.find_element("id", "preview-note").text, 60, "the record shown")
    assert js(editor, "window.shaderxEditor.preview.stats.compiles") == 1
    assert console_problems(editor) == []
    screenshot(editor, "editor-rough.png", tmp_path)


@pytest.mark.usefixtures("renderer_required")
def test_the_preview_matches_the_thumbnail(editor, server, tmp_path):
    import OpenImageIO as oiio

    response = server.client.post("/v1/thumbnails", json={"document": GOLD.read_text(), "size": 256})
    assert response.status_code == 200
    (tmp_path / "thumbnail.png").write_bytes(response.content)
    thumbnail = oiio.ImageBuf(str(tmp_path / "thumbnail.png")).get_pixels(oiio.FLOAT)[..., :3]
    preview = canvas_pixels(editor, tmp_path)
    psnr = 10 * np.log10(1.0 / float(((preview - thumbnail) ** 2).mean()))
    print(f"\nWebGL2 preview against the service's thumbnail: PSNR {psnr:.1f} dB")
    assert psnr > 40, f"preview against thumbnail: {psnr:.1f} dB"


def test_an_invalid_document_shows_its_error_in_place(editor, tmp_path):
    area = editor.find_element("id", "document")
    editor.execute_script("arguments[0].value = arguments[1]", area,
                          '<materialx version="1.39"><standard_surface name="s" type="surfaceshader">'
                          '<input name="base" type="float" value="1"/></standard_surface>'
                          '<surfacematerial name="M" type="material"><input name="surfaceshader" '
                          'type="surfaceshader" nodename="missing"/></surfacematerial></materialx>')
    editor.find_element("id", "generate").click()
    error = editor.find_element("id", "error")
    wait_until(lambda: error.is_displayed(), 60, "the error record")
    assert "M/surfaceshader" in error.text and "missing" in error.text
    # the only console line is the browser's note of the 4xx answer itself
    problems = console_problems(editor)
    assert len(problems) == 1 and problems[0]["source"] == "network", problems
    assert "/v1/generate" in problems[0]["message"] and "status of 422" in problems[0]["message"]
    screenshot(editor, "editor-error.png", tmp_path)


def test_an_enum_is_a_menu_and_listings_alone_are_asked_without_source(editor, tmp_path):
    from selenium.webdriver.support.select import Select

    Select(editor.find_element("id", "example")).select_by_value("saturated_plastic.mtlx")
    wait_until(lambda: editor.find_elements("css selector", "[data-path='NG_tint/tint/lumacoeffs'] select"), 60, "the menu")
    menu = Select(editor.find_element("css selector", "[data-path='NG_tint/tint/lumacoeffs'] select"))
    assert [o.text for o in menu.options] == ["acescg", "rec709", "rec2020", "rec2100"]
    assert menu.first_selected_option.text == "rec709"
    draws = js(editor, "window.shaderxEditor.preview.stats.draws")
    menu.select_by_visible_text("acescg")
    wait_for_draw(editor, draws)
    assert "0.2722287, 0.6740818, 0.0536895" in editor.find_element("id", "document").get_attribute("value")
    live = editor.find_element("id", "live")
    live.click()  # live preview off: the next request asks for the listing only
    wait_until(lambda: "source: false" in editor.find_element("id", "preview-note").text, 60, "a listing")
    assert js(editor, "Object.values(window.shaderxEditor.state.record.stages).every(source => !source)")
    assert "source not requested" in editor.find_element("id", "output").text
    assert js(editor, "window.shaderxEditor.state.record.blocks.pixel.PublicUniforms.length") > 10
    assert console_problems(editor) == []
