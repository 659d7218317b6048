"""Renderer: draws any shader record of the contract on a mesh in the fixed thumbnail scene.

A Renderer is meant to live as long as its worker process: the GL context (one per process),
compiled programs (by source digest: one per topology, since complete and reduced sources are
value-free and the values are bound from the listing), meshes, environments and file textures stay between
renders, so a repeat material costs one draw. Use it from the thread that first renders with it.
"""
import os
import statistics
import time
from collections import OrderedDict
from dataclasses import dataclass, field

import numpy as np

from .context import gl_context
from .environment import ENV_MATRIX, Environment
from .errors import RenderError
from .geometry import Mesh, load_mesh
from .lights import Light, light_type_ids, light_uniforms, load_lights
from .prefilter import prefiltered_chain
from .program import Program
from .record import check_record, source_digest, uniform_variables
from .scene import matrix_bytes, scene_uniforms
from .textures import GL_CLAMP_TO_EDGE, Sampling, TextureCache, bind, resolve_file, sampling_from, upload
from .values import numbers

ENV_SAMPLERS = ("u_envRadiance", "u_envIrradiance")
# How the generated code lights with the environment: by filtered importance sampling of the
# radiance map (u_envRadianceSamples), or from its GGX-prefiltered chain, which the pixel stage
# reads when compiled with PREFILTER_DEFINE (libraries/pbrlib/genglsl/lib/mx_environment_prefilter.glsl).
ENV_METHODS = ("fis", "prefilter")
PREFILTER_DEFINE = "MX_ENV_PREFILTER"
# Lat-long maps wrap around in longitude and stop at the poles.
ENV_SAMPLING = Sampling(wrap_v=GL_CLAMP_TO_EDGE)
MAX_IMAGE_SIDE = 8192
ENV_SAMPLES = 16  # u_envRadianceSamples of a thumbnail: filtered importance samples per pixel


def fixed_uniforms(environment: Environment, env_samples: int = ENV_SAMPLES) -> dict[str, bytes | list[float]]:
    """The scene's and the environment's uniforms as every render binds them: matrices as the
    bytes of GLSL's column-major storage, everything else as lists of numbers."""
    values: dict[str, bytes | list[float]] = {}
    for name, value in scene_uniforms().items():
        values[name] = matrix_bytes(value) if isinstance(value, np.ndarray) else numbers("float", value)
    values["u_envMatrix"] = matrix_bytes(ENV_MATRIX)
    values["u_envRadianceMips"] = [float(environment.radiance_mips)]
    values["u_envRadianceSamples"] = [float(env_samples)]
    values["u_envLightIntensity"] = [float(environment.intensity)]
    return values


@dataclass
class RenderResult:
    rgba: np.ndarray  # float32 (size, size, 4), linear, premultiplied, top row first
    timings_ms: dict[str, float] = field(default_factory=dict)  # compile_link, first_frame, frame, total
    warnings: list[str] = field(default_factory=list)
    program_reused: bool = False  # the program was compiled for an earlier record of the same source


@dataclass
class _EnvironmentTextures:
    environment: Environment
    radiance: object
    irradiance: object
    prefiltered: object = None  # made when a prefilter render first needs it

    def release(self) -> None:
        for texture in (self.radiance, self.irradiance, self.prefiltered):
            if texture is not None:
                texture.release()


