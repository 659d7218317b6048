"""A Vulkan GLSL stage compiled to SPIR-V by glslangValidator (Khronos' reference front end; Debian
`glslang-tools`), run as a child process on the source from stdin. Its output depends only on the
source and glslang's version, so a record's SPIR-V is as deterministic as its text."""
import os
import shutil
import subprocess
import tempfile

from ...errors import ShaderGenError

STAGE_NAMES = {"vertex": "vert", "pixel": "frag"}
TARGET_ENV = "vulkan1.0"  # what lavapipe, wgpu and every Vulkan driver take
TIMEOUT_S = 60


def glslang() -> str:
    path = shutil.which("glslangValidator")
    if path is None:
        raise ShaderGenError("missing_tool", "the vulkan target compiles SPIR-V with glslangValidator, which is not "
                             "installed (Debian glslang-tools; scripts/system-packages.sh)", "vulkan")
    return path


def compile_stage(stage: str, source: str) -> bytes:
    """The stage's SPIR-V module; ShaderGenError(compile_error) with glslang's first errors (where:
    "stage:LINE") when it refuses the source."""
    with tempfile.TemporaryDirectory(prefix="shadergen-spirv-") as folder:
        out = os.path.join(folder, "stage.spv")
        try:
            run = subprocess.run([glslang(), "-V", "--target-env", TARGET_ENV, "--stdin", "-S", STAGE_NAMES[stage],
                                  "-o", out], input=source, capture_output=True, text=True, errors="replace",
                                 timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            raise ShaderGenError("compile_error", f"glslangValidator took over {TIMEOUT_S} s on the {stage} stage",
                                 stage) from None
        if run.returncode != 0 or not os.path.exists(out):
            errors = [line for line in run.stdout.splitlines() if line.startswith("ERROR")]
            line = next((e.split(":")[2] for e in errors if e.count(":") >= 3 and e.split(":")[2].isdigit()), None)
            raise ShaderGenError("compile_error", f"glslangValidator refused the {stage} stage: "
                                 + (" | ".join(errors[:3]) or run.stdout[-600:] or run.stderr[-600:]),
                                 f"{stage}:{line}" if line else stage)
        with open(out, "rb") as f:
            return f.read()
