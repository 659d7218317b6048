"""Issue 27, item 2, in a real browser (editor_testing.py): the preview binds the textures a
document names, from the service's texture roots or from what is dropped on the page (images,
an .exr decoded in the page, a .zip with folders, a .usdz), with the sampling its image node gives; a file it cannot have is
drawn in the node's default colour with the reason listed, as a thumbnail draws it."""
import io
import zipfile

import numpy as np
import pytest

from editor_testing import browser, canvas_pixels, console_problems, drop_files, editor, exr, js, poll_js, psnr, \
    screenshot, set_document, thumbnail_pixels, wait_for_draw  # noqa: F401 (fixtures)
from hostile_packages import LAYER, png, textured_layer, usdz
from service_testing import Server, wait_until

RED, GREEN, BLUE = (230, 20, 20), (20, 200, 30), (20, 30, 230)


def material(file: str, default: str = "0, 0, 1", image_inputs: str = "", texcoord: str = "") -> str:
    """A standard_surface whose base colour is one image node (and whose light is mostly diffuse)."""
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  {texcoord}
  <image name="tex" type="color3">
    <input name="file" type="filename" value="{file}" />
    <input name="default" type="color3" value="{default}" />
    {image_inputs}
  </image>
  <standard_surface name="S" type="surfaceshader">
    <input name="base_color" type="color3" nodename="tex" />
    <input name="specular" type="float" value="0" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>"""


def centre_colour(driver, tmp_path) -> np.ndarray:
    return canvas_pixels(driver, tmp_path)[108:148, 108:148].reshape(-1, 3).mean(axis=0)


def textures_listed(driver) -> dict[str, str]:
    return js(driver, "Object.fromEntries([...document.querySelectorAll('#textures li')]"
                      ".map(li => [li.dataset.sampler, li.className + ': ' + li.textContent]))")


def counters(driver) -> tuple[int, int]:
    """The records shown and frames drawn so far, read before an edit: read after it, a frame
    that came quickly (same program, new sampler state) would already be counted and never awaited."""
    return js(driver, "[window.shaderxEditor.runs, window.shaderxEditor.preview.stats.draws]")


def shown(driver, before: tuple[int, int]) -> None:
    """The next record shown and drawn (its textures loaded with it)."""
    runs, draws = before
    wait_until(lambda: (poll_js(driver, "window.shaderxEditor.runs") or 0) > runs, 60, "the record")
    wait_for_draw(driver, draws)


def assert_is(colour: np.ndarray, hue: tuple[int, int, int]) -> None:
    strongest = int(np.argmax(hue))
    others = [c for c in range(3) if c != strongest]
    assert all(colour[strongest] > 1.5 * colour[c] for c in others), (colour, hue)


@pytest.mark.usefixtures("renderer_required")
def test_a_texture_in_the_roots_is_bound_with_its_sampling_as_the_thumbnail_draws_it(editor, server, tmp_path):
    """quadrants.png (64 x 32, four colours and a mark: any flip is another picture) from the
    test server's root, tiled 3 x 3 and mirrored in u."""
    tiled = ('<texcoord name="uv" type="vector2" /><multiply name="uv3" type="vector2">'
             '<input name="in1" type="vector2" nodename="uv" /><input name="in2" type="float" value="3" /></multiply>')
    inputs = ('<input name="texcoord" type="vector2" nodename="uv3" />'
              '<input name="uaddressmode" type="string" value="mirror" />')
    document = material("quadrants.png", image_inputs=inputs, texcoord=tiled)
    before = counters(editor)
    set_document(editor, document)
    shown(editor, before)
    assert list(textures_listed(editor).values()) == ["loaded: quadrants.png (service)"]
    assert js(editor, "window.shaderxEditor.preview.textureProblems()") == []
    preview = canvas_pixels(editor, tmp_path)
    agreement = psnr(preview, thumbnail_pixels(server, document, tmp_path))
    print(f"\ntextured preview against the service's thumbnail: PSNR {agreement:.1f} dB")
    assert agreement > 35, f"{agreement:.1f} dB"
    # the address mode is what is drawn: constant in u shows the default colour beyond the image
    before = counters(editor)
    set_document(editor, document.replace('value="mirror"', 'value="constant"'))
    shown(editor, before)
    assert psnr(canvas_pixels(editor, tmp_path), preview) < 25
    assert console_problems(editor) == []
    screenshot(editor, "editor-texture.png", tmp_path)


def test_a_file_outside_the_roots_draws_its_default_until_a_dropped_image_resolves_it(editor, tmp_path):
    before = counters(editor)
    set_document(editor, material("../../../Images/red_paint.png", default="0, 0, 1"))
    shown(editor, before)
    [listed] = textures_listed(editor).values()
    assert listed.startswith("missing: ../../../Images/red_paint.png: default colour") and "path_not_allowed" in listed
    assert_is(centre_colour(editor, tmp_path), BLUE)
    # the refusal is the only console line: the browser's note of the 403 itself
    problems = console_problems(editor)
    assert len(problems) == 1 and "/v1/textures" in problems[0]["message"] and "403" in problems[0]["message"]

    requests, draws = js(editor, "window.shaderxEditor.traffic.generate"), js(editor, "window.shaderxEditor.preview.stats.draws")
    drop_files(editor, [("red_paint.png", png(8, 8, RED))])
    wait_for_draw(editor, draws)
    wait_until(lambda: "loaded" in "".join(textures_listed(editor).values()), 60, "the dropped image listed")
    assert list(textures_listed(editor).values()) == ["loaded: ../../../Images/red_paint.png (dropped)"]
    assert_is(centre_colour(editor, tmp_path), RED)
    assert js(editor, "window.shaderxEditor.traffic.generate") == requests  # a drop of images asks nothing
    screenshot(editor, "editor-dropped-texture.png", tmp_path)


