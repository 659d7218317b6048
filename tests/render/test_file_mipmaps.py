"""A renderer made with file_mipmaps=False reads file images from their base level (the
like-for-like read of bench/osl_agreement.py); by default they are read from their mipmaps."""
import numpy as np
import pytest

from shadergen.api import Generator
from shadergen.render import Renderer


def stripes(folder, columns: int) -> str:
    """A document reading an image of 1-texel black and white columns, `columns` texels wide."""
    oiio = pytest.importorskip("OpenImageIO")
    pixels = np.zeros((columns, columns, 3), "f4")
    pixels[:, 1::2] = 1.0
    assert oiio.ImageBuf(pixels).write(str(folder / "stripes.exr"))
    return """<?xml version="1.0"?>
<materialx version="1.39">
  <image name="img" type="color3"><input name="file" type="filename" value="stripes.exr"/></image>
  <output name="out" type="color3" nodename="img"/>
</materialx>"""


# Mipmapped: 64 columns, a power of two, stored as they are (test_texture_sides.py bounds what
# resampling other sides leaves). Base level: 60 columns, the file's own, so that 8 pixels' lookups
# fall at 8 different fractions of a texel.
@pytest.mark.parametrize("mipmaps, columns", [(True, 64), (False, 60)])
def test_a_minified_image_reads_its_mipmaps_or_its_base_level(renderer, tmp_path, mipmaps, columns):
    record = Generator().prepare(stripes(tmp_path, columns)).emit()
    reader = renderer if mipmaps else Renderer(search_paths=[], file_mipmaps=False)
    inside = reader.render(record, size=8, mesh="plane", document_dir=str(tmp_path)).rgba[1:-1, 1:-1, 0]
    if mipmaps:  # a level where the columns have averaged to grey
        np.testing.assert_allclose(inside, 0.5, atol=0.02)
    else:  # single bilinear lookups between a black and a white column, at a pixel's own fraction
        assert inside.max() - inside.min() > 0.5


def test_a_clamped_edge_without_mipmaps_reads_the_edge_texel(tmp_path):
    """A clamped axis beyond its edge reads the base level's edge texel when the image is bound
    without mipmaps: the edge inset is half a texel of the level the sampler reads (level 0 here),
    not of a level chosen as if mipmaps existed (10 texels in, a white column, before)."""
    oiio = pytest.importorskip("OpenImageIO")
    pixels = np.ones((60, 60, 3), "f4")
    pixels[:, 0] = 0.0  # the left edge column black, the rest white
    assert oiio.ImageBuf(pixels).write(str(tmp_path / "edge.exr"))
    document = """<?xml version="1.0"?>
<materialx version="1.39">
  <texcoord name="tc" type="vector2"/>
  <multiply name="scaled" type="vector2"><input name="in1" type="vector2" nodename="tc"/>
    <input name="in2" type="float" value="2"/></multiply>
  <subtract name="shifted" type="vector2"><input name="in1" type="vector2" nodename="scaled"/>
    <input name="in2" type="float" value="0.5"/></subtract>
  <image name="img" type="color3"><input name="file" type="filename" value="edge.exr"/>
    <input name="texcoord" type="vector2" nodename="shifted"/>
    <input name="uaddressmode" type="string" value="clamp"/></image>
  <output name="out" type="color3" nodename="img"/>
</materialx>"""
    record = Generator().prepare(document).emit()
    image = Renderer(search_paths=[], file_mipmaps=False).render(record, size=8, mesh="plane",
                                                                 document_dir=str(tmp_path)).rgba[1:-1, 1:-1, 0]
    np.testing.assert_allclose(image[:, 0], 0.0, atol=1e-3)  # u < 0: clamped to column 0
    np.testing.assert_allclose(image[:, 1:], 1.0, atol=1e-3)
