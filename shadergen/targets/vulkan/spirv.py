"""Vulkan GLSL stages compiled to SPIR-V by glslangValidator (Khronos' reference front end; Debian
`glslang-tools`), run as one child process for all the stages given: most of a run is glslang
starting up (its built-in symbol tables: a 30-line vertex stage takes 0.19 s here; a lit
standard_surface's two stages 0.24 s together, 0.42 s one by one). Each stage is a file named for
it, so an error line names its stage. Its output depends only on the source and glslang's version,
so a record's SPIR-V is as deterministic as its text."""
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


def compile_stages(stages: dict[str, str]) -> dict[str, bytes]:
    """Each stage's SPIR-V module; ShaderGenError(compile_error) with glslang's first errors (where:
    "stage:LINE") for the first stage it refuses. glslang links the stages of one run, and its
    cross-stage check refuses what separate Vulkan modules may do (a member of one stage's
    anonymous uniform block named as a global of the other: TestSuite's transform.mtlx): when the
    stages fail together, each is compiled alone, and only its own refusal counts."""
    try:
        return _compiled(stages)
    except ShaderGenError as exc:
        if len(stages) == 1 or exc.code != "compile_error":
            raise
    return {stage: _compiled({stage: source})[stage] for stage, source in stages.items()}


def _compiled(stages: dict[str, str]) -> dict[str, bytes]:
    with tempfile.TemporaryDirectory(prefix="shadergen-spirv-") as folder:
        files = {stage: f"{stage}.{STAGE_NAMES[stage]}" for stage in stages}  # in `folder`, its working folder
        for stage, source in stages.items():
            with open(os.path.join(folder, files[stage]), "w", encoding="utf-8") as f:
                f.write(source)
        # without -o each module is written to the working folder as <vert|frag>.spv
        try:
            run = subprocess.run([glslang(), "-V", "--target-env", TARGET_ENV, *files.values()], cwd=folder,
                                 capture_output=True, text=True, errors="replace", timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            raise ShaderGenError("compile_error", f"glslangValidator took over {TIMEOUT_S} s on the "
                                 f"{' and '.join(stages)} stages", next(iter(stages))) from None
        outputs = {stage: os.path.join(folder, f"{STAGE_NAMES[stage]}.spv") for stage in stages}
        if run.returncode != 0 or not all(map(os.path.exists, outputs.values())):
            raise _refusal(run, stages)
        modules = {}
        for stage, out in outputs.items():
            with open(out, "rb") as f:
                modules[stage] = f.read()
        return modules


def _refusal(run: subprocess.CompletedProcess, stages) -> ShaderGenError:
    """The error of the first stage whose file glslang's ERROR lines name ("ERROR: pixel.frag:12: ...")."""
    errors = [line for line in run.stdout.splitlines() if line.startswith("ERROR")]
    for stage in stages:
        mine = [e for e in errors if e.startswith(f"ERROR: {stage}.{STAGE_NAMES[stage]}:")]
        if mine:
            line = next((e.split(":")[2] for e in mine if e.count(":") >= 3 and e.split(":")[2].isdigit()), None)
            return ShaderGenError("compile_error", f"glslangValidator refused the {stage} stage: "
                                  + " | ".join(mine[:3]), f"{stage}:{line}" if line else stage)
    stage = next(iter(stages))
    return ShaderGenError("compile_error", f"glslangValidator refused the {' and '.join(stages)} stages: "
                          + (" | ".join(errors[:3]) or run.stdout[-600:] or run.stderr[-600:]), stage)
