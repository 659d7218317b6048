"""Targets: one per shading language, each a Syntax plus the hooks the generator writes through
(glsl_target.py describes them); the passes and the generator are shared (seed 2.2)."""
from ..errors import ShaderGenError
from .glsl_target import EsslTarget, GlslTarget
from .wgsl.target import WgslTarget

TARGETS: dict[str, type[GlslTarget]] = {"glsl": GlslTarget, "essl": EsslTarget, "wgsl": WgslTarget}


def target_for(name: str):
    try:
        return TARGETS[name]()
    except KeyError:
        raise ShaderGenError("unsupported_target", f"unknown target '{name}'; supported: "
                             + ", ".join(sorted(TARGETS)), name) from None
