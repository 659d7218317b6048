"""WgpuRenderer: draws WGSL and Vulkan (SPIR-V) shader records with WebGPU (the `wgpu` package on Vulkan; Mesa's lavapipe
without a GPU) in the same scene as the GL renderer: the same meshes, camera, environment, light
rigs, values and file textures (base.py and inputs.py hold what both share), so an image of our
WGSL or Vulkan GLSL can be compared pixel for pixel with one of our GLSL.

Differences from GL that the scene absorbs: clip-space depth runs 0..1 (the projection is
remapped, x and y untouched); framebuffer rows come back top first; mipmaps are built here (WebGPU
has no glGenerateMipmap), by the same 2 x 2 box filter; the sampler cannot clamp to a border colour,
which the generated code does itself (its image fetch handles MaterialX's address modes).
"""
import functools
import os
import time
from dataclasses import dataclass

import numpy as np

from .base import RenderResult, SceneRenderer
from .errors import RenderError
from .inputs import ENV_SAMPLERS, env_samples_for, lighting_values, light_rig, record_values, texture_requests
from .record import check_record, source_digest
from .textures import (GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT, GL_REPEAT, MAX_LUTS, Sampling, lut_image, lut_key,
                       mip_chain, rgba)
from .wgpu_device import wgpu_device
from .wgpu_program import COLOR_FORMAT, DEPTH_FORMAT, STAGES, WgpuPipeline

WGPU_TARGETS = ("wgsl", "vulkan")
ADDRESS_MODES = {GL_REPEAT: "repeat", GL_MIRRORED_REPEAT: "mirror-repeat", GL_CLAMP_TO_EDGE: "clamp-to-edge"}
ENV_SAMPLING = Sampling(wrap_v=GL_CLAMP_TO_EDGE)  # lat-long: around in longitude, stopped at the poles
# a LUT (filter linear or not): clamped at its edges, as OCIO's code expects
LUT_SAMPLING = {linear: Sampling(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, not linear) for linear in (False, True)}


@dataclass
class WgpuTexture:
    texture: object
    view: object
    width: int
    height: int
    components: int = 4

    def release(self) -> None:
        self.texture.destroy()


