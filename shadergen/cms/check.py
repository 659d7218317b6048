"""Our generated colour transforms against OCIO's own CPU processor (tests and bench/color.py).

A ramp of test colours is an EXR of one row; a document samples it (closest texel) on a plane,
with the file's colour space set to the space under test. The same document without a colour
space draws the source colours themselves, so each pixel's expected value is OCIO's CPU
processor applied to what that pixel sampled: no assumption about which texel lands where.
"""
import os
import tempfile

import numpy as np

from ..api import DocumentFile, Generator
from ..errors import ShaderGenError

RAMP = """<?xml version="1.0"?>
<materialx version="1.39"{working}>
  <nodegraph name="ramp">
    <image name="colours" type="color3">
      <input name="file" type="filename" value="ramp.exr"{space} />
      <input name="filtertype" type="string" value="closest" />
    </image>
    <output name="out" type="color3" nodename="colours" />
  </nodegraph>
</materialx>
"""


def test_colours(n: int = 256) -> np.ndarray:
    """(n, 3) float32 colours over [0, 1]: a ramp in red, faster ramps in green and blue, so
    every channel meets every part of a transfer function and the channels mix."""
    t = np.linspace(0.0, 1.0, n, dtype="f8")
    return np.stack([t, (t * 7.0) % 1.0, (t * 13.0) % 1.0], 1).astype("f4")


def _attribute(name: str, value: str | None) -> str:
    from xml.sax.saxutils import quoteattr
    return f" {name}={quoteattr(value)}" if value else ""


class RampCheck:
    """Draws the ramp through a config's transforms on GL; one folder, renderer and generator."""

    def __init__(self, config: str, working: str, colours: np.ndarray | None = None, size: int = 64,
                 target: str = "glsl"):
        """`target`: glsl (drawn by GL) or wgsl (drawn by WebGPU)."""
        from ..render import Renderer
        from ..render.imageio import write_image
        from .ocio import OcioCMS

        self.config, self.working, self.size, self.target = config, working, size, target
        self.cms = OcioCMS.for_config(config)
        self.colours = test_colours() if colours is None else colours
        self.folder = tempfile.mkdtemp(prefix="shadergen-colour-")
        rgba = np.concatenate([self.colours, np.ones((len(self.colours), 1), "f4")], 1)[None]
        write_image(os.path.join(self.folder, "ramp.exr"), rgba)
        self.generator = Generator()
        if target == "wgsl":
            from ..render.wgpu_renderer import WgpuRenderer
            self.renderer = WgpuRenderer()
        else:
            self.renderer = Renderer()
        self.source = self.draw(None)[0]  # what each pixel samples

    def record(self, space: str | None) -> dict:
        path = os.path.join(self.folder, "ramp.mtlx")
        with open(path, "w") as f:
            f.write(RAMP.format(working=_attribute("colorspace", self.working), space=_attribute("colorspace", space)))
        record = next(iter(self.generator.records(DocumentFile(path), target=self.target, interface="specialized",
                                                  lights=False, cms="ocio", ocio_config=self.config)))
        if "error" in record:
            raise ShaderGenError(record["error"]["code"], record["error"]["message"], record["error"]["where"])
        return record

    def draw(self, space: str | None, frames: int = 1) -> tuple[np.ndarray, dict]:
        """(rgba of the plane, the render's timings) with the ramp in `space` (None: as is)."""
        result = self.renderer.render(self.record(space), size=self.size, mesh="plane", frames=frames,
                                      document_dir=self.folder)
        return result.rgba, result.timings_ms

    def error(self, space: str) -> tuple[float, float, bool]:
        """(max absolute error of the GL draw against OCIO's CPU processor, the same error over
        max(1, |expected|), whether the transform samples a LUT) for the ramp in `space`. The
        second is the one float32 can meet where a log space's 1.0 is a linear 200."""
        drawn = self.draw(space)[0]
        covered = self.source[..., 3] > 0.5
        source = np.ascontiguousarray(self.source[covered][:, :3], "f4")
        expected = source.copy()
        transform = self.cms.transform_for(self.cms.require(space, "source", space),
                                           self.cms.require(self.working, "working", "ramp"))
        if transform is not None:
            transform.cpu.applyRGB(expected)
        difference = np.abs(drawn[covered][:, :3] - expected)
        return (float(difference.max()), float((difference / np.maximum(1.0, np.abs(expected))).max()),
                transform is not None and transform.has_luts)

    def folded(self, space: str) -> float:
        """Max difference, over max(1, |expected|), of the values `specialized` folds (a constant
        of each test colour in `space`) from OCIO's CPU processor applied to them."""
        transform = self.cms.transform_for(self.cms.require(space, "source", space),
                                           self.cms.require(self.working, "working", "ramp"))
        worst = 0.0
        for colour in self.colours[:: max(1, len(self.colours) // 16)]:
            value = ", ".join(repr(float(c)) for c in colour)
            text = (f'<?xml version="1.0"?><materialx version="1.39"{_attribute("colorspace", self.working)}>'
                    f'<constant name="c" type="color3"><input name="value" type="color3" value="{value}"'
                    f'{_attribute("colorspace", space)} /></constant><output name="out" type="color3" nodename="c" />'
                    f'</materialx>')
            graph = self.generator.prepare(text, interface="specialized", cms="ocio", ocio_config=self.config).graph
            out = next(iter(graph.outputs.values()))
            if out.node.category != "constant":
                raise ShaderGenError("not_folded", f"the constant in '{space}' was not folded", space)
            got = np.array(out.node.inputs["value"].value, "f8")
            want = np.array(colour, "f4")[None].copy()
            if transform is not None:
                transform.cpu.applyRGB(want)
            worst = max(worst, float((np.abs(got - want[0]) / np.maximum(1.0, np.abs(want[0]))).max()))
        return worst
