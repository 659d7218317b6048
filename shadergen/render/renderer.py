"""Renderer: draws any shader record of the contract on a mesh in the fixed thumbnail scene.

A Renderer is meant to live as long as its worker process: the GL context (one per process),
compiled programs (by source digest: one per topology, since complete and reduced sources are
value-free and the values are bound from the listing), meshes, environments and file textures stay between
renders, so a repeat material costs one draw. Use it from the thread that first renders with it.
"""
import functools
import os
import time
from dataclasses import replace

import numpy as np

from shadergen.features import ENVIRONMENT_MACROS, ENVIRONMENTS

from .base import EnvironmentTextures, RenderResult, SceneRenderer
from .context import gl_context
from .errors import RenderError
from .inputs import ENV_SAMPLERS, env_samples_for, lighting_values, light_rig, record_values, texture_requests
from .prefilter import prefiltered_chain
from .program import Program
from .record import check_record, source_digest
from .textures import GL_CLAMP_TO_EDGE, MAX_LUTS, Sampling, bind, lut_key, upload, upload_lut

# How the generated code lights with the environment, and the macros its pixel stage is compiled
# with (shadergen/features.py): by filtered importance sampling of the radiance map
# (u_envRadianceSamples); from its GGX-prefiltered chain, one lookup; or that lookup corrected by
# u_envRadianceSamples samples of the chain (libraries/pbrlib/genglsl/lib/mx_environment_prefilter.glsl).
# A record generated for one of them (its "environment") has only that one.
ENV_METHODS = ENVIRONMENTS
# Lat-long maps wrap around in longitude and stop at the poles.
ENV_SAMPLING = Sampling(wrap_v=GL_CLAMP_TO_EDGE)

__all__ = ["ENV_METHODS", "Renderer", "RenderResult"]


