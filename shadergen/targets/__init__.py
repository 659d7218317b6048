"""Targets: one per shading language, each a printer of the IR, a stage assembler and a closure
convention (ARCHITECTURE.md, "How to add a target"); the passes and the generator are shared
(seed 2.2)."""
import importlib

from ..errors import ShaderGenError

# name -> (module, class). A target's module is imported when it is first asked for: a process
# writing GLSL never loads the WGSL printer.
TARGETS: dict[str, tuple[str, str]] = {"glsl": (".glsl.target", "GlslTarget"), "essl": (".glsl.target", "EsslTarget"),
                                       "wgsl": (".wgsl.target", "WgslTarget"), "vulkan": (".vulkan.target", "VulkanTarget"),
                                       "hlsl": (".hlsl.target", "HlslTarget"), "slang": (".slang.target", "SlangTarget"),
                                       "msl": (".msl.target", "MslTarget"), "osl": (".osl.target", "OslTarget")}


def target_for(name: str):
    return target_class(name)()


def target_class(name: str) -> type:
    try:
        module, cls = TARGETS[name]
    except KeyError:
        raise ShaderGenError("unsupported_target", f"unknown target '{name}'; supported: "
                             + ", ".join(sorted(TARGETS)), name) from None
    return getattr(importlib.import_module(module, __package__), cls)


def checker_for(name: str):
    """The target's checker module (`targets/<package>/check.py`: `errors(shaders)`, see
    targets/checking.py); ShaderGenError(unsupported_target) for a target the registry lacks,
    ModuleNotFoundError for a registered target without a checker."""
    if name not in TARGETS:
        target_for(name)  # raises the unknown target's error
    package = TARGETS[name][0].rsplit(".", 1)[0]
    return importlib.import_module(package + ".check", __package__)
