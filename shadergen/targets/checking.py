"""What every target's checker (`targets/<name>/check.py`) shares. A checker compiles generated
shaders with the language's real compiler:

    errors(shaders: dict[str, tuple[str, str]]) -> dict[str, str]
        label -> (stage "vertex" | "pixel", source) in; label -> the compiler's message out, for
        each shader it rejects (an empty dict: all accepted). Raises Unavailable when the
        compiler is not on this machine, so a caller can tell "not checked" from "rejected".

Tests (tests/name_cases.py ShaderChecker), tests/core/test_golden.py and bench/targets.py call
them through `checker_for(target)` (targets/__init__.py)."""
import shutil


class Unavailable(Exception):
    """The checker's compiler is missing: `what` is missing, `why` says how to get it."""

    def __init__(self, what: str, why: str):
        super().__init__(f"{what} is not available ({why})")
        self.what, self.why = what, why


def tool(name: str, package: str) -> str:
    """The path of the program `name`, or Unavailable naming the Debian package that has it."""
    path = shutil.which(name)
    if path is None:
        raise Unavailable(name, f"Debian {package}; scripts/system-packages.sh installs it")
    return path