class Renderer(SceneRenderer):
    """Renders GLSL and ESSL shader records with OpenGL (moderngl on headless EGL); see SceneRenderer
    for the arguments."""

    def __init__(self, *args, file_mipmaps: bool = True, **kwargs):
        """`file_mipmaps` False binds file images without their mipmaps (the base level at the file's
        own sides, bilinear or closest): a like-for-like read for a bench that compares with a single
        bilinear lookup (bench/osl_agreement.py); renders, records and thumbnails keep the default."""
        super().__init__(*args, power_of_two_files=file_mipmaps, **kwargs)
        self.file_mipmaps = file_mipmaps
        self._framebuffers: dict[int, object] = {}
        self._luts: dict[tuple, object] = {}  # a LUT's description -> its texture

    def render(self, record: dict, *, size: int = 256, mesh: str = "sphere", env=None, env_samples: int | None = None,
               env_method: str = "fis", lights=None, supersample: int = 1, document_dir: str | None = None,
               frames: int = 1) -> RenderResult:
        """Draw `record` on `mesh` ('sphere', 'plane' or an .obj path), lit by `env` (None: the
        procedural sky; a lat-long file path; or an Environment) with `env_method` (ENV_METHODS) and
        `env_samples` (None: the method's default, inputs.DEFAULT_ENV_SAMPLES), and `lights` (None, a
        light-rig .mtlx path, or a list of Light). `frames` > 1 draws again to time a steady frame."""
        start = time.perf_counter()
        vertex, pixel = check_record(record)
        element = record.get("element")
        side = self._image_side(size, supersample, element)
        if env_method not in ENV_METHODS:
            raise RenderError("invalid_request", f"unknown env_method {env_method!r}; supported: "
                              + ", ".join(ENV_METHODS), element)
        if record.get("environment", env_method) != env_method:
            raise RenderError("invalid_request", f"the record was generated for env_method {record['environment']!r} "
                              f"only, not {env_method!r}", element)
        env_samples = env_samples_for(env_method, env_samples)
        for macro in ENVIRONMENT_MACROS[env_method]:
            pixel = _with_define(pixel, macro)
        ctx = gl_context(self.lp_threads)
        import moderngl

        warnings: list[str] = []
        program, compile_link_ms, reused = self._program(source_digest(vertex, pixel),
                                                         lambda: Program(ctx, vertex, pixel, element))
        vao = program.vertex_array(ctx, *self._mesh(mesh, record))
        environment, textures = self._environment(env, functools.partial(upload, ctx))
        radiance = textures.radiance if env_method == "fis" else self._prefiltered(ctx, textures)
        if document_dir is None and isinstance(record.get("document"), str):
            document_dir = os.path.dirname(os.path.abspath(record["document"]))

        owned = self._bind_lighting(program, record, environment, env_samples, lights, warnings)
        for name, value in record_values(record, owned):
            if name in program.uniforms and (warning := program.set_uniform(name, value)):
                warnings.append(warning)
        self._textures.trim()
        units = {}  # sampler name -> texture unit
        for name, texture in (("u_envRadiance", radiance), ("u_envIrradiance", textures.irradiance)):
            if name in program.samplers:
                units[name] = len(units)
                bind(texture, units[name], ENV_SAMPLING)
        warnings += self._bind_file_textures(ctx, program, record, document_dir, units)

        framebuffer = self._framebuffer(ctx, side)
        framebuffer.use()
        ctx.enable(moderngl.DEPTH_TEST)
        frame_ms = []
        for _ in range(max(1, frames)):
            t0 = time.perf_counter()
            framebuffer.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
            vao.render(moderngl.TRIANGLES)
            raw = framebuffer.read(components=4, dtype="f4")
            frame_ms.append((time.perf_counter() - t0) * 1e3)
        rgba = np.frombuffer(raw, "f4").reshape(side, side, 4)[::-1]  # GL's first row is the bottom
        return self._result(rgba, size, supersample, frame_ms, start, compile_link_ms, reused, warnings)

    # -- cached resources -------------------------------------------------------------------

    @staticmethod
    def _prefiltered(ctx, textures: EnvironmentTextures):
        if textures.prefiltered is None:
            textures.prefiltered = prefiltered_chain(ctx, textures.environment.radiance, textures.radiance,
                                                     ENV_SAMPLING)
        return textures.prefiltered

    def _framebuffer(self, ctx, side: int):
        if side not in self._framebuffers:
            colour = ctx.texture((side, side), 4, dtype="f4")
            self._framebuffers[side] = ctx.framebuffer(color_attachments=[colour],
                                                       depth_attachment=ctx.depth_renderbuffer((side, side)))
        return self._framebuffers[side]

    # -- uniform binding --------------------------------------------------------------------

    @staticmethod
    def _bind_lighting(program: Program, record: dict, environment, env_samples: int, lights,
                       warnings: list[str]) -> set[str]:
        """Scene, environment and light uniforms; returns their names, which record values never override."""
        rig = light_rig(record, lights)
        values = lighting_values(environment, env_samples, rig)
        light_data = {name for name in program.uniforms if name.startswith("u_lightData[")}
        if rig and not light_data:
            warnings.append("the shader reads no u_lightData (generated without lights?): the light rig has no effect")
        warnings += filter(None, (program.set_uniform(name, value) for name, value in values.items()))
        return set(values) | set(ENV_SAMPLERS) | light_data

    def _bind_file_textures(self, ctx, program: Program, record: dict, document_dir, units: dict) -> list[str]:
        """Every filename uniform the program samples, with MaterialX's sampler state; a file that
        cannot be used becomes a 1 x 1 texture of the image node's `default` (black without one)
        and a warning. Samplers the record does not describe get black."""
        warnings = []
        make = functools.partial(upload, ctx)
        for name, entry in (record.get("luts") or {}).items():
            if name in program.samplers and name not in units:
                units[name] = len(units)
                self._lut(ctx, entry).use(location=units[name])
        for request in texture_requests(record, document_dir, self.search_paths, self.texture_roots, self.confined):
            if request.name not in program.samplers or request.name in units:
                continue
            texture, warning = self._textures.texture(make, request)
            if warning:
                warnings.append(warning)
            units[request.name] = len(units)
            bind(texture, units[request.name], replace(request.sampling, mipmaps=self.file_mipmaps))
        for name in program.samplers:
            if name not in units:
                units[name] = len(units)
                bind(self._textures.constant(make, Sampling.border), units[name], Sampling())
                warnings.append(f"sampler {name} is not described by the record; bound black")
        for name, unit in units.items():
            program.gl[name].value = unit
        return warnings


    def _lut(self, ctx, entry: dict):
        key = lut_key(entry)
        if key not in self._luts:
            if len(self._luts) >= MAX_LUTS:
                for texture in self._luts.values():
                    texture.release()
                self._luts.clear()
            self._luts[key] = upload_lut(ctx, entry)
        return self._luts[key]


def _with_define(source: str, name: str) -> str:
    """`source` with `#define name` after its #version line (which must come first)."""
    first, newline, rest = source.partition("\n")
    if first.lstrip().startswith("#version"):
        return f"{first}\n#define {name}\n{rest}"
    return f"#define {name}\n{source}"
