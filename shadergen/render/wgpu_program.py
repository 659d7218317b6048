"""The render pipeline of a record WebGPU draws: a WGSL record's two modules (`vertexMain`,
`fragmentMain`), or a Vulkan record's SPIR-V (its `spirv`, base64; `main` in each; naga reads it
into the same pipeline). Both targets publish the same `layout` (group or set 0 the vertex stage's,
1 the pixel stage's: binding 0 the uniform buffer, then a texture and its sampler per filename
uniform; Vulkan's std140 offsets are WGSL's, targets/vulkan/layout.py), so bind group layouts,
vertex buffers fed from the AppData listing in location order, and uniform buffers packed at the
layout's byte offsets are made alike.
"""
import base64
import binascii
import struct
import time

import numpy as np

from ..targets.closures import LIGHT_DATA_MEMBERS
from ..targets.wgsl.layout import MEMBER, struct_members
from .errors import RenderError
from .geometry import Mesh
from .wgpu_device import shader_module

STAGES = ("vertex", "pixel")
COLOR_FORMAT, DEPTH_FORMAT = "rgba32float", "depth32float"
# Vertex inputs by MaterialX type: (components, WebGPU vertex format).
VERTEX_FORMATS = {"float": (1, "float32"), "vector2": (2, "float32x2"), "vector3": (3, "float32x3"),
                  "color3": (3, "float32x3"), "vector4": (4, "float32x4"), "color4": (4, "float32x4"),
                  "integer": (1, "sint32")}
# target -> (vertex, pixel) entry points
ENTRY_POINTS = {"wgsl": ("vertexMain", "fragmentMain"), "vulkan": ("main", "main")}
# Member types of the uniform buffer as WGSL names them (MEMBER: both targets' MaterialX types):
# (struct format of one column, columns, bytes between columns).
COLUMNS = {"f32": ("f", 1, 4), "i32": ("i", 1, 4), "vec2f": ("2f", 1, 8), "vec3f": ("3f", 1, 12),
           "vec4f": ("4f", 1, 16), "mat3x3f": ("3f", 3, 16), "mat4x4f": ("4f", 4, 16)}
LIGHT_DATA, LIGHT_DATA_SIZE = struct_members(LIGHT_DATA_MEMBERS)