class Renderer:
    """Renders shader records. `search_paths`: folders where relative texture names are looked up
    (after the document's folder); `texture_roots`: further folders textures may be read from.
    Unless `confined` is False (the command line, reading a user's own files), nothing outside the
    document's folder, the search paths and the roots is ever read.
    `lp_threads` caps llvmpipe's threads (LP_NUM_THREADS) when this renderer creates the
    process's context, so that several worker processes share the cores. `max_programs`: compiled
    programs kept for records of the same source (one per topology in complete and reduced); 0
    compiles every render's program afresh."""

    MAX_PROGRAMS = 64

    def __init__(self, texture_roots=(), search_paths=(), *, confined: bool = True, lp_threads: int | None = None,
                 max_programs: int = MAX_PROGRAMS, texture_budget_bytes: int = 512 << 20):
        self.texture_roots = [os.path.abspath(p) for p in texture_roots]
        self.search_paths = [os.path.abspath(p) for p in search_paths]
        self.confined = confined
        self.lp_threads = lp_threads
        self.max_programs = max_programs
        self._programs: OrderedDict[str, Program] = OrderedDict()
        self.program_counts = {"compiled": 0, "reused": 0}  # how often a render compiled or reused its program
        self._meshes: dict[str, Mesh] = {}
        self._environments: OrderedDict[str, _EnvironmentTextures] = OrderedDict()
        self._textures = TextureCache(texture_budget_bytes)
        self._framebuffers: dict[int, object] = {}

    def render(self, record: dict, *, size: int = 256, mesh: str = "sphere", env=None, env_samples: int = ENV_SAMPLES,
               env_method: str = "fis", lights=None, supersample: int = 1, document_dir: str | None = None,
               frames: int = 1) -> RenderResult:
        """Draw `record` on `mesh` ('sphere', 'plane' or an .obj path), lit by `env` (None: the
        procedural sky; a lat-long file path; or an Environment) with `env_method` (ENV_METHODS),
        and `lights` (None, a light-rig .mtlx path, or a list of Light). `frames` > 1 draws again
        to time a steady frame."""
        start = time.perf_counter()
        vertex, pixel = check_record(record)
        element = record.get("element")
        size, supersample = int(size), int(supersample)
        side = size * supersample
        if not (size >= 1 and supersample >= 1 and side <= MAX_IMAGE_SIDE):
            raise RenderError("invalid_request", f"size x supersample must be within 1..{MAX_IMAGE_SIDE}", element)
        if env_method not in ENV_METHODS:
            raise RenderError("invalid_request", f"unknown env_method {env_method!r}; supported: "
                              + ", ".join(ENV_METHODS), element)
        if env_method == "prefilter":
            pixel = _with_define(pixel, PREFILTER_DEFINE)
        ctx = gl_context(self.lp_threads)
        import moderngl

        warnings: list[str] = []
        program, compile_link_ms, reused = self._program(ctx, vertex, pixel, element)
        vao = program.vertex_array(ctx, *self._mesh(mesh))
        environment, radiance, irradiance = self._environment(ctx, env, env_method)
        if document_dir is None and isinstance(record.get("document"), str):
            document_dir = os.path.dirname(os.path.abspath(record["document"]))

        owned = self._bind_lighting(program, environment, env_samples, lights, light_type_ids(record), warnings)
        warnings += self._bind_record_values(program, record, owned)
        self._textures.trim()
        units = {}  # sampler name -> texture unit
        for name, texture in (("u_envRadiance", radiance), ("u_envIrradiance", irradiance)):
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
        if supersample > 1:
            rgba = rgba.reshape(size, supersample, size, supersample, 4).mean(axis=(1, 3))
        rgba = np.ascontiguousarray(rgba, "f4")
        bad = int((~np.isfinite(rgba)).any(axis=2).sum())
        if bad:
            warnings.append(f"{bad} pixels are NaN or Inf")
        timings = {"compile_link": compile_link_ms, "first_frame": frame_ms[0],
                   "frame": statistics.median(frame_ms[1:]) if len(frame_ms) > 1 else frame_ms[0],
                   "total": (time.perf_counter() - start) * 1e3}
        return RenderResult(rgba, timings, warnings, program_reused=reused)

    # -- cached resources -------------------------------------------------------------------

    def _program(self, ctx, vertex: str, pixel: str, element) -> tuple[Program, float, bool]:
        key = source_digest(vertex, pixel)
        program = self._programs.get(key) if self.max_programs else None
        compile_link_ms, reused = 0.0, program is not None
        if program is None:
            while len(self._programs) >= max(1, self.max_programs):  # room first: the new one is drawn next
                self._programs.popitem(last=False)[1].release()
            program = Program(ctx, vertex, pixel, element)
            compile_link_ms = program.compile_link_ms
            self._programs[key] = program
        self.program_counts["reused" if reused else "compiled"] += 1
        self._programs.move_to_end(key)
        return program, compile_link_ms, reused

    def _mesh(self, spec: str) -> tuple[str, Mesh]:
        key = spec if spec in ("sphere", "plane") else f"{os.path.abspath(spec)}@{_mtime(spec)}"
        if key not in self._meshes:
            self._meshes[key] = load_mesh(spec)
        return key, self._meshes[key]

    def _environment(self, ctx, env, env_method: str) -> tuple[Environment, object, object]:
        """The environment and the textures to bind as u_envRadiance and u_envIrradiance."""
        if isinstance(env, Environment):
            key = env.key
        elif env is None:
            key = "procedural-sky"
        else:
            key = f"{os.path.abspath(env)}@{_mtime(env)}"
        if key not in self._environments:
            if not isinstance(env, Environment):
                env = Environment.procedural() if env is None else Environment.load(str(env))
            self._environments[key] = _EnvironmentTextures(env, upload(ctx, env.radiance), upload(ctx, env.irradiance))
            while len(self._environments) > 4:
                self._environments.popitem(last=False)[1].release()
        self._environments.move_to_end(key)
        cached = self._environments[key]
        radiance = cached.radiance
        if env_method == "prefilter":
            if cached.prefiltered is None:
                cached.prefiltered = prefiltered_chain(ctx, cached.environment.radiance, cached.radiance, ENV_SAMPLING)
            radiance = cached.prefiltered
        # An Environment passed in may differ from the cached one in intensity only.
        return (env if isinstance(env, Environment) else cached.environment), radiance, cached.irradiance

    def _framebuffer(self, ctx, side: int):
        if side not in self._framebuffers:
            colour = ctx.texture((side, side), 4, dtype="f4")
            self._framebuffers[side] = ctx.framebuffer(color_attachments=[colour],
                                                       depth_attachment=ctx.depth_renderbuffer((side, side)))
        return self._framebuffers[side]

    # -- uniform binding --------------------------------------------------------------------

    def _bind_lighting(self, program: Program, environment: Environment, env_samples: int, lights,
                       type_ids: dict[str, int] | None, warnings: list[str]) -> set[str]:
        """Scene, environment and light uniforms; returns their names, which record values never override."""
        values: dict[str, object] = fixed_uniforms(environment, env_samples)
        rig: list[Light] = (load_lights(lights, type_ids=type_ids) if isinstance(lights, (str, os.PathLike))
                            else list(lights or []))
        values.update(light_uniforms(rig) if rig else {"u_numActiveLightSources": [0.0]})
        light_data = {name for name in program.uniforms if name.startswith("u_lightData[")}
        if rig and not light_data:
            warnings.append("the shader reads no u_lightData (generated without lights?): the light rig has no effect")
        warnings += filter(None, (program.set_uniform(name, value) for name, value in values.items()))
        return set(values) | set(ENV_SAMPLERS) | light_data

    def _bind_record_values(self, program: Program, record: dict, owned: set[str]) -> list[str]:
        warnings = []
        for variable in uniform_variables(record):
            name = variable["name"]
            if name in owned or name not in program.uniforms:
                continue
            value = numbers(str(variable.get("type")), variable.get("value"))
            if value is not None and (warning := program.set_uniform(name, value)):
                warnings.append(warning)
        return warnings

    def _bind_file_textures(self, ctx, program: Program, record: dict, document_dir, units: dict) -> list[str]:
        """Every filename uniform the program samples, with MaterialX's sampler state; a file that
        cannot be used becomes a 1 x 1 texture of the image node's `default` (black without one)
        and a warning. Samplers the record does not describe get black."""
        warnings = []
        variables = list(uniform_variables(record))
        for variable in variables:
            name = variable["name"]
            if variable.get("type") != "filename" or name not in program.samplers or name in units:
                continue
            sampling = sampling_from(_siblings(variable, variables))
            texture, problem = None, None
            filename = variable.get("value")
            if isinstance(filename, str) and filename:
                path, problem = resolve_file(filename, document_dir, self.search_paths, self.texture_roots,
                                             self.confined)
                if path:
                    try:
                        texture = self._textures.file(ctx, path)
                    except RenderError as exc:
                        problem = f"{filename}: {exc.message}"
            if texture is None:
                texture = self._textures.constant(ctx, sampling.border)
                if problem:
                    warnings.append(f"texture for {name} unusable, using its default colour: {problem}")
            units[name] = len(units)
            bind(texture, units[name], sampling)
        for name in program.samplers:
            if name not in units:
                units[name] = len(units)
                bind(self._textures.constant(ctx, Sampling.border), units[name], Sampling())
                warnings.append(f"sampler {name} is not described by the record; bound black")
        for name, unit in units.items():
            program.gl[name].value = unit
        return warnings


