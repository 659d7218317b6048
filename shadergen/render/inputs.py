"""What a render binds, whichever API draws it (GL for GLSL records, WebGPU for WGSL ones): the scene's,
environment's and lights' uniforms, the record's values, and the file textures with their
sampling. Each renderer writes these into its own API's objects.
"""
import os
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from .environment import ENV_MATRIX, Environment
from .errors import RenderError
from .lights import Light, light_type_ids, light_uniforms, load_lights
from .record import uniform_variables
from .scene import matrix_bytes, scene_uniforms
from .textures import Sampling, resolve_file, sampling_from
from .values import numbers

ENV_SAMPLERS = ("u_envRadiance", "u_envIrradiance")
ENV_SAMPLES = 16  # u_envRadianceSamples of a thumbnail: filtered importance samples per pixel
# u_envRadianceSamples when a render names none: the hybrid's few correcting samples are closer to
# the converged image than FIS's 16 (bench/accuracy_time.py); the prefiltered map reads none.
DEFAULT_ENV_SAMPLES = {"fis": ENV_SAMPLES, "prefilter": 1, "hybrid": 4}


def env_samples_for(env_method: str, env_samples: int | None) -> int:
    """u_envRadianceSamples of a render with `env_method` (None: the method's default)."""
    return DEFAULT_ENV_SAMPLES[env_method] if env_samples is None else env_samples


def fixed_uniforms(environment: Environment, env_samples: int = ENV_SAMPLES,
                   depth_zero_to_one: bool = False) -> dict[str, bytes | list[float]]:
    """The scene's and the environment's uniforms as every render binds them: matrices as the
    bytes of their column-major storage (GLSL's and WGSL's alike), everything else as lists of
    numbers. `depth_zero_to_one`: clip space as WebGPU's (z in 0..1) rather than GL's."""
    values: dict[str, bytes | list[float]] = {}
    for name, value in scene_uniforms(depth_zero_to_one).items():
        values[name] = matrix_bytes(value) if isinstance(value, np.ndarray) else numbers("float", value)
    values["u_envMatrix"] = matrix_bytes(ENV_MATRIX)
    values["u_envRadianceMips"] = [float(environment.radiance_mips)]
    values["u_envRadianceSamples"] = [float(env_samples)]
    values["u_envLightIntensity"] = [float(environment.intensity)]
    return values


def light_rig(record: dict, lights) -> list[Light]:
    """`lights` (None, a light-rig .mtlx path, or a list of Light) as the record's shader numbers them.
    A record generated without lights (`"lights": false`) has no light loop to draw them with."""
    if lights and record.get("lights", True) is False:
        raise RenderError("invalid_request", "the record was generated without lights (\"lights\": false): "
                          "generate it with lights to draw a light rig", record.get("element"))
    if isinstance(lights, (str, os.PathLike)):
        return load_lights(lights, type_ids=light_type_ids(record))
    return list(lights or [])


def lighting_values(environment: Environment, env_samples: int, rig: list[Light],
                    depth_zero_to_one: bool = False) -> dict[str, bytes | list[float]]:
    """Scene, environment and light uniforms by name (`u_lightData[i].member` for the rig's);
    record values never override them."""
    values = fixed_uniforms(environment, env_samples, depth_zero_to_one)
    values.update(light_uniforms(rig) if rig else {"u_numActiveLightSources": [0.0]})
    return values


def record_values(record: dict, owned) -> Iterator[tuple[str, list[float]]]:
    """(name, numbers) of every numeric uniform value the record lists, except those in `owned`."""
    for variable in uniform_variables(record):
        name = variable["name"]
        if name in owned:
            continue
        value = numbers(str(variable.get("type")), variable.get("value"))
        if value is not None:
            yield name, value


@dataclass
class TextureRequest:
    name: str            # the filename uniform (the sampler's name in the shader)
    sampling: Sampling   # MaterialX's address modes, filter and default colour for it
    path: str | None     # the file to read, when it resolved
    problem: str | None  # why there is no path (a warning), None when no file was named
    file: str | None = None  # the file as the document names it: what messages call it


def texture_requests(record: dict, document_dir: str | None, search_paths: list[str], texture_roots: list[str],
                     confined: bool) -> Iterator[TextureRequest]:
    """Every filename uniform of the record, resolved (resolve_file) and with its node's sampling."""
    variables = list(uniform_variables(record))
    for variable in variables:
        if variable.get("type") != "filename":
            continue
        path, problem = None, None
        filename = variable.get("value")
        if isinstance(filename, str) and filename:
            path, problem = resolve_file(filename, document_dir, search_paths, texture_roots, confined)
        node_inputs = siblings(variable, variables)
        # A `default` folded into the code (reduced, specialized) is not a uniform: the listing
        # gives it with the filename, so every interface shows the same colour for a missing file.
        node_inputs.setdefault("default", variable.get("fallback"))
        yield TextureRequest(variable["name"], sampling_from(node_inputs), path, problem, filename or None)


def siblings(variable: dict, variables: list[dict]) -> dict[str, object]:
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
