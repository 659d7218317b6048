"""The process's one WebGPU device (the `wgpu` package: wgpu-native on Vulkan; Mesa's lavapipe when
there is no GPU), and WGSL validation through it.

Validation is what wgpu does when it creates a shader module: naga (inside wgpu-native) parses the
WGSL and runs its validator, the same checks a browser's WebGPU makes. Drawing additionally
creates the render pipeline, where the two stages' interfaces and bindings are checked against
each other. Validation alone runs in a child process (wgsl_errors).
"""
import os

from .errors import RenderError
from .wgsl_validation import Validator

# Float textures the environment and HDR images need are filterable only with this feature.
FEATURES = ("float32-filterable",)
INSTALL = "pip install wgpu (the [wgpu] extra) and the Vulkan driver mesa-vulkan-drivers (scripts/system-packages.sh)"

_device = None
_owner_pid: int | None = None
_validator: Validator | None = None


def wgpu_device(lp_threads: int | None = None):
    """The process's device, created on first call. `lp_threads` caps lavapipe's threads
    (LP_NUM_THREADS, read when the device is created) as it does llvmpipe's for GL."""
    global _device, _owner_pid
    if _device is not None:
        if _owner_pid != os.getpid():
            raise RenderError("context_misuse", "this process was forked after its wgpu device was created; "
                              "start render workers with the 'spawn' method")
        return _device
    if lp_threads:
        os.environ["LP_NUM_THREADS"] = str(int(lp_threads))
    os.environ.setdefault("XDG_RUNTIME_DIR", "/tmp")  # Mesa's Vulkan WSI layer complains without one
    try:
        import wgpu
        from wgpu.backends.wgpu_native.extras import set_instance_extras

        # Vulkan only: probing wgpu's OpenGL back end makes its own EGL context current on this
        # thread, and the GL renderer's context in the same process then fails every glCreateProgram.
        set_instance_extras(backends=["Vulkan"])
        adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
        missing = [f for f in FEATURES if f not in adapter.features]
        if missing:
            raise RenderError("no_wgpu_device", f"the Vulkan adapter {adapter.info.get('device')} lacks "
                              f"{', '.join(missing)}")
        _device = adapter.request_device_sync(required_features=list(FEATURES))
    except RenderError:
        raise
    except Exception as exc:  # ImportError, or wgpu's RuntimeError when no Vulkan adapter exists
        raise RenderError("no_wgpu_device", f"cannot create a WebGPU device: {exc}. Needs {INSTALL}") from exc
    _owner_pid = os.getpid()
    return _device


def shader_module(device, source: str | bytes, label: str):
    """The compiled module from WGSL text or SPIR-V bytes, or RenderError(compile_error) with
    naga's message; `where` is "label:LINE" of the first WGSL error when naga gives one."""
    try:
        return device.create_shader_module(label=label, code=source)
    except Exception as exc:  # wgpu's GPUValidationError carries naga's report
        message = str(exc)
    line = None
    for text in message.splitlines():  # naga points at the source as "┌─ wgsl:LINE:COLUMN"
        marker = text.find("wgsl:")
        if marker >= 0 and text[marker + 5:].split(":")[0].isdigit():
            line = text[marker + 5:].split(":")[0]
            break
    language = "SPIR-V" if isinstance(source, bytes) else "WGSL"
    raise RenderError("compile_error", f"{language} {label} stage rejected: {message.strip()}",
                      f"{label}:{line}" if line else label)


def wgsl_errors(sources: dict[str, str]) -> dict[str, str]:
    """name -> the validator's message, for every WGSL module it rejects (an empty dict: all valid).
    Validated in a child process (wgsl_validation.py): a naga panic rejects one module, with its
    message, instead of aborting this process."""
    global _validator
    if _validator is None:
        _validator = Validator()
    return _validator.errors(sources)