def _siblings(variable: dict, variables: list[dict]) -> dict[str, object]:
    """Values of the other inputs of the node a filename uniform belongs to: by element path
    (`NG/image1/file` -> `NG/image1/*`; a USD attribute path `/Looks/Image.inputs:file` ->
    `/Looks/Image.inputs:*`), or by MaterialX's variable naming (`image1_file` -> `image1_*`)
    when the record gives no paths."""
    path = variable.get("path")
    if isinstance(path, str) and "/" in path:
        usd_inputs = path.rfind(".inputs:")
        node = path[:usd_inputs + len(".inputs:")] if usd_inputs >= 0 else path.rsplit("/", 1)[0] + "/"
        return {v["path"][len(node):]: v.get("value") for v in variables
                if isinstance(v.get("path"), str) and v["path"].startswith(node)}
    prefix = variable["name"][: -len("file")] if variable["name"].endswith("file") else None
    if not prefix:
        return {}
    return {v["name"][len(prefix):]: v.get("value") for v in variables if v["name"].startswith(prefix)}


def _with_define(source: str, name: str) -> str:
    """`source` with `#define name` after its #version line (which must come first)."""
    first, newline, rest = source.partition("\n")
    if first.lstrip().startswith("#version"):
        return f"{first}\n#define {name}\n{rest}"
    return f"#define {name}\n{source}"


def _mtime(path) -> int:
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return 0  # the loader reports the missing file
