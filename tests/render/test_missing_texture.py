"""A file that is missing shows its image node's `default`, whichever interface the shader was
generated with: `reduced` and `specialized` fold that input into the code, so the listing gives it
with the filename (`fallback`) for the renderer to bind."""
import numpy as np
import pytest

from shadergen.api import Generator

GEN = Generator()
DEFAULT = [0.8, 0.2, 0.4, 0.5]
DEFAULT_VALUE = f'value="{", ".join(map(str, DEFAULT))}"'


def missing_image(category: str, default: str = DEFAULT_VALUE, extra: str = "") -> str:
    """A color4 `category` node (image, or tiledimage: a nodegraph whose body holds the image)
    reading a file that does not exist, its `default` input given by `default`."""
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  {extra}
  <{category} name="tex" type="color4">
    <input name="file" type="filename" value="no_such_image.png" />
    <input name="default" type="color4" {default} />
  </{category}>
  <output name="out" type="color4" nodename="tex" />
</materialx>"""


def filename_variables(record: dict) -> list[dict]:
    return [v for v in record["blocks"]["pixel"]["PublicUniforms"] if v["type"] == "filename"]


@pytest.mark.parametrize("category", ["image", "tiledimage"])
@pytest.mark.parametrize("interface", ["complete", "reduced", "specialized"])
def test_a_missing_file_shows_the_nodes_default_in_every_interface(renderer, tmp_path, category, interface):
    record = GEN.prepare(missing_image(category), interface=interface).emit()
    assert [v["fallback"] for v in filename_variables(record)] == [DEFAULT]
    result = renderer.render(record, size=32, document_dir=str(tmp_path))
    assert any("no_such_image.png" in w and "not found" in w for w in result.warnings)
    np.testing.assert_allclose(result.rgba[16, 16], DEFAULT, atol=1e-6)


def test_a_default_computed_per_pixel_gives_no_fallback():
    document = missing_image("image", default='nodename="tint"', extra='<geomcolor name="tint" type="color4" />')
    files = filename_variables(GEN.prepare(document, interface="complete").emit())
    assert len(files) == 1 and "fallback" not in files[0]


@pytest.mark.timeout(120)  # the walk to the default once went round forever here
def test_each_of_several_tiled_images_gives_its_own_default(renderer, tmp_path):
    """Used several times, tiledimage's body is kept as a function: each node's `default` is bound
    to that function's parameter, whose origin is the node's own input."""
    defaults = [[0.1, 0.2, 0.3, 1.0], [0.4, 0.5, 0.6, 1.0], [0.7, 0.8, 0.9, 1.0]]
    nodes = "".join(f"""
    <tiledimage name="tex{i}" type="color4">
      <input name="file" type="filename" value="no_such_image_{i}.png" />
      <input name="default" type="color4" value="{", ".join(map(str, d))}" />
    </tiledimage>""" for i, d in enumerate(defaults))
    document = f"""<?xml version="1.0"?>
<materialx version="1.39">{nodes}
  <add name="ab" type="color4"><input name="in1" type="color4" nodename="tex0" /><input name="in2" type="color4" nodename="tex1" /></add>
  <add name="abc" type="color4"><input name="in1" type="color4" nodename="ab" /><input name="in2" type="color4" nodename="tex2" /></add>
  <output name="out" type="color4" nodename="abc" />
</materialx>"""
    record = GEN.prepare(document, interface="complete").emit()
    assert [v["fallback"] for v in filename_variables(record)] == defaults
    result = renderer.render(record, size=8, document_dir=str(tmp_path))
    np.testing.assert_allclose(result.rgba[4, 4, :3], np.sum(defaults, axis=0)[:3], atol=1e-5)
