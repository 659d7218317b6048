"""Issue 27, item 1, in a real browser (editor_testing.py): the document's node graph drawn as
boxes with typed ports and wires, a nested graph entered and left, a node's input edited on the
GPU alone, a node added from the service's nodedef listing and wired (a request), a wire of the
wrong type refused in place with its reason (no request, the document unchanged), a node
deleted, a wire taken away, and every edit undone and redone."""
import numpy as np

from editor_testing import browser, canvas_pixels, console_problems, editor, js, poll_js, screenshot, \
    wait_for_draw  # noqa: F401 (fixtures)
from service_testing import wait_until


def boxes(driver) -> list[str]:
    return js(driver, "[...document.querySelectorAll('#graph [data-box]')].map(g => g.dataset.box)")


def wires(driver) -> set[str]:
    return set(js(driver, "[...document.querySelectorAll('#graph path.wire[data-to]')].map(p => p.dataset.to)"))


def box(driver, name: str):
    return driver.find_element("css selector", f'#graph [data-box="{name}"]')


def port(driver, name: str, side: str, port_name: str):
    return box(driver, name).find_element("css selector", f'circle[data-side="{side}"][data-port="{port_name}"]')


def drag_wire(driver, source, target) -> None:
    from selenium.webdriver import ActionChains

    ActionChains(driver).click_and_hold(source).move_to_element(target).release(target).perform()


def document_text(driver) -> str:
    return driver.find_element("id", "document").get_attribute("value")


def requests(driver) -> int:
    return js(driver, "window.shaderxEditor.traffic.generate")


def wait_shown(driver, runs_before: int) -> None:
    wait_until(lambda: (poll_js(driver, "window.shaderxEditor.runs") or 0) > runs_before, 60, "the new record")


def add_node(driver, search: str, nodedef: str) -> None:
    field = driver.find_element("id", "palette-search")
    field.clear()
    field.send_keys(search)
    wait_until(lambda: driver.find_elements("css selector", f'#palette li[data-nodedef="{nodedef}"]'), 30, "the palette")
    driver.find_element("css selector", f'#palette li[data-nodedef="{nodedef}"]').click()


def test_the_graph_is_drawn_and_a_nested_graph_is_entered_and_left(editor, tmp_path):
    from selenium.webdriver import ActionChains
    from selenium.webdriver.support.select import Select

    runs = js(editor, "window.shaderxEditor.runs")
    Select(editor.find_element("id", "example")).select_by_value("marble.mtlx")
    wait_shown(editor, runs)
    assert boxes(editor) == ["NG_marble", "SR_marble", "Marble"]
    assert wires(editor) == {"SR_marble.emission_color", "Marble.surfaceshader"}
    assert port(editor, "NG_marble", "out", "base_color").get_attribute("data-type") == "color3"
    # laid out in columns: each box left of the boxes it feeds
    x = {name: box(editor, name).rect["x"] for name in boxes(editor)}
    assert x["NG_marble"] < x["SR_marble"] < x["Marble"]
    ActionChains(editor).double_click(box(editor, "NG_marble")).perform()
    wait_until(lambda: "split" in boxes(editor), 10, "the nodegraph entered")
    assert set(boxes(editor)) == {"pos", "scaled", "noise", "split", "veins", "frequency", "wave", "ridge", "valley",
                                  "vein", "color", "(outputs)"}
    assert {"veins.in1", "(outputs).base_color", "color.mix"} <= wires(editor)
    # the multioutput node's ports are its definition's
    assert port(editor, "split", "out", "outx").get_attribute("data-type") == "float"
    screenshot(editor, "editor-graph-nested.png", tmp_path)
    editor.find_element("css selector", '#graph-crumbs button[data-scope=""]').click()
    wait_until(lambda: boxes(editor) == ["NG_marble", "SR_marble", "Marble"], 10, "the document's scope again")
    assert console_problems(editor) == []


def test_an_input_edited_in_the_inspector_changes_the_gpu_alone_and_is_undone(editor, tmp_path):
    from selenium.webdriver import Keys

    box(editor, "SR_gold").click()
    field = editor.find_element("css selector", '#inspector [data-input="metalness"] input')
    assert field.get_attribute("value") == "1"
    before, sent, draws = canvas_pixels(editor, tmp_path), requests(editor), js(editor, "window.shaderxEditor.preview.stats.draws")
    original = document_text(editor)
    field.send_keys(Keys.CONTROL, "a")
    field.send_keys("0\n")  # Enter commits it (a change event)
    wait_for_draw(editor, draws)
    assert 'name="metalness" type="float" value="0"' in document_text(editor)
    changed = float((np.abs(canvas_pixels(editor, tmp_path) - before).max(axis=2) > 2 / 255).mean())
    assert changed > 0.05, f"only {changed:.1%} of the pixels changed"
    assert requests(editor) == sent
    assert js(editor, "window.shaderxEditor.timings.value.length") >= 1
    draws = js(editor, "window.shaderxEditor.preview.stats.draws")
    editor.find_element("id", "undo").click()
    wait_for_draw(editor, draws)
    assert document_text(editor) == original
    assert float(np.abs(canvas_pixels(editor, tmp_path) - before).max()) < 2 / 255
    editor.find_element("id", "redo").click()
    assert 'value="0"' in document_text(editor) and requests(editor) == sent
    assert console_problems(editor) == []


