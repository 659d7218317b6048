"""Targets: one per shading language, each a printer of the IR, a stage assembler and a closure
convention (ARCHITECTURE.md, "How to add a target"); the passes and the generator are shared
(seed 2.2)."""
import importlib

from ..errors import ShaderGenError

# name -> (module, class). A target's module is imported when it is first asked for: a process
# writing GLSL never loads the WGSL printer.
TARGETS: dict[str, tuple[str, str]] = {"glsl": (".glsl.target", "GlslTarget"), "essl": (".glsl.target", "EsslTarget"),
                                       "wgsl": (".wgsl.target", "WgslTarget"), "osl": (".osl.target", "OslTarget")}


def target_for(name: str):
    try:
        module, cls = TARGETS[name]
    except KeyError:
        raise ShaderGenError("unsupported_target", f"unknown target '{name}'; supported: "
                             + ", ".join(sorted(TARGETS)), name) from None
    return getattr(importlib.import_module(module, __package__), cls)()
