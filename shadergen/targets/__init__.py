"""Targets: one per shading language, each a Syntax plus the hooks the generator writes through
(glsl_target.py describes them); the passes and the generator are shared (seed 2.2)."""
import importlib

from ..errors import ShaderGenError

# name -> (module, class). A target's module is imported when it is first asked for: a process
# writing GLSL never loads the WGSL translator.
TARGETS: dict[str, tuple[str, str]] = {"glsl": (".glsl_target", "GlslTarget"), "essl": (".glsl_target", "EsslTarget"),
                                       "wgsl": (".wgsl.target", "WgslTarget")}


def target_for(name: str):
    try:
        module, cls = TARGETS[name]
    except KeyError:
        raise ShaderGenError("unsupported_target", f"unknown target '{name}'; supported: "
                             + ", ".join(sorted(TARGETS)), name) from None
    return getattr(importlib.import_module(module, __package__), cls)()