class WgpuRenderer(SceneRenderer):
    """Renders WGSL and Vulkan records; the arguments are SceneRenderer's."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._targets: dict[int, tuple] = {}
        self._samplers: dict[Sampling, object] = {}
        self._luts: dict[tuple, WgpuTexture] = {}  # a LUT's description -> its texture

    def render(self, record: dict, *, size: int = 256, mesh: str = "sphere", env=None, env_samples: int | None = None,
               env_method: str = "fis", lights=None, supersample: int = 1, document_dir: str | None = None,
               frames: int = 1) -> RenderResult:
        """As Renderer.render; the environment is always importance-sampled (`env_method` fis)."""
        start = time.perf_counter()
        vertex, pixel = check_record(record, WGPU_TARGETS)
        element = record.get("element")
        side = self._image_side(size, supersample, element)
        if env_method != "fis":
            raise RenderError("invalid_request", "the wgpu backend samples the environment (env_method 'fis') only",
                              element)
        device = wgpu_device(self.lp_threads)
        program, compile_link_ms, reused = self._program(source_digest(vertex, pixel),
                                                         lambda: WgpuPipeline(device, record, element))
        vertex_buffers, index_buffer, index_count = program.vertex_buffers(device, *self._mesh(mesh, record))
        make = functools.partial(upload, device)
        environment, env_textures = self._environment(env, make)
        if document_dir is None and isinstance(record.get("document"), str):
            document_dir = os.path.dirname(os.path.abspath(record["document"]))

        warnings: list[str] = []
        rig = light_rig(record, lights)
        values = lighting_values(environment, env_samples_for(env_method, env_samples), rig, depth_zero_to_one=True)
        if rig and not any(m["type"] == "LightData" for m in program.layout["pixel"]["members"]):
            warnings.append("the shader reads no u_lightData (generated without lights?): the light rig has no effect")
        values.update(record_values(record, set(values) | set(ENV_SAMPLERS)))
        self._textures.trim()
        textures = {"u_envRadiance": (env_textures.radiance, ENV_SAMPLING),
                    "u_envIrradiance": (env_textures.irradiance, ENV_SAMPLING)}
        for name, entry in (record.get("luts") or {}).items():  # colour transforms' tables (cms/ocio.py)
            textures[name] = (self._lut(device, entry), LUT_SAMPLING[entry.get("filter") == "linear"])
        for request in texture_requests(record, document_dir, self.search_paths, self.texture_roots, self.confined):
            if request.name not in textures:
                texture, warning = self._textures.texture(make, request)
                warnings += [warning] if warning else []
                textures[request.name] = (texture, request.sampling)
        bind_groups = [self._bind_group(device, program, group, stage, values, textures, warnings)
                       for group, stage in enumerate(STAGES)]

        colour, depth = self._target(device, side)
        frame_ms = []
        for _ in range(max(1, frames)):
            t0 = time.perf_counter()
            encoder = device.create_command_encoder()
            rpass = encoder.begin_render_pass(
                color_attachments=[{"view": colour.create_view(), "load_op": "clear", "store_op": "store",
                                    "clear_value": (0.0, 0.0, 0.0, 0.0)}],
                depth_stencil_attachment={"view": depth.create_view(), "depth_load_op": "clear",
                                          "depth_store_op": "store", "depth_clear_value": 1.0})
            rpass.set_pipeline(program.pipeline)
            for group, bind_group in enumerate(bind_groups):
                rpass.set_bind_group(group, bind_group)
            for slot, buffer in enumerate(vertex_buffers):
                rpass.set_vertex_buffer(slot, buffer)
            rpass.set_index_buffer(index_buffer, "uint32")
            rpass.draw_indexed(index_count)
            rpass.end()
            device.queue.submit([encoder.finish()])
            raw = device.queue.read_texture({"texture": colour, "origin": (0, 0, 0), "mip_level": 0},
                                            {"offset": 0, "bytes_per_row": side * 16}, (side, side, 1))
            frame_ms.append((time.perf_counter() - t0) * 1e3)
        rgba = np.frombuffer(raw, "f4").reshape(side, side, 4)  # WebGPU's first row is the top
        return self._result(rgba, size, supersample, frame_ms, start, compile_link_ms, reused, warnings)

    def _bind_group(self, device, program: WgpuPipeline, group: int, stage: str, values: dict, textures: dict,
                    warnings: list[str]):
        """Group `group`: the stage's uniform buffer, then each of its textures and samplers; a
        sampler the record does not describe gets black."""
        import wgpu

        stage_layout = program.layout[stage]
        entries = []
        if stage_layout["members"]:
            data = program.uniform_bytes(stage, values, warnings)
            buffer = device.create_buffer_with_data(data=data, usage=wgpu.BufferUsage.UNIFORM)
            entries.append({"binding": 0, "resource": {"buffer": buffer, "offset": 0, "size": len(data)}})
        for t in stage_layout["textures"]:
            texture, sampling = textures.get(t["name"], (None, Sampling()))
            if texture is None:
                texture = self._textures.constant(functools.partial(upload, device), Sampling.border)
                warnings.append(f"sampler {t['name']} is not described by the record; bound black")
            entries.append({"binding": t["texture_binding"], "resource": texture.view})
            entries.append({"binding": t["sampler_binding"], "resource": self._sampler(device, sampling)})
        return device.create_bind_group(layout=program.bind_group_layouts[group], entries=entries)

    def _lut(self, device, entry: dict) -> WgpuTexture:
        key = lut_key(entry)
        if key not in self._luts:
            if len(self._luts) >= MAX_LUTS:
                for texture in self._luts.values():
                    texture.release()
                self._luts.clear()
            self._luts[key] = upload(device, lut_image(entry), mipmaps=False)
        return self._luts[key]

    def _sampler(self, device, sampling: Sampling):
        """MaterialX's sampler state as WebGPU has it: trilinear or nearest; a border clamps to the
        edge here (the generated code returns the border colour itself)."""
        key = Sampling(sampling.wrap_u, sampling.wrap_v, sampling.closest)
        if key not in self._samplers:
            texel = "nearest" if sampling.closest else "linear"
            self._samplers[key] = device.create_sampler(
                address_mode_u=ADDRESS_MODES.get(sampling.wrap_u, "clamp-to-edge"),
                address_mode_v=ADDRESS_MODES.get(sampling.wrap_v, "clamp-to-edge"),
                mag_filter=texel, min_filter=texel, mipmap_filter=texel)
        return self._samplers[key]

    def _target(self, device, side: int) -> tuple:
        import wgpu

        if side not in self._targets:
            usage = wgpu.TextureUsage.RENDER_ATTACHMENT
            colour = device.create_texture(size=(side, side, 1), format=COLOR_FORMAT,
                                           usage=usage | wgpu.TextureUsage.COPY_SRC)
            depth = device.create_texture(size=(side, side, 1), format=DEPTH_FORMAT, usage=usage)
            self._targets[side] = (colour, depth)
        return self._targets[side]


def upload(device, image: np.ndarray, mipmaps: bool = True) -> WgpuTexture:
    """A float32 (h, w, c) image, top row first, as an rgba32float texture with its mip chain
    (row 0 at v = 0, as GL's upload puts it: the generated code flips v). Grey images read as
    grey, as the GL renderer's do (textures.rgba). A LUT has no mipmaps (a table, not an image)."""
    import wgpu

    image = rgba(np.asarray(image, "f4"))
    height, width = image.shape[:2]
    levels = mip_chain(image) if mipmaps else [image]
    texture = device.create_texture(size=(width, height, 1), format="rgba32float", mip_level_count=len(levels),
                                    usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
    for level, data in enumerate(levels):
        h, w = data.shape[:2]
        device.queue.write_texture({"texture": texture, "mip_level": level, "origin": (0, 0, 0)},
                                   np.ascontiguousarray(data), {"offset": 0, "bytes_per_row": w * 16}, (w, h, 1))
    return WgpuTexture(texture, texture.create_view(), width, height)
