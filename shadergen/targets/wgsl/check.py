"""The WGSL checker (targets/checking.py): wgpu creating each module on a Vulkan device, so naga
(inside wgpu-native) parses and validates it as a browser's WebGPU does; in a child process that a
naga panic cannot take down (shadergen/render/wgpu_device.py, wgsl_validation.py)."""
import threading

from ..checking import Unavailable

_lock = threading.Lock()  # one validator child, one module at a time, whatever thread asks


def errors(shaders: dict[str, tuple[str, str]]) -> dict[str, str]:
    from ...render.errors import RenderError
    from ...render.wgpu_device import wgpu_device, wgsl_errors

    try:
        wgpu_device()
    except RenderError as exc:
        raise Unavailable("a WebGPU device", exc.message) from None
    if not shaders:
        return {}
    with _lock:
        return wgsl_errors({label: source for label, (_, source) in shaders.items()})
