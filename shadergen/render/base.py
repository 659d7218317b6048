"""What every renderer keeps between renders and does around its draw, whatever API draws: compiled
programs by source digest, meshes, environments, file textures, the request's checks, and the
framebuffer turned into a RenderResult. A renderer (GL: renderer.py, WebGPU: wgpu_renderer.py)
lives as long as its worker process and supplies the API's own objects.
"""
import json
import os
import statistics
import time
from collections import OrderedDict
from dataclasses import dataclass, field

import numpy as np

from .environment import Environment
from .errors import RenderError
from .geometry import Mesh, load_mesh, primvar_defaults, with_constant_streams
from .textures import TextureCache

MAX_IMAGE_SIDE = 8192


@dataclass
class RenderResult:
    rgba: np.ndarray  # float32 (size, size, 4), linear, premultiplied, top row first
    timings_ms: dict[str, float] = field(default_factory=dict)  # compile_link, first_frame, frame, total
    warnings: list[str] = field(default_factory=list)
    program_reused: bool = False  # the program was compiled for an earlier record of the same source


@dataclass
class EnvironmentTextures:
    environment: Environment
    radiance: object
    irradiance: object
    prefiltered: object = None  # made when a prefilter render first needs it

    def release(self) -> None:
        for texture in (self.radiance, self.irradiance, self.prefiltered):
            if texture is not None:
                texture.release()


class SceneRenderer:
    """`search_paths`: folders where relative texture names are looked up (after the document's
    folder); `texture_roots`: further folders textures may be read from. Unless `confined` is
    False (the command line, reading a user's own files), nothing outside the document's folder,
    the search paths and the roots is ever read. `lp_threads` caps the software rasterizer's
    threads (LP_NUM_THREADS) when the renderer creates the process's context, so that several
    worker processes share the cores. `max_programs`: compiled programs kept for records of the
    same source (one per topology in complete and reduced); 0 compiles every render's program afresh.
    `power_of_two_files` False keeps file images at their own sides where a filtered read would
    have them resampled (textures.power_of_two)."""

    MAX_PROGRAMS = 64

    def __init__(self, texture_roots=(), search_paths=(), *, confined: bool = True, lp_threads: int | None = None,
                 max_programs: int = MAX_PROGRAMS, texture_budget_bytes: int = 512 << 20,
                 power_of_two_files: bool = True):
        self.texture_roots = [os.path.abspath(p) for p in texture_roots]
        self.search_paths = [os.path.abspath(p) for p in search_paths]
        self.confined = confined
        self.lp_threads = lp_threads
        self.max_programs = max_programs
        self._programs: OrderedDict[str, object] = OrderedDict()
        self.program_counts = {"compiled": 0, "reused": 0}  # how often a render compiled or reused its program
        self._meshes: dict[str, Mesh] = {}
        self._environments: OrderedDict[str, EnvironmentTextures] = OrderedDict()
        self._textures = TextureCache(texture_budget_bytes, power_of_two_sides=power_of_two_files)

    def trim_textures(self) -> None:
        """Release the cached textures of files that are gone (after a job whose folder held its
        textures: service/workers/render_worker.py) and those over the budget, as every render
        does before it binds its own."""
        self._textures.trim()

    @staticmethod
    def _image_side(size: int, supersample: int, element) -> int:
        side = int(size) * int(supersample)
        if not (int(size) >= 1 and int(supersample) >= 1 and side <= MAX_IMAGE_SIDE):
            raise RenderError("invalid_request", f"size x supersample must be within 1..{MAX_IMAGE_SIDE}", element)
        return side

    def _program(self, key: str, compile_program) -> tuple[object, float, bool]:
        """(program, compile ms, reused): the cached program of `key`, else `compile_program()`'s;
        a program has `compile_link_ms` and `release()`."""
        program = self._programs.get(key) if self.max_programs else None
        compile_link_ms, reused = 0.0, program is not None
        if program is None:
            while len(self._programs) >= max(1, self.max_programs):  # room first: the new one is drawn next
                self._programs.popitem(last=False)[1].release()
            program = compile_program()
            compile_link_ms = program.compile_link_ms
            self._programs[key] = program
        self.program_counts["reused" if reused else "compiled"] += 1
        self._programs.move_to_end(key)
        return program, compile_link_ms, reused

    def _mesh(self, spec: str, record: dict) -> tuple[str, Mesh]:
        """The mesh under its cache key, with the record's values for the primvars it lacks (in
        the key too: programs cache their vertex arrays by it)."""
        key = spec if spec in ("sphere", "plane") else f"{os.path.abspath(spec)}@{mtime(spec)}"
        if key not in self._meshes:
            self._meshes[key] = load_mesh(spec)
        defaults = primvar_defaults(self._meshes[key], record)
        if not defaults:
            return key, self._meshes[key]
        return f"{key} {json.dumps(defaults, sort_keys=True)}", with_constant_streams(self._meshes[key], defaults)

    def _environment(self, env, upload) -> tuple[Environment, EnvironmentTextures]:
        """The environment (None: the procedural sky; a lat-long file path; or an Environment) and
        its cached textures, made by `upload(image)` the first time."""
        if isinstance(env, Environment):
            key = env.key
        elif env is None:
            key = "procedural-sky"
        else:
            key = f"{os.path.abspath(env)}@{mtime(env)}"
        if key not in self._environments:
            if not isinstance(env, Environment):
                env = Environment.procedural() if env is None else Environment.load(str(env))
            self._environments[key] = EnvironmentTextures(env, upload(env.radiance), upload(env.irradiance))
            while len(self._environments) > 4:
                self._environments.popitem(last=False)[1].release()
        self._environments.move_to_end(key)
        cached = self._environments[key]
        # An Environment passed in may differ from the cached one in intensity only.
        return (env if isinstance(env, Environment) else cached.environment), cached

    @staticmethod
    def _result(rgba: np.ndarray, size: int, supersample: int, frame_ms: list[float], start: float,
                compile_link_ms: float, reused: bool, warnings: list[str]) -> RenderResult:
        """The drawn (side, side, 4) float framebuffer, top row first, as a RenderResult."""
        size, supersample = int(size), int(supersample)
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


def mtime(path) -> int:
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return 0  # the loader reports the missing file
