"""The Vulkan target: the GLSL target's stage assembly (targets/glsl/target.py) with what Vulkan
GLSL requires instead of GLSL 4.00's.

- `#version 450`; no loose uniforms: each stage's uniforms, public and private, are the members of
  one std140 block with no instance name (so the code reads them by their own names), in set 0
  for the vertex stage and set 1 for the pixel stage at binding 0 (layout.py); each texture a
  `texture2D` and a `sampler` at the next two bindings of the set (printer.py says why apart).
  No initialisers: a block member has none; the values come from the listing.
- Every stage input and output at an explicit location (app data in listing order, vertex data
  `vd_<member>` in listing order, the pixel output at 0). Vertex data is no interface block, as
  Vulkan GLSL allows, because naga, which reads our SPIR-V for WebGPU, takes none.
- The record carries each stage's SPIR-V (glslangValidator, spirv.py), base64, under "spirv".
"""
import base64

from ...shader import Writer
from ..glsl.target import GlslTarget
from .layout import SETS, std140_layout
from .printer import VulkanPrinter
from .spirv import compile_stages


class VulkanTarget(GlslTarget):
    name = "vulkan"
    header = ("#version 450",)
    uniform_initializers = False
    # vertex data as `vd_<member>` variables, as in ESSL: WebGPU (naga) takes no interface blocks
    vertex_data_block = False
    printer_class = VulkanPrinter

    def layout(self, ctx) -> dict:
        """Each stage's uniform block (set, binding, std140 offsets of its members) and textures."""
        return {stage: std140_layout(ctx.stages[stage], set_index) for set_index, stage in enumerate(SETS)}

    @staticmethod
    def compiled(stages: dict[str, str]) -> dict:
        """The record's "spirv": each stage's module, base64."""
        return {"spirv": {stage: base64.b64encode(module).decode("ascii")
                          for stage, module in compile_stages(stages).items()}}

    @staticmethod
    def io(direction: str, location: int) -> str:
        return f"layout(location = {location}) {direction}"

    def _uniforms(self, stage, w: Writer) -> None:
        set_index = SETS.index(stage.name)
        layout = std140_layout(stage, set_index)
        if layout["members"]:
            w.line(f"layout(std140, set = {set_index}, binding = 0) uniform {stage.name.capitalize()}Uniforms")
            w.line("{")
            for m in layout["members"]:
                w.line(f"    {self.printer.declarator(m['glsl'], m['name'])};  // offset {m['offset']}")
            w.line("};")
            w.line()
        for t in layout["textures"]:
            w.line(f"layout(set = {set_index}, binding = {t['texture_binding']}) uniform texture2D {t['name']};")
            w.line(f"layout(set = {set_index}, binding = {t['sampler_binding']}) uniform sampler {t['name']}_sampler;")
        if layout["textures"]:
            w.line()
