"""The Vulkan target's uniform blocks under std140 (OpenGL 4.5, 7.6.2.2): every type a listing
holds lands where WGSL's uniform rules put it (a vec3 aligned to 16 taking 12, so a scalar may
follow it; matrix columns and array elements of structs at multiples of 16; a block's size
rounded to 16), so the offsets are those of targets/wgsl/layout.py, and a renderer packs both
targets' buffers alike. Set 0 is the vertex stage's, set 1 the pixel stage's: binding 0 the
uniform block, then a texture and its sampler per filename uniform."""
from ...code.types import ir_type
from ...shader import PIXEL, VERTEX
from ..wgsl.layout import uniform_layout

SETS = (VERTEX, PIXEL)


def std140_layout(stage, set_index: int) -> dict:
    wgsl = uniform_layout(stage, set_index)
    members = [{"name": m["name"], "type": m["type"], "glsl": _glsl_type(m["type"]), "offset": m["offset"],
                "size": m["size"]} for m in wgsl["members"]]
    textures = [{"name": t["name"], "set": set_index, "texture_binding": t["texture_binding"],
                 "sampler_binding": t["sampler_binding"]} for t in wgsl["textures"]]
    return {"set": set_index, "binding": 0, "size": wgsl["size"], "members": members, "textures": textures}


def _glsl_type(materialx_type: str) -> str:
    """As the GLSL target declares it (the light array's length is the prelude's)."""
    return "LightData[MAX_LIGHT_SOURCES]" if materialx_type == "LightData" else ir_type(materialx_type)
