"""The Slang checker: the Slang compiler PyPI's slangpy ships, on its `cpu` device (no GPU: the
host's C++ backend), loads each shader as a module from its source; loading parses and
type-checks every function and refuses bad code with its location. The module must then declare
its stage's entry point (`vertexMain` or `fragmentMain`, of that stage). The same checks HLSL
(hlsl/check.py), which Slang's front end reads."""
import itertools
import re
import threading

from ..checking import Unavailable

# The cpu device compiles for the host's C++, which has no fragment derivatives: an entry point
# reaching one (fwidth, ddx, a texture sampled at an implicit level of detail) is refused with
# E36107 "unavailable features in entry point ... for 'cpp' compilation target" after the whole
# module has been parsed and type-checked. That refusal alone, naming these intrinsics only, is
# no error of the shader (a GPU target has them); any other diagnostic is.
DERIVATIVES = frozenset({"fwidth", "ddx", "ddy", "ddx_coarse", "ddy_coarse", "ddx_fine", "ddy_fine", "Sample",
                         "SampleBias", "CalculateLevelOfDetail", "CalculateLevelOfDetailUnclamped"})
_ERROR = re.compile(r"^(?:fatal )?error\[(E\d+)\]")  # (the compiler's diagnostics, not our shader's text)
_USING = re.compile(r"^note: see using of '(\w+)'")
# slangpy loads a module from source with one line of its own before it: a diagnostic's line is ours plus one
_LOCATION = re.compile(r"-->\s*\S+?:(\d+):(\d+)")
_FOLLOW_ON = {"E39999", "E40003"}  # "import failed", "compilation ceased": after any error

ENTRY_POINTS = {"vertex": ("vertexMain", "vertex"), "pixel": ("fragmentMain", "fragment")}
_DEVICE = []
_LOCK = threading.Lock()
_MODULES = itertools.count()


def device():
    """The slangpy cpu device, made once per process (about a second)."""
    with _LOCK:
        if not _DEVICE:
            try:
                import slangpy
            except ImportError:
                raise Unavailable("slangpy", "pip install -e '.[slang]'") from None
            # the compiler's warnings (HLSL 5's component-wise `?:`, deprecated in Slang) are no
            # refusal: the log keeps errors only, which the load raises with anyway
            slangpy.Logger.get().level = slangpy.LogLevel.error
            _DEVICE.append(slangpy.create_device(type=slangpy.DeviceType.cpu))
        return _DEVICE[0]


def errors(shaders: dict[str, tuple[str, str]]) -> dict[str, str]:
    """label -> (stage, source) in; label -> the compiler's message for each rejected shader out."""
    if not shaders:
        return {}
    session = device().create_slang_session()  # a session per batch: modules do not pile up
    found = {}
    for label, (stage, source) in shaders.items():
        with _LOCK:
            name = f"shader_{next(_MODULES)}"
        try:
            module = session.load_module_from_source(name, source)
        except Exception as exc:  # slangpy raises RuntimeError with the diagnostics
            if not only_derivatives_missing(str(exc)):
                found[label] = diagnostics(str(exc))
            continue
        entry, kind = ENTRY_POINTS[stage]
        stages = {e.name: e.stage.name for e in module.entry_points}
        if stages.get(entry) != kind:
            found[label] = f"no {kind} entry point {entry} (entry points: {stages})"
    return found


def only_derivatives_missing(text: str) -> bool:
    """The diagnostics are the cpu target's lack of fragment derivatives, and nothing else."""
    lines = text.splitlines()
    codes = {m.group(1) for m in map(_ERROR.match, lines) if m}
    used = {m.group(1) for m in map(_USING.match, lines) if m}
    return codes - _FOLLOW_ON == {"E36107"} and "'cpp' compilation target" in text and bool(used) \
        and used <= DERIVATIVES


def diagnostics(text: str) -> str:
    """The compiler's errors with their locations (the lines after each `error[...]`)."""
    lines = text.splitlines()
    kept = [line.strip() for i, line in enumerate(lines) if line.startswith("error") or
            (i and lines[i - 1].startswith("error") and "-->" in line)]
    kept = [_LOCATION.sub(lambda m: f"at line {int(m.group(1)) - 1}, column {m.group(2)}", line) for line in kept]
    return " | ".join(kept[:6]) or text[:600]
