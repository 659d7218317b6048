"""A record's GL program: compiling and linking it (errors located by stage and line), writing
uniform values in the form the linked program declares, and feeding its vertex inputs from a mesh.

What the program declares is the truth here: an input the driver optimised away is simply not
bound, and a value is converted to the declared GLSL type rather than trusted from the listing.
"""
import re
import struct
import time

import numpy as np

from .errors import RenderError
from .geometry import Mesh

GL_SAMPLER_2D = 0x8B5E
_STAGE_NAMES = {"vertex_shader": "vertex", "fragment_shader": "pixel"}
_GLSL_ERROR = re.compile(r"^\s*\d+:(\d+)\(\d+\): error: (.*)$", re.MULTILINE)


class Program:
    def __init__(self, ctx, vertex: str, pixel: str, element: str | None = None):
        start = time.perf_counter()
        try:
            self.gl = ctx.program(vertex_shader=vertex, fragment_shader=pixel)
        except Exception as exc:  # moderngl.Error carries the driver's log
            raise _compile_error(str(exc), element) from exc
        self.compile_link_ms = (time.perf_counter() - start) * 1e3
        self.attributes = {}  # name -> (components, 'f' or 'i')
        self.uniforms = {}    # name -> moderngl.Uniform, samplers excluded
        self.samplers = []
        for name in self.gl:
            member = self.gl[name]
            kind = type(member).__name__
            if kind == "Attribute":
                self.attributes[name] = (member.dimension, "i" if member.shape in "iI" else "f")
            elif kind == "Uniform":
                if member.gl_type == GL_SAMPLER_2D:
                    self.samplers.append(name)
                else:
                    self.uniforms[name] = member
        self._vertex_arrays = {}

    def set_uniform(self, name: str, value: list[float] | bytes) -> str | None:
        """Write numbers (or ready-made bytes) to a uniform the program uses; a value that does not
        fit the declared type is left out and described in the returned warning."""
        uniform = self.uniforms.get(name)
        if uniform is None:
            return None
        if isinstance(value, bytes):
            uniform.write(value)
            return None
        per_element, kind = int(uniform.fmt[:-1]), uniform.fmt[-1]
        count = per_element * uniform.array_length
        if uniform.array_length > 1 and len(value) < count and len(value) % per_element == 0:
            value = list(value) + [0.0] * (count - len(value))  # a shorter array fills the front
        if len(value) != count:
            return f"uniform {name}: value has {len(value)} numbers, the shader declares {count}; left at its default"
        if kind in "iI":
            value = [int(round(v)) for v in value]
        uniform.write(struct.pack(f"{count}{kind}", *value))
        return None

    def vertex_array(self, ctx, mesh_key: str, mesh: Mesh):
        """The program's vertex array for a mesh (cached): every active vertex input from the
        mesh's stream of that name; Mesh.stream raises missing_stream for what it cannot supply."""
        if mesh_key not in self._vertex_arrays:
            streams = []  # gathered first, so a missing stream leaves no GL buffers behind
            for name, (components, kind) in sorted(self.attributes.items()):
                data = mesh.stream(name, components)
                streams.append((np.rint(data).astype("i4") if kind == "i" else data, f"{components}{kind}", name))
            buffers = [ctx.buffer(data.tobytes()) for data, _, _ in streams]
            content = [(buffer, layout, name) for buffer, (_, layout, name) in zip(buffers, streams)]
            buffers.append(ctx.buffer(np.ascontiguousarray(mesh.indices, "u4").tobytes()))
            vao = ctx.vertex_array(self.gl, content, index_buffer=buffers[-1], index_element_size=4)
            self._vertex_arrays[mesh_key] = (vao, buffers)
        return self._vertex_arrays[mesh_key][0]

    def release(self) -> None:
        for vao, buffers in self._vertex_arrays.values():
            vao.release()
            for buffer in buffers:
                buffer.release()
        self.gl.release()


def _compile_error(log: str, element: str | None) -> RenderError:
    """The driver's log as a RenderError whose `where` is "stage:line" of the first error."""
    stage = next((ours for theirs, ours in _STAGE_NAMES.items() if theirs in log), None)
    first = _GLSL_ERROR.search(log)
    if "Linker failed" in log or stage is None:
        where = "link"
    else:
        where = f"{stage}:{first.group(1)}" if first else stage
    detail = first.group(2) if first else log.strip().splitlines()[-1] if log.strip() else "unknown error"
    prefix = f"{element}: " if element else ""
    return RenderError("compile_error", f"{prefix}GLSL {'link' if where == 'link' else 'compile'} failed: {detail}\n{log.strip()}", where)
