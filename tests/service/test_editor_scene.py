"""Issue 27, item 3, in a real browser (editor_testing.py): the preview's scene chosen on the
page, with no request: the mesh (sphere, plane, cube, a dropped .obj), the environment (the
thumbnails' sky or a dropped .hdr or .exr, both decoded in the page, its irradiance
computed in the page), its intensity and rotation, and the turntable."""
import struct

import numpy as np
from selenium.webdriver.support.select import Select

from editor_testing import browser, canvas_pixels, console_problems, drop_files, editor, exr, js, poll_js, psnr, \
    screenshot, wait_for_draw  # noqa: F401 (fixtures)
from service_testing import wait_until

TETRAHEDRON = """# a tetrahedron, no normals or uvs (computed)
v 0 1 0
v -1 -1 1
v 1 -1 1
v 0 -1 -1
f 1 2 3
f 1 3 4
f 1 4 2
f 2 4 3
"""


def hdr(width: int, height: int, rgb: tuple[float, float, float]) -> bytes:
    """A Radiance .hdr of one colour, flat scanlines."""
    exponent = max(int(np.ceil(np.log2(max(rgb)))), -127) + 1
    pixel = bytes(int(c / 2.0 ** exponent * 256) for c in rgb) + bytes([exponent + 128])
    header = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n".encode()
    return header + pixel * (width * height)


def changed(driver, tmp_path, before: np.ndarray, action) -> np.ndarray:
    """Do `action`, wait for its frame, return the new picture."""
    draws = js(driver, "window.shaderxEditor.preview.stats.draws")
    action()
    wait_for_draw(driver, draws)
    return canvas_pixels(driver, tmp_path)


def centre(picture: np.ndarray) -> np.ndarray:
    return picture[108:148, 108:148].reshape(-1, 3).mean(axis=0)


def set_range(driver, element_id: str, value: float) -> None:
    driver.execute_script("const r = document.getElementById(arguments[0]); r.value = arguments[1];"
                          "r.dispatchEvent(new Event('input'))", element_id, value)


def test_meshes_are_chosen_and_dropped(editor, tmp_path):
    sent = js(editor, "window.shaderxEditor.traffic.generate")
    sphere = canvas_pixels(editor, tmp_path)
    menu = Select(editor.find_element("id", "mesh"))
    assert [o.text for o in menu.options] == ["sphere", "plane", "cube"]
    pictures = {"sphere": sphere}
    for name in ("plane", "cube"):
        pictures[name] = changed(editor, tmp_path, sphere, lambda n=name: menu.select_by_value(n))
        assert js(editor, "window.shaderxEditor.preview.mesh") == name
    assert psnr(pictures["plane"], sphere) < 25 and psnr(pictures["cube"], sphere) < 25
    assert psnr(pictures["plane"], pictures["cube"]) < 25
    screenshot(editor, "editor-cube.png", tmp_path)
    tetrahedron = changed(editor, tmp_path, sphere, lambda: drop_files(editor, [("tetra.obj", TETRAHEDRON.encode())]))
    assert js(editor, "window.shaderxEditor.preview.mesh") == "tetra.obj"
    assert Select(editor.find_element("id", "mesh")).first_selected_option.text == "tetra.obj"
    assert psnr(tetrahedron, sphere) < 25 and psnr(tetrahedron, pictures["cube"]) < 25
    back = changed(editor, tmp_path, sphere, lambda: Select(editor.find_element("id", "mesh")).select_by_value("sphere"))
    assert psnr(back, sphere) > 50
    assert js(editor, "window.shaderxEditor.traffic.generate") == sent
    assert console_problems(editor) == []


def test_the_environment_intensity_rotation_and_turntable(editor, tmp_path):
    sent = js(editor, "window.shaderxEditor.traffic.generate")
    sky = canvas_pixels(editor, tmp_path)
    dim = changed(editor, tmp_path, sky, lambda: set_range(editor, "intensity", 0.25))
    assert centre(dim).sum() < 0.8 * centre(sky).sum()
    set_range(editor, "intensity", 1)
    turned = changed(editor, tmp_path, sky, lambda: set_range(editor, "rotation", 180))
    assert psnr(turned, sky) < 35
    back = changed(editor, tmp_path, sky, lambda: set_range(editor, "rotation", 0))
    assert psnr(back, sky) > 50
    # the turntable draws frame after frame, the object turning; off, it stands as it was
    editor.find_element("id", "turntable").click()
    draws = js(editor, "window.shaderxEditor.preview.stats.draws")
    wait_until(lambda: (poll_js(editor, "window.shaderxEditor.preview.stats.draws") or 0) > draws + 3, 60, "turning")
    assert js(editor, "window.shaderxEditor.preview.choices.turntableDegrees") > 0
    editor.find_element("id", "turntable").click()
    wait_until(lambda: js(editor, "window.shaderxEditor.preview.choices.turntableDegrees") == 0, 10, "stopped")
    wait_until(lambda: psnr(canvas_pixels(editor, tmp_path), sky) > 50, 30, "the object as it stood")
    # a dropped .hdr of one red colour: gold lit by red alone is red
    red = changed(editor, tmp_path, sky, lambda: drop_files(editor, [("red.hdr", hdr(64, 32, (1.0, 0.1, 0.1)))]))
    assert Select(editor.find_element("id", "environment")).first_selected_option.text == "red.hdr"
    colour = centre(red)
    assert colour[0] > 2 * colour[1] and colour[0] > 2 * colour[2], colour
    screenshot(editor, "editor-environment.png", tmp_path)
    back = changed(editor, tmp_path, sky, lambda: Select(editor.find_element("id", "environment")).select_by_value("sky"))
    assert psnr(back, sky) > 50
    assert js(editor, "window.shaderxEditor.traffic.generate") == sent
    assert console_problems(editor) == []


def test_a_dropped_exr_environment_lights_the_object_as_the_same_hdr_does(editor, tmp_path):
    """red.exr holds exactly what red.hdr decodes to (RGBE keeps 8 bits: 0.1 reads 0.09375), so
    the two environments draw one picture; the .exr was decoded in the page (no request to the
    service's decoder), the document was not generated again."""
    sent, decodes = js(editor, "window.shaderxEditor.traffic.generate"), js(editor, "window.shaderxEditor.traffic.decode")
    sky = canvas_pixels(editor, tmp_path)
    red = changed(editor, tmp_path, sky, lambda: drop_files(editor, [("red.exr", exr(tmp_path, 64, 32, (1.0, 0.09375, 0.09375)))]))
    assert Select(editor.find_element("id", "environment")).first_selected_option.text == "red.exr"
    colour = centre(red)
    assert colour[0] > 2 * colour[1] and colour[0] > 2 * colour[2], colour
    assert psnr(red, sky) < 25
    screenshot(editor, "editor-exr-environment.png", tmp_path)
    from_hdr = changed(editor, tmp_path, red, lambda: drop_files(editor, [("red.hdr", hdr(64, 32, (1.0, 0.1, 0.1)))]))
    assert psnr(from_hdr, red) > 50
    assert js(editor, "window.shaderxEditor.traffic.generate") == sent
    assert js(editor, "window.shaderxEditor.traffic.decode") == decodes
    assert console_problems(editor) == []
