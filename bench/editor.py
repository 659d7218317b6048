#!/usr/bin/env python3
"""The web editor over every Examples material (issue 27, "How it is measured"): starts the
service on 127.0.0.1 and drives headless Chromium (WebGL2 on SwiftShader, as the browser tests).
Each material is opened from a link holding its document (the page's own share format), and
measured: page load to first frame, a value edit (a control moved: the GPU alone) to its frame,
a topology edit (a node added, then undone: a request each) to its frame, and the screenshot of
the preview against the service's thumbnail of the same material (256 px, sphere, camera and
environment as `shadergen render`), PSNR. The service reads textures from its texture roots only,
so each document's `fileprefix` folder becomes a root and the prefix is dropped from the text sent;
each document's own folder is an include root, so a look document's `xi:include` of its material
(an href relative to the look's folder, which the text sent no longer has) is read.

    .venv/bin/python bench/editor.py ../shared/corpus/resources/Materials/Examples [--out docs/editor]

Writes the table to OUT/bench.md and each preview to OUT/examples/; the last line reads
`editor: N materials | preview vs thumbnail min X dB | median Y dB | value edit p50 ... ms | ...`.
"""
import argparse
import base64
import re
import statistics
import sys
import time
import zlib
from pathlib import Path

import httpx
import numpy as np

from load import ROOT, percentile, start_server

sys.path.insert(0, str(ROOT / "tests" / "service"))
sys.path.insert(0, str(ROOT / "tests"))
from editor_testing import CHROMEDRIVER, CHROMIUM, CHROMIUM_FLAGS  # noqa: E402 (the tests' browser, flags and all)

VALUE_EDITS = 5
FRAME_WAIT_S = 300  # a large shader compiles for a minute on a software GPU on a loaded machine
SIZE = 256


def documents(examples: Path) -> list[tuple[str, str, Path]]:
    """(name, document text with its fileprefix made a texture root, that root) per .mtlx."""
    found = []
    for path in sorted(examples.rglob("*.mtlx")):
        text = path.read_text()
        prefix = re.search(r'fileprefix="([^"]*)"', text)
        root = (path.parent / prefix.group(1)).resolve() if prefix else path.parent
        found.append((path.stem, re.sub(r'\s+fileprefix="[^"]*"', "", text, count=1), root))
    return found


def link_fragment(text: str) -> str:
    packer = zlib.compressobj(9, zlib.DEFLATED, -15)  # raw deflate, as CompressionStream("deflate-raw")
    packed = packer.compress(text.encode()) + packer.flush()
    return "doc=" + base64.urlsafe_b64encode(packed).decode().rstrip("=")


def pixels(png: bytes) -> np.ndarray:
    import OpenImageIO as oiio

    path = Path("/tmp") / f"shadergen-bench-editor-{time.monotonic_ns()}.png"
    path.write_bytes(png)
    try:
        return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)[..., :3]
    finally:
        path.unlink()


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    return 10 * np.log10(1.0 / max(float(((a - b) ** 2).mean()), 1e-12))


def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(FRAME_WAIT_S)
    driver.set_script_timeout(FRAME_WAIT_S)
    return driver


def wait(driver, expression: str, what: str):
    deadline = time.monotonic() + FRAME_WAIT_S
    while time.monotonic() < deadline:
        try:
            value = driver.execute_script(f"return {expression}")
        except Exception:  # the renderer too busy compiling to answer in time: ask again
            value = None
        if value:
            return value
        time.sleep(0.1)
    raise SystemExit(f"{what}: not within {FRAME_WAIT_S} s")


