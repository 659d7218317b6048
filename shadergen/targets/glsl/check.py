"""The GLSL and ESSL checker (targets/checking.py): glslangValidator, the Khronos reference front
end, in one run over every shader (it tells GLSL 4.00 from ESSL 3.00 by the #version line)."""
import os
import subprocess
import tempfile

from ..checking import tool

SUFFIXES = {"vertex": "vert", "pixel": "frag"}


def errors(shaders: dict[str, tuple[str, str]]) -> dict[str, str]:
    glslang = tool("glslangValidator", "glslang-tools")
    if not shaders:
        return {}
    with tempfile.TemporaryDirectory(prefix="shadergen-glsl-") as folder:
        paths = {}
        for k, (label, (stage, source)) in enumerate(shaders.items()):
            path = os.path.join(folder, f"s{k}.{SUFFIXES[stage]}")
            with open(path, "w", encoding="utf-8") as f:
                f.write(source)
            paths[path] = label
        run = subprocess.run([glslang, *paths], capture_output=True, text=True, errors="replace")
    if run.returncode == 0:
        return {}
    failed, current = {}, None
    for line in run.stdout.splitlines():  # each file's name on a line, then its errors
        if line in paths:
            current = line
        elif current and line.startswith("ERROR"):
            failed.setdefault(current, []).append(line)
    if not failed:  # refused without saying which: every shader of the run is unchecked
        return {label: f"glslangValidator exited {run.returncode}: {run.stdout[-600:]}" for label in paths.values()}
    return {paths[p]: " | ".join(lines[:3])[:600] for p, lines in failed.items()}
