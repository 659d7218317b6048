"""WGSL's uniform buffer layout (WGSL spec, "Memory Layout"): each member at the next multiple of
its alignment; a vec3 aligns to 16 bytes but takes 12, so a scalar may follow it in the same 16;
matrix columns are vec3/vec4 padded to 16; the structure's size rounds up to 16."""

# MaterialX type -> (WGSL type in the buffer, alignment, size). Booleans are not host-shareable:
# they travel as i32 (0 or 1); strings are enum indices.
MEMBER = {
    "float": ("f32", 4, 4), "integer": ("i32", 4, 4), "boolean": ("i32", 4, 4), "string": ("i32", 4, 4),
    "geomname": ("i32", 4, 4), "vector2": ("vec2f", 8, 8), "vector3": ("vec3f", 16, 12),
    "color3": ("vec3f", 16, 12), "vector4": ("vec4f", 16, 16), "color4": ("vec4f", 16, 16),
    "matrix33": ("mat3x3f", 16, 48), "matrix44": ("mat4x4f", 16, 64),
    # the light rig: LightData is i32, three vec3f at 16, 32, 48 (the f32 intensity fills the last
    # one's 4 bytes at 60), three f32 at 64..72: 76 bytes, rounded to its 16-byte alignment
    "LightData": ("array<LightData, MAX_LIGHT_SOURCES>", 16, 3 * 80),
    # closures and shaders (unconnected inputs of those types): two vec3f, or a vec3f and an f32
    "surfaceshader": ("surfaceshader", 16, 32), "material": ("surfaceshader", 16, 32),
    "volumeshader": ("volumeshader", 16, 32), "BSDF": ("BSDF", 16, 32), "VDF": ("VDF", 16, 32),
    "EDF": ("vec3f", 16, 12), "displacementshader": ("displacementshader", 16, 16),
}
from ...errors import ShaderGenError

UNIFORM_BLOCKS = ("PrivateUniforms", "PublicUniforms")


def struct_members(variables) -> tuple[list[dict], int]:
    """(members with their offsets, size rounded to 16) of a struct of (name, MaterialX type)
    pairs in order: a stage's uniform buffer, or one LightData."""
    members, offset = [], 0
    for name, type_name in variables:
        if type_name not in MEMBER:
            raise ShaderGenError("unsupported_node", f"a {type_name} uniform is not yet laid out for wgsl", name)
        wgsl, align, size = MEMBER[type_name]
        offset = -(-offset // align) * align
        members.append({"name": name, "type": type_name, "wgsl": wgsl, "offset": offset, "size": size})
        offset += size
    return members, -(-offset // 16) * 16


def uniform_layout(stage, group: int) -> dict:
    """The stage's uniform buffer (binding 0 of `group`) and its textures, each a texture and a
    sampler binding after it."""
    numeric, textures = [], []
    for block in UNIFORM_BLOCKS:
        for v in stage.blocks[block]:
            if v.type == "filename":
                binding = 1 + 2 * len(textures)
                textures.append({"name": v.name, "group": group, "texture_binding": binding,
                                 "sampler_binding": binding + 1})
            else:
                numeric.append((v.name, v.type))
    members, size = struct_members(numeric)
    return {"group": group, "binding": 0, "size": size, "members": members, "textures": textures}
