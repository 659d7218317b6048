"""Thumbnail renderer: any shader record of the contract drawn on headless EGL (moderngl; Mesa
llvmpipe without a GPU). Nothing here is imported by the generator, and importing this package
loads no GL: the context is created by the first render.

    from shadergen.render import Renderer
    result = Renderer(search_paths=["assets"]).render(record, size=256)
    result.rgba, result.timings_ms, result.warnings
"""
from .environment import Environment
from .errors import RenderError
from .renderer import Renderer, RenderResult

__all__ = ["Environment", "RenderError", "RenderResult", "Renderer"]
