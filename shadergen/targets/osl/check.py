"""The OSL checker: oslc, OpenShadingLanguage's own compiler (scripts/osl.sh builds it into
.venv/bin), compiling each shader; `oslinfo` reading a compiled shader's parameters back."""
import os
import shutil
import subprocess
import sys
import tempfile

from ..checking import Unavailable


def tool(name: str) -> str | None:
    """`name` beside this interpreter (the virtual environment's bin, where scripts/osl.sh links
    it) or on PATH."""
    beside = os.path.join(os.path.dirname(sys.executable), name)
    if os.access(beside, os.X_OK):
        return beside
    return shutil.which(name)


def compile_shaders(shaders: dict[str, tuple[str, str]], folder: str, include: str | None = None,
                    strict: bool = True) -> dict[str, str]:
    """Compiles each (stage, source) into `folder`/<n>.oso; label -> oslc's message for each
    rejected one. `strict`: a warning is a rejection (generated code is product); `include`: a
    folder the shaders' #include lines name files in (bench/osl.py's reference shaders)."""
    oslc = tool("oslc")
    if oslc is None:
        raise Unavailable("oslc", "scripts/osl.sh builds it into .venv/bin")
    flags = ["-q"] + (["-Werror"] if strict else []) + ([f"-I{include}"] if include else [])
    errors = {}
    for n, (label, (_stage, source)) in enumerate(sorted(shaders.items())):
        path = os.path.join(folder, f"shader{n}.osl")
        with open(path, "w", encoding="utf-8") as f:
            f.write(source)
        done = subprocess.run([oslc, *flags, "-o", os.path.join(folder, f"shader{n}.oso"), path],
                              capture_output=True, text=True, timeout=300)
        if done.returncode != 0:
            errors[label] = (done.stdout + done.stderr).replace(path, label).strip() or f"oslc exit {done.returncode}"
    return errors


def errors(shaders: dict[str, tuple[str, str]], include: str | None = None, strict: bool = True) -> dict[str, str]:
    """label -> (stage, source) in, label -> oslc's message out for each shader it rejects."""
    with tempfile.TemporaryDirectory(prefix="shadergen-osl-") as folder:
        return compile_shaders(shaders, folder, include, strict)


def oslinfo(source: str) -> str:
    """`oslinfo -v` of `source` compiled: its parameters, types, defaults and metadata."""
    with tempfile.TemporaryDirectory(prefix="shadergen-osl-") as folder:
        failed = compile_shaders({"shader": ("pixel", source)}, folder)
        if failed:
            raise ValueError(failed["shader"])
        done = subprocess.run([tool("oslinfo"), "-v", os.path.join(folder, "shader0.oso")], capture_output=True,
                              text=True, timeout=60, check=True)
        return done.stdout
