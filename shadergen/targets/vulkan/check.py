"""The Vulkan checker (targets/checking.py): glslangValidator -V compiling each stage to SPIR-V
for Vulkan 1.0 (the same compile as the record's, spirv.py), then spirv-val (Debian spirv-tools),
the Khronos validator of SPIR-V modules, on what it wrote. `spirv_errors` validates modules already
compiled (a record's "spirv": bench/targets.py, which would otherwise compile every stage twice)."""
import os
import subprocess
import tempfile

from ...errors import ShaderGenError
from ..checking import Unavailable, tool
from .spirv import TARGET_ENV, compile_stages


def errors(shaders: dict[str, tuple[str, str]]) -> dict[str, str]:
    tool("glslangValidator", "glslang-tools")
    found, modules = {}, {}
    items = list(shaders.items())
    k = 0
    while k < len(items):  # a vertex and a pixel stage in turn: one glslang run (spirv.py)
        size = 2 if k + 1 < len(items) and items[k][1][0] != items[k + 1][1][0] else 1
        _compile(items[k:k + size], found, modules)
        k += size
    return found | spirv_errors(modules)


def _compile(batch: list, found: dict[str, str], modules: dict[str, bytes]) -> None:
    """Each (label, (stage, source)) of `batch` (stages apart) into `modules`, or its message into
    `found`; a pair glslang refuses is compiled again a stage at a time, for each one's message."""
    try:
        compiled = compile_stages({stage: source for _, (stage, source) in batch})
    except ShaderGenError as exc:
        if exc.code == "missing_tool":
            raise Unavailable("glslangValidator", exc.message) from None
        if len(batch) == 1:
            found[batch[0][0]] = exc.message[:600]
        else:
            for one in batch:
                _compile([one], found, modules)
        return
    modules.update((label, compiled[stage]) for label, (stage, _) in batch)


def spirv_errors(modules: dict[str, bytes]) -> dict[str, str]:
    """label -> spirv-val's message, for each module (SPIR-V bytes) it rejects."""
    spirv_val = tool("spirv-val", "spirv-tools")
    found = {}
    with tempfile.TemporaryDirectory(prefix="shadergen-spirv-val-") as folder:
        for k, (label, module) in enumerate(modules.items()):
            path = os.path.join(folder, f"s{k}.spv")
            with open(path, "wb") as f:
                f.write(module)
            run = subprocess.run([spirv_val, "--target-env", TARGET_ENV, path], capture_output=True, text=True,
                                 errors="replace")
            if run.returncode != 0:
                found[label] = f"spirv-val: {(run.stderr or run.stdout).strip()[:600]}"
    return found
