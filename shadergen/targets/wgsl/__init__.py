"""WGSL for WebGPU: the GLSL libraries translated (translate.py), the stages assembled (target.py)."""