def test_a_node_is_added_wired_refused_deleted_and_undone(editor, tmp_path):
    runs, sent = js(editor, "window.shaderxEditor.runs"), requests(editor)
    add_node(editor, "constant color3", "ND_constant_color3")
    wait_until(lambda: "constant1" in boxes(editor), 10, "the new node")
    assert '<constant name="constant1" type="color3"' in document_text(editor)
    wait_shown(editor, runs)
    # a color3 output into a float input: refused where it was dropped, nothing sent or written
    sent, text = requests(editor), document_text(editor)
    drag_wire(editor, port(editor, "constant1", "out", "out"), port(editor, "SR_gold", "in", "metalness"))
    note = editor.find_element("id", "graph-note")
    wait_until(lambda: "refused" in note.text, 10, "the refusal")
    assert "constant1.out gives color3; SR_gold.metalness takes float" in note.text
    refusal = editor.find_element("css selector", "#graph text.refusal")
    assert "takes float" in refusal.text and refusal.is_displayed()
    assert document_text(editor) == text and requests(editor) == sent
    screenshot(editor, "editor-graph-refused.png", tmp_path)
    # a wire of the right type: the document and a new record
    runs = js(editor, "window.shaderxEditor.runs")
    drag_wire(editor, port(editor, "constant1", "out", "out"), port(editor, "SR_gold", "in", "base_color"))
    wait_until(lambda: "SR_gold.base_color" in wires(editor), 10, "the wire")
    assert 'name="base_color" type="color3" nodename="constant1"' in document_text(editor)
    wait_shown(editor, runs)
    assert requests(editor) == sent + 1
    wait_until(lambda: js(editor, "window.shaderxEditor.timings.topology.length") >= 1, 60, "the topology edit's frame")
    # a cycle is refused too
    runs = js(editor, "window.shaderxEditor.runs")
    add_node(editor, "multiply color3FA", "ND_multiply_color3FA")
    wait_shown(editor, runs)
    box(editor, "multiply1").find_element("css selector", "text.toggle").click()
    box(editor, "constant1").find_element("css selector", "text.toggle").click()
    runs = js(editor, "window.shaderxEditor.runs")
    drag_wire(editor, port(editor, "multiply1", "out", "out"), port(editor, "constant1", "in", "value"))
    wait_until(lambda: "constant1.value" in wires(editor), 10, "constant fed by multiply")
    wait_shown(editor, runs)
    drag_wire(editor, port(editor, "constant1", "out", "out"), port(editor, "multiply1", "in", "in1"))
    wait_until(lambda: "cycle" in editor.find_element("id", "graph-note").text, 10, "the cycle refused")
    # delete the constant: its wires go, base_color is its default again
    box(editor, "constant1").click()
    runs = js(editor, "window.shaderxEditor.runs")
    editor.find_element("css selector", '#inspector button[data-action="delete node"]').click()
    wait_until(lambda: "constant1" not in boxes(editor), 10, "the node deleted")
    assert "constant1" not in document_text(editor)
    assert "SR_gold.base_color" not in wires(editor)
    wait_shown(editor, runs)
    editor.find_element("id", "undo").click()
    wait_until(lambda: "constant1" in boxes(editor), 30, "the node back")
    assert 'nodename="constant1"' in document_text(editor)
    assert console_problems(editor) == []
    screenshot(editor, "editor-graph.png", tmp_path)


def test_a_wire_is_selected_and_taken_away(editor):
    from selenium.webdriver import ActionChains, Keys

    runs = js(editor, "window.shaderxEditor.runs")
    wire = editor.find_element("css selector", '#graph path.wire[data-to="Gold.surfaceshader"]')
    ActionChains(editor).move_to_element(wire).click().perform()
    selected = '#graph path.wire.selected[data-to="Gold.surfaceshader"]'  # the graph is drawn again
    wait_until(lambda: editor.find_elements("css selector", selected), 10, "the wire selected")
    ActionChains(editor).send_keys(Keys.DELETE).perform()
    wait_until(lambda: "Gold.surfaceshader" not in wires(editor), 10, "the wire taken away")
    assert 'nodename="SR_gold"' not in document_text(editor)
    wait_shown(editor, runs)