def measure(driver, client: httpx.Client, url: str, name: str, text: str, out: Path) -> dict:
    driver.get("about:blank")
    driver.get(f"{url}/editor/#{link_fragment(text)}")
    wait(driver, "window.shaderxEditor && window.shaderxEditor.ready", f"{name}: the editor")
    editor = "window.shaderxEditor"
    failed = driver.execute_script("return document.getElementById('error').hidden ? null : document.getElementById('error').textContent")
    if failed:
        return {"name": name, "error": failed.replace("\n", " ")[:120]}
    element = driver.execute_script(f"return {editor}.state.record.element")
    first = driver.execute_script(f"return {editor}.firstFrameMs")
    png = base64.b64decode(driver.execute_script("return document.getElementById('preview').toDataURL('image/png')").split(",", 1)[1])
    (out / "examples" / f"{name}.png").write_bytes(png)
    thumbnail = client.post("/v1/thumbnails", json={"document": text, "element": element, "size": SIZE})
    agreement = psnr(pixels(png), pixels(thumbnail.content)) if thumbnail.status_code == 200 else float("nan")
    # value edits: the first float slider moved, each to its frame, with no request
    sent = driver.execute_script(f"return {editor}.traffic.generate")
    for i in range(VALUE_EDITS):
        driver.execute_script("""
            const field = document.querySelector('#controls .control input[type=number][step=any]');
            if (field) { field.value = String(0.2 + 0.15 * arguments[0]); field.dispatchEvent(new Event('input')); }
        """, i)
        wait(driver, f"{editor}.timings.value.length >= {i + 1} || !document.querySelector('#controls input[type=number][step=any]')",
             f"{name}: value edit {i}")
    assert driver.execute_script(f"return {editor}.traffic.generate") == sent, "a value edit sent a request"
    # topology edits: a node added from the palette, then undone; each a new record and its frame
    runs = driver.execute_script(f"return {editor}.runs")
    driver.execute_script("""
        const search = document.getElementById('palette-search');
        search.value = 'constant float';
        search.dispatchEvent(new Event('input'));
        document.querySelector('#palette li[data-nodedef=ND_constant_float]').click();
    """)
    wait(driver, f"{editor}.timings.topology.length >= 1", f"{name}: topology edit")
    driver.execute_script("document.getElementById('undo').click()")
    wait(driver, f"{editor}.timings.topology.length >= 2 && {editor}.runs >= {runs + 2}", f"{name}: its undo")
    timings = driver.execute_script(f"return {editor}.timings")
    return {"name": name, "element": element, "first": first, "psnr": agreement, "value": timings["value"],
            "topology": timings["topology"], "textures": driver.execute_script(
                "return document.querySelectorAll('#textures li.loaded').length")}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("examples", type=Path, help="the Examples folder of the corpus")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "editor", help="where the table and previews go")
    args = ap.parse_args()
    found = documents(args.examples)
    roots = sorted({str(root) for _, _, root in found})
    folders = sorted({str(path.parent.resolve()) for path in args.examples.rglob("*.mtlx")})
    (args.out / "examples").mkdir(parents=True, exist_ok=True)
    proc, url, _ = start_server(1, 1, {"SHADERGEN_TEXTURE_ROOTS": ":".join(roots), "SHADERGEN_RENDER_TIMEOUT_S": "300",
                                       "SHADERGEN_INCLUDE_ROOTS": ":".join(folders)})
    driver = browser()
    try:
        with httpx.Client(base_url=url, timeout=FRAME_WAIT_S) as client:
            results = [measure(driver, client, url, name, text, args.out) for name, text, _ in found]
    finally:
        driver.quit()
        proc.terminate()
        proc.wait(timeout=30)
    done = [r for r in results if "error" not in r]
    rows = ["| material | textures | first frame ms | value edit p50 ms | topology edit p50 ms | preview vs thumbnail dB |",
            "| --- | --- | --- | --- | --- | --- |"]
    for r in results:
        if "error" in r:
            rows.append(f"| {r['name']} | | | | | not drawn: {r['error']} |")
            continue
        rows.append(f"| {r['name']} | {r['textures']} | {r['first']:.0f} | {statistics.median(r['value'] or [float('nan')]):.1f} | "
                    f"{statistics.median(r['topology']):.0f} | {r['psnr']:.1f} |")
    table = "\n".join(rows)
    print(table)
    (args.out / "bench.md").write_text("# bench/editor.py\n\n" + table + "\n")
    scores = [r["psnr"] for r in done]
    values = [t for r in done for t in r["value"]]
    topologies = [t for r in done for t in r["topology"]]
    firsts = [r["first"] for r in done]
    print(f"editor: {len(done)} materials | preview vs thumbnail min {min(scores):.1f} dB | median "
          f"{statistics.median(scores):.1f} dB | value edit p50 {percentile(values, 0.5):.1f} ms | "
          f"topology edit p50 {percentile(topologies, 0.5):.0f} ms | first frame p50 {percentile(firsts, 0.5):.0f} ms")


if __name__ == "__main__":
    main()
