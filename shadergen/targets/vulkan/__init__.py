"""The Vulkan target: GLSL 4.50 for Vulkan (GL_KHR_vulkan_glsl), printed by the GLSL printer with
textures split into a texture and its sampler (printer.py), stages assembled with explicit
locations, sets and bindings (target.py), uniforms laid out by std140 (layout.py), each stage
compiled to SPIR-V by glslangValidator (spirv.py)."""