class WgpuPipeline:
    def __init__(self, device, record: dict, element: str | None = None):
        import wgpu

        target = record.get("target")
        layout = record.get("layout")
        if not isinstance(layout, dict) or not all(isinstance(layout.get(s), dict) for s in STAGES):
            raise RenderError("invalid_record", f"a {target} record needs its 'layout' (uniform offsets and bindings)",
                              element)
        self.layout = layout
        start = time.perf_counter()
        code = _stage_code(record, element)
        modules = {s: shader_module(device, code[s], s) for s in STAGES}
        entry_points = dict(zip(STAGES, ENTRY_POINTS[target]))
        self.bind_group_layouts = [device.create_bind_group_layout(entries=self._layout_entries(layout[s]))
                                   for s in STAGES]
        self.app_data = [(v["name"], *VERTEX_FORMATS[v["type"]])
                         for v in record["blocks"]["vertex"].get("AppData", []) if v.get("type") in VERTEX_FORMATS]
        vertex_buffers = [{"array_stride": 4 * components, "step_mode": "vertex",
                           "attributes": [{"format": fmt, "offset": 0, "shader_location": i}]}
                          for i, (_, components, fmt) in enumerate(self.app_data)]
        try:
            self.pipeline = device.create_render_pipeline(
                layout=device.create_pipeline_layout(bind_group_layouts=self.bind_group_layouts),
                vertex={"module": modules["vertex"], "entry_point": entry_points["vertex"], "buffers": vertex_buffers},
                primitive={"topology": wgpu.PrimitiveTopology.triangle_list, "cull_mode": wgpu.CullMode.none},
                depth_stencil={"format": DEPTH_FORMAT, "depth_write_enabled": True, "depth_compare": "less"},
                fragment={"module": modules["pixel"], "entry_point": entry_points["pixel"],
                          "targets": [{"format": COLOR_FORMAT}]})
        except Exception as exc:  # wgpu's validation error: stages or bindings that do not fit together
            raise RenderError("compile_error", f"{element + ': ' if element else ''}{target} pipeline rejected: {exc}",
                              "link") from exc
        self.compile_link_ms = (time.perf_counter() - start) * 1e3
        self._vertex_buffers: dict[str, tuple[list, object, int]] = {}

    @staticmethod
    def _layout_entries(stage_layout: dict) -> list[dict]:
        import wgpu

        visible = wgpu.ShaderStage.VERTEX | wgpu.ShaderStage.FRAGMENT
        entries = []
        if stage_layout["members"]:
            entries.append({"binding": 0, "visibility": visible, "buffer": {"type": "uniform"}})
        for t in stage_layout["textures"]:
            entries.append({"binding": t["texture_binding"], "visibility": visible,
                            "texture": {"sample_type": "float", "view_dimension": "2d"}})
            entries.append({"binding": t["sampler_binding"], "visibility": visible, "sampler": {"type": "filtering"}})
        return entries

    def uniform_bytes(self, stage: str, values: dict, warnings: list[str]) -> bytes:
        """The stage's uniform buffer: each member that `values` holds (numbers, or the bytes of
        a column-major matrix) at its offset; the rest zero. The light rig fills u_lightData[i]
        from `u_lightData[i].member` values."""
        buffer = bytearray(self.layout[stage]["size"])
        for m in self.layout[stage]["members"]:
            if m["type"] == "LightData":
                self._pack_lights(buffer, m["offset"], m["size"] // LIGHT_DATA_SIZE, values, warnings)
            elif MEMBER.get(m["type"], ("",))[0] in COLUMNS and m["name"] in values:
                _pack(buffer, m["offset"], MEMBER[m["type"]][0], values[m["name"]], m["name"], warnings)
        return bytes(buffer)

    @staticmethod
    def _pack_lights(buffer: bytearray, offset: int, count: int, values: dict, warnings: list[str]) -> None:
        for i in range(count):
            for member in LIGHT_DATA:
                name = f"u_lightData[{i}].{member['name']}"
                if name in values:
                    _pack(buffer, offset + i * LIGHT_DATA_SIZE + member["offset"], member["wgsl"], values[name], name,
                          warnings)

    def vertex_buffers(self, device, mesh_key: str, mesh: Mesh) -> tuple[list, object, int]:
        """(vertex buffers in location order, index buffer, index count) for a mesh (cached);
        Mesh.stream raises missing_stream for what it cannot supply."""
        import wgpu

        if mesh_key not in self._vertex_buffers:
            streams = []
            for name, components, fmt in self.app_data:
                data = mesh.stream(name, components)
                streams.append(np.rint(data).astype("i4") if fmt.startswith("sint") else data)
            buffers = [device.create_buffer_with_data(data=np.ascontiguousarray(d), usage=wgpu.BufferUsage.VERTEX)
                       for d in streams]
            indices = np.ascontiguousarray(mesh.indices, "u4")
            index = device.create_buffer_with_data(data=indices, usage=wgpu.BufferUsage.INDEX)
            self._vertex_buffers[mesh_key] = (buffers, index, len(indices))
        return self._vertex_buffers[mesh_key]

    def release(self) -> None:
        for buffers, index, _ in self._vertex_buffers.values():
            for buffer in [*buffers, index]:
                buffer.destroy()
        self._vertex_buffers.clear()


def _stage_code(record: dict, element: str | None) -> dict:
    """Each stage's module as wgpu takes it: WGSL text, or SPIR-V bytes."""
    if record.get("target") != "vulkan":
        return record["stages"]
    spirv = record.get("spirv")
    try:
        return {s: base64.b64decode(spirv[s], validate=True) for s in STAGES}
    except (TypeError, KeyError, binascii.Error):
        raise RenderError("invalid_record", "a vulkan record needs its 'spirv': each stage's module, base64",
                          element) from None


def _pack(buffer: bytearray, offset: int, wgsl: str, value, name: str, warnings: list[str]) -> None:
    """One member: ready-made bytes (a 4x4 matrix) as they are, numbers by the member's type, a
    matrix's columns at WGSL's 16-byte column stride."""
    fmt, columns, stride = COLUMNS[wgsl]
    if isinstance(value, bytes):
        buffer[offset:offset + len(value)] = value
        return
    per_column = int(fmt[:-1] or 1)
    if len(value) != per_column * columns:
        warnings.append(f"uniform {name}: value has {len(value)} numbers, the shader declares "
                        f"{per_column * columns}; left at zero")
        return
    numbers = [int(round(v)) for v in value] if fmt.endswith("i") else list(value)
    for c in range(columns):
        struct.pack_into(f"<{per_column}{fmt[-1]}", buffer, offset + c * stride,
                         *numbers[c * per_column:(c + 1) * per_column])
