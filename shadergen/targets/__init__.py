"""Targets: one Syntax per shading language; the generator is shared (seed 2.2)."""
from ..errors import ShaderGenError
from .glsl import EsslSyntax, GlslSyntax, Syntax

SYNTAXES: dict[str, type[Syntax]] = {"glsl": GlslSyntax, "essl": EsslSyntax}


def syntax_for(target: str) -> Syntax:
    try:
        return SYNTAXES[target]()
    except KeyError:
        raise ShaderGenError("unsupported_target", f"unknown target '{target}'; supported: "
                             + ", ".join(sorted(SYNTAXES)), target) from None
