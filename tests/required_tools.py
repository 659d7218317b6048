"""What a test needs from the machine (glslangValidator, redis-server, dpkg, an importable renderer,
a WebGPU device).
On a developer's machine a missing tool skips the test; under CI=true it fails it, so a green CI
run always means every check ran."""
import importlib
import os
import shutil
import subprocess
import sys

import pytest

INSTALL = "scripts/system-packages.sh installs it"


def missing(what: str, why: str = INSTALL):
    message = f"{what} is not available ({why})"
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"{message}; under CI=true a missing tool fails the run", pytrace=False)
    pytest.skip(message)


def require_module(name: str, why: str):
    """The module, imported; for a test module that cannot be collected without it, so a skip
    skips the whole module (and a failure under CI=true is a collection error)."""
    try:
        return importlib.import_module(name)
    except ImportError:
        message = f"{name} is not importable ({why})"
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail(f"{message}; under CI=true a missing tool fails the run", pytrace=False)
        pytest.skip(message, allow_module_level=True)


def tool_path(name: str) -> str:
    path = shutil.which(name)
    if path is None:
        missing(name)
    return path


def require_renderer() -> None:
    probe = "from shadergen.render import Renderer; Renderer(texture_roots=[], search_paths=[])"
    if subprocess.run([sys.executable, "-c", probe], capture_output=True, timeout=60).returncode != 0:
        missing("shadergen.render.Renderer", "pip install -e '.[render]'")


def require_wgpu():
    """The WGSL validator (wgpu creating shader modules on a Vulkan device): a function from
    name -> source to name -> message of every rejected module."""
    from shadergen.render.errors import RenderError
    from shadergen.render.wgpu_device import wgpu_device, wgsl_errors
    try:
        wgpu_device()
    except RenderError as exc:
        missing("a WebGPU device", exc.message)
    return wgsl_errors
