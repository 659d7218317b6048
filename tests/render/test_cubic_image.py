"""A cubic <image> reads the bicubic B-spline of its texels on GL (libraries/stdlib/genglsl/lib/
mx_texture.glsl), as OIIO's "cubic" does in OSL; GL's sampler has no cubic filter, and the library
read cubic as linear before."""
import numpy as np
import pytest

from shadergen.api import Generator
from tests.documents import image_document


@pytest.mark.parametrize("filtertype", ["cubic", "linear"])
def test_a_cubic_read_is_the_b_spline_of_its_texels(renderer, tmp_path, filtertype):
    """A row of 16 white texels with texel 10 black, magnified about 3 pixels a texel: linear reads
    the black texel's centre as 0 (the nearest sample at most 1/6 texel off it: at most 1/6); the
    B-spline spreads it, its weights at distances 0 and 1 being 4/6 and 1/6, so it reads 1 - 4/6 =
    1/3 at the centre, more elsewhere (1 - B(1/6) = 0.359 at 1/6 texel off), and 1 two texels away."""
    oiio = pytest.importorskip("OpenImageIO")
    pixels = np.ones((1, 16, 3), "f4")
    pixels[0, 10] = 0.0
    assert oiio.ImageBuf(pixels).write(str(tmp_path / "row.exr"))
    record = Generator().prepare(image_document("row.exr", filtertype)).emit()
    row = renderer.render(record, size=64, mesh="plane", document_dir=str(tmp_path)).rgba[32]
    reds = row[row[:, 3] > 0.5, 0]  # the plane's pixels (the background has alpha 0)
    if filtertype == "cubic":
        assert 1 / 3 - 1e-3 <= reds.min() <= 0.36
    else:
        assert reds.min() <= 1 / 6
    assert (reds >= 1 - 1e-3).sum() >= 16  # the texels two or more away from the black one read 1