def test_a_dropped_exr_the_document_names_is_decoded_in_the_page_and_bound_as_a_texture(editor, tmp_path):
    before = counters(editor)
    set_document(editor, material("maps/green.exr", default="0, 0, 1"))
    shown(editor, before)
    [listed] = textures_listed(editor).values()
    assert listed.startswith("missing: maps/green.exr: default colour") and "not_found" in listed
    assert_is(centre_colour(editor, tmp_path), BLUE)
    # the refusal is the only console line: the browser's note of the 404 itself
    problems = console_problems(editor)
    assert len(problems) == 1 and "/v1/textures" in problems[0]["message"] and "404" in problems[0]["message"]
    requests, draws = js(editor, "window.shaderxEditor.traffic.generate"), js(editor, "window.shaderxEditor.preview.stats.draws")
    decodes = js(editor, "window.shaderxEditor.traffic.decode")
    drop_files(editor, [("green.exr", exr(tmp_path, 8, 8, tuple(c / 255 for c in GREEN)))])
    wait_for_draw(editor, draws)
    wait_until(lambda: "loaded" in "".join(textures_listed(editor).values()), 60, "the dropped .exr listed")
    assert list(textures_listed(editor).values()) == ["loaded: maps/green.exr (dropped)"]
    assert_is(centre_colour(editor, tmp_path), GREEN)
    # a texture, not an environment: the menu did not change, and the document was not sent again
    assert [o.text for o in editor.find_elements("css selector", "#environment option")] == ["sky"]
    assert js(editor, "window.shaderxEditor.traffic.generate") == requests
    assert js(editor, "window.shaderxEditor.traffic.decode") == decodes
    assert console_problems(editor) == []


def test_an_exr_in_the_texture_roots_is_served_and_decoded_in_the_page(browser, tmp_path):
    """A service whose texture root holds an .exr OpenImageIO wrote: the page fetches it from
    GET /v1/textures and decodes it itself (no request to the service's decoder)."""
    roots = tmp_path / "roots"
    (roots / "maps").mkdir(parents=True)
    (roots / "maps" / "green.exr").write_bytes(exr(tmp_path, 8, 8, tuple(c / 255 for c in GREEN)))
    served = Server(tmp_path, workers=1, env={"SHADERGEN_TEXTURE_ROOTS": str(roots)})
    try:
        browser.get(served.url + "/")
        wait_until(lambda: poll_js(browser, "window.shaderxEditor && window.shaderxEditor.ready"), 120, "the editor")
        decodes, before = js(browser, "window.shaderxEditor.traffic.decode"), counters(browser)
        set_document(browser, material("maps/green.exr", default="0, 0, 1"))
        shown(browser, before)
        assert list(textures_listed(browser).values()) == ["loaded: maps/green.exr (service)"]
        assert_is(centre_colour(browser, tmp_path), GREEN)
        assert js(browser, "window.shaderxEditor.traffic.decode") == decodes
        assert console_problems(browser) == []
        screenshot(browser, "editor-exr-texture.png", tmp_path)
    finally:
        served.close()


def test_a_dropped_zip_opens_its_document_and_its_folders_resolve_the_references(editor, tmp_path):
    archive = io.BytesIO()
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("look/textures/green.png", png(8, 8, GREEN))
        z.writestr("look/other/green.png", png(8, 8, RED))  # same name, another folder: not the one named
        z.writestr("look/materials/green.mtlx", material("../textures/green.png"))
    before = counters(editor)
    drop_files(editor, [("look.zip", archive.getvalue())])
    shown(editor, before)
    assert "../textures/green.png" in editor.find_element("id", "document").get_attribute("value")
    assert list(textures_listed(editor).values()) == ["loaded: ../textures/green.png (dropped)"]
    assert_is(centre_colour(editor, tmp_path), GREEN)
    assert console_problems(editor) == []


def test_a_dropped_usdz_is_generated_as_it_is_with_its_own_members_as_textures(editor, tmp_path):
    package = usdz([(LAYER, textured_layer("textures/wood.png").encode()), ("textures/wood.png", png(8, 8, BLUE))])
    before = counters(editor)
    drop_files(editor, [("wood.usdz", package)])
    shown(editor, before)
    assert js(editor, "window.shaderxEditor.state.record.element") == "/Looks/Wood"
    assert list(textures_listed(editor).values()) == ["loaded: textures/wood.png (dropped)"]
    assert_is(centre_colour(editor, tmp_path), BLUE)
    assert console_problems(editor) == []
