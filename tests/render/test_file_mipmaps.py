"""A renderer made with file_mipmaps=False reads file images from their base level (the
like-for-like read of bench/osl_agreement.py); by default they are read from their mipmaps."""
import numpy as np
import pytest

from shadergen.api import Generator
from shadergen.render import Renderer


@pytest.fixture
def stripes(tmp_path) -> str:
    """A document reading an image of 1-texel black and white columns, 60 texels wide."""
    oiio = pytest.importorskip("OpenImageIO")
    pixels = np.zeros((60, 60, 3), "f4")
    pixels[:, 1::2] = 1.0
    assert oiio.ImageBuf(pixels).write(str(tmp_path / "stripes.exr"))
    return """<?xml version="1.0"?>
<materialx version="1.39">
  <image name="img" type="color3"><input name="file" type="filename" value="stripes.exr"/></image>
  <output name="out" type="color3" nodename="img"/>
</materialx>"""


@pytest.mark.parametrize("mipmaps", [True, False])
def test_a_minified_image_reads_its_mipmaps_or_its_base_level(renderer, stripes, tmp_path, mipmaps):
    record = Generator().prepare(stripes).emit()
    reader = renderer if mipmaps else Renderer(search_paths=[], file_mipmaps=False)
    inside = reader.render(record, size=8, mesh="plane", document_dir=str(tmp_path)).rgba[1:-1, 1:-1, 0]
    if mipmaps:  # a level where the columns have averaged to grey
        np.testing.assert_allclose(inside, 0.5, atol=0.02)
    else:  # single bilinear lookups between a black and a white column, at a pixel's own fraction
        assert inside.max() - inside.min() > 0.5
