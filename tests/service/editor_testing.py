"""What the browser tests of the web editor share: Debian's Chromium, headless, WebGL2 on
SwiftShader, driven by Selenium through chromedriver against the session's live `shadergen serve`
on 127.0.0.1, and the page's state read through `window.shaderxEditor`. Test modules import the
fixtures `browser` and `editor` from here. Set SHADERGEN_SCREENSHOT_DIR to keep the screenshots
(docs/editor holds the README's)."""
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
EXAMPLES = Path(__file__).parents[2] / "service" / "static" / "editor" / "examples"


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
    # a bound on a hang, not a speed: a textured surface on SwiftShader under a loaded CI takes long
    wait_until(lambda: (poll_js(driver, "window.shaderxEditor.preview.stats.draws") or 0) > draws_before, 180,
               "a new frame")


def screenshot(driver, name: str, tmp_path: Path) -> None:
    folder = Path(os.environ.get("SHADERGEN_SCREENSHOT_DIR") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    assert driver.save_screenshot(str(folder / name))




def drop_files(driver, files: list[tuple[str, bytes]]) -> None:
    """Drop files on the page as a person dragging them from a file manager would (a DataTransfer
    of File objects on a drop event; folders travel inside archives here)."""
    payload = [[name, base64.b64encode(data).decode()] for name, data in files]
    driver.execute_script("""
        const transfer = new DataTransfer();
        for (const [name, data] of arguments[0]) {
          const bytes = Uint8Array.from(atob(data), (c) => c.charCodeAt(0));
          transfer.items.add(new File([bytes], name));
        }
        document.body.dispatchEvent(new DragEvent("drop", { dataTransfer: transfer, bubbles: true, cancelable: true }));
    """, payload)


def set_document(driver, text: str) -> None:
    """Paste a document and generate it."""
    driver.execute_script("arguments[0].value = arguments[1]", driver.find_element("id", "document"), text)
    driver.find_element("id", "generate").click()


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    return 10 * np.log10(1.0 / max(float(((a - b) ** 2).mean()), 1e-12))


def thumbnail_pixels(server, document: str, tmp_path: Path, **options) -> np.ndarray:
    import OpenImageIO as oiio

    response = server.client.post("/v1/thumbnails", json={"document": document, "size": 256, **options})
    assert response.status_code == 200, response.text
    path = tmp_path / f"thumbnail-{time.monotonic_ns()}.png"
    path.write_bytes(response.content)
    return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)[..., :3]


def exr(folder: Path, width: int, height: int, rgb: tuple[float, float, float]) -> bytes:
    """An OpenEXR file of one colour (half RGB), written by OpenImageIO."""
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(oiio.ImageSpec(width, height, 3, oiio.FLOAT))
    oiio.ImageBufAlgo.fill(buf, list(rgb))
    path = folder / f"made-{time.monotonic_ns()}.exr"
    assert buf.write(str(path), "half"), buf.geterror()
    return path.read_bytes()
