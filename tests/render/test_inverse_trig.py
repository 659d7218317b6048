"""asin on the GL renderer is asin to float precision: the library writes it as atan(x, sqrt(1 - x^2))
(Mesa llvmpipe's own asin(0.5) is 0.5233885, off by 2e-4; bench/osl_agreement.py found it)."""
import math

import numpy as np
import pytest

from shadergen.api import Generator


@pytest.mark.parametrize("x", [0.5, -0.9, 0.999])
def test_asin_is_asin(renderer, x):
    document = f"""<?xml version="1.0"?>
<materialx version="1.39">
  <asin name="a" type="float"><input name="in" type="float" value="{x}"/></asin>
  <output name="out" type="float" nodename="a"/>
</materialx>"""
    record = Generator().prepare(document, interface="complete", values="source").emit()
    assert "asin(" not in record["stages"]["pixel"]  # a uniform's asin, computed by the shader
    image = renderer.render(record, size=8, mesh="plane").rgba
    np.testing.assert_allclose(image[4, 4, 0], math.asin(x), rtol=2e-6, atol=2e-6)
