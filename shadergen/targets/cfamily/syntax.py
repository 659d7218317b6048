"""How HLSL, Slang and MSL spell what the IR says: one table per language, read by the shared
printer (printer.py) and assembler (target.py). Most of their syntax is C's; the tables hold
what differs (GLSL built-ins renamed, texture objects, matrix order, how a struct, a splat or an
out parameter is written)."""
from dataclasses import dataclass, field

# IR types as the three languages spell them (the same names in each)
TYPES = {
    "float": "float", "int": "int", "uint": "uint", "bool": "bool", "void": "void",
    **{f"{p}{n}": f"{s}{n}" for p, s in (("vec", "float"), ("ivec", "int"), ("uvec", "uint"), ("bvec", "bool"))
       for n in (2, 3, 4)},
    **{f"mat{n}": f"float{n}x{n}" for n in (2, 3, 4)},
}


@dataclass(frozen=True)
class Syntax:
    name: str  # the language, in messages
    renamed: dict  # GLSL built-in (or (name, argument count)) -> the language's
    texture: str  # a sampler2D's texture object type
    sampler: str  # and its sampler's
    # IR matrices are column-major (m[i] a column, `m * v` the product). HLSL and Slang keep each
    # IR matrix as its transpose: their m[i] is a row, so constructors and indexing read alike and
    # the product `M * v` is mul(v, M); MSL's matrices are GLSL's.
    transposed: bool
    splat: str  # a scalar spread over a vector: "cast" `(float3)x` (HLSL) or "constructor" `float3(x)`
    structs: str  # a struct value: "helper" (a function per struct, HLSL), "constructor" `S(a, b)`, "braces" `S{a, b}`
    vector_select: str  # mix() by a bool vector: "ternary" `c ? b : a`, "select" `select(c, b, a)`, "select_msl" `select(a, b, c)`
    spread_written: bool  # scalars spread over vector parameters written out (MSL's templates deduce none)
    out_parameter: str  # format of an out/inout parameter: {qualifier} {type} {name}
    constant: str  # a module-scope constant's keyword
    mutable_global: str  # a module-scope variable's keyword ("": MSL has none, a member of the stage's struct)
    texture_calls: dict = field(default_factory=dict)  # GLSL texture built-in -> method format
    # a module-scope constant array's keyword, where not `constant`'s: Slang's SPIR-V copies a
    # `static const` array into a function-local variable at every run-time index (SPIR-V cannot
    # index a value; 128 copies of the 256-1024-float albedo tables in a lit standard_surface, which
    # lavapipe did not compile in 10 minutes), and indexes a `static` one (a Private variable) in place
    constant_array: str | None = None


HLSL_RENAMED = {"mix": "lerp", "fract": "frac", "inversesqrt": "rsqrt", "dFdx": "ddx", "dFdy": "ddy",
                ("atan", 2): "atan2", "fma": "mad", "roundEven": "round", "floatBitsToInt": "asint",
                "floatBitsToUint": "asuint", "intBitsToFloat": "asfloat", "uintBitsToFloat": "asfloat",
                "bitCount": "countbits", "findLSB": "firstbitlow", "findMSB": "firstbithigh"}
MSL_RENAMED = {"inversesqrt": "rsqrt", "dFdx": "dfdx", "dFdy": "dfdy", ("atan", 2): "atan2", "roundEven": "rint",
               "bitCount": "popcount"}

# texture built-ins: format over {t} (texture), {s} (its sampler) and {0}, {1}, ... (the other arguments)
HLSL_TEXTURES = {
    ("texture", 2): "{t}.Sample({s}, {0})", ("texture", 3): "{t}.SampleBias({s}, {0}, {1})",
    ("textureLod", 3): "{t}.SampleLevel({s}, {0}, {1})", ("textureGrad", 4): "{t}.SampleGrad({s}, {0}, {1}, {2})",
    ("texelFetch", 3): "{t}.Load(int3({0}, {1}))",
    ("textureQueryLod", 2): "float2({t}.CalculateLevelOfDetail({s}, {0}), {t}.CalculateLevelOfDetailUnclamped({s}, {0}))",
    ("textureSize", 2): "mx_texture_size({t}, {0})", ("textureQueryLevels", 1): "mx_texture_levels({t})",
}
MSL_TEXTURES = {
    ("texture", 2): "{t}.sample({s}, {0})", ("texture", 3): "{t}.sample({s}, {0}, bias({1}))",
    ("textureLod", 3): "{t}.sample({s}, {0}, level({1}))",
    ("textureGrad", 4): "{t}.sample({s}, {0}, gradient2d({1}, {2}))",
    ("texelFetch", 3): "{t}.read(uint2({0}), uint({1}))",
    ("textureQueryLod", 2): "float2({t}.calculate_clamped_lod({s}, {0}), {t}.calculate_unclamped_lod({s}, {0}))",
    ("textureSize", 2): "int2(int({t}.get_width(uint({0}))), int({t}.get_height(uint({0}))))",
    ("textureQueryLevels", 1): "int({t}.get_num_mip_levels())",
}

HLSL = Syntax("HLSL", HLSL_RENAMED, "Texture2D", "SamplerState", True, "cast", "helper", "ternary", False,
              "{qualifier} {type} {name}", "static const", "static", HLSL_TEXTURES)
SLANG = Syntax("Slang", HLSL_RENAMED, "Texture2D", "SamplerState", True, "constructor", "constructor", "select", False,
               "{qualifier} {type} {name}", "static const", "static", HLSL_TEXTURES, constant_array="static")
MSL = Syntax("MSL", MSL_RENAMED, "texture2d<float>", "sampler", False, "constructor", "braces", "select_msl", True,
             "thread {type}& {name}", "constant", "", MSL_TEXTURES)
