"""GLSL built-ins and types as WGSL spells them (WGSL spec, section 17 built-in functions)."""

WGSL_TYPES = {
    "float": "f32", "int": "i32", "uint": "u32", "bool": "bool",
    "vec2": "vec2f", "vec3": "vec3f", "vec4": "vec4f", "ivec2": "vec2i", "ivec3": "vec3i", "ivec4": "vec4i",
    "uvec2": "vec2u", "uvec3": "vec3u", "uvec4": "vec4u", "bvec2": "vec2<bool>", "bvec3": "vec3<bool>", "bvec4": "vec4<bool>",
    "mat2": "mat2x2f", "mat3": "mat3x3f", "mat4": "mat4x4f",
}

# Component-wise built-ins: GLSL accepts scalars for vector parameters, WGSL wants one type, so
# every argument is widened to the widest argument's type.
COMPONENTWISE = {"mix", "clamp", "min", "max", "step", "smoothstep", "pow", "atan", "abs", "sign", "floor",
                 "ceil", "fract", "round", "sqrt", "inversesqrt", "exp", "exp2", "log", "log2", "sin", "cos", "tan",
                 "asin", "acos", "radians", "degrees", "trunc", "sinh", "cosh", "tanh", "fma"}


def _first(types):
    return types[0]


def _scalar(types):
    return "float"


def _cross(types):
    return "vec3"


BUILTIN_RETURN = {
    "dot": _scalar, "length": _scalar, "distance": _scalar, "determinant": _scalar,
    "normalize": _first, "reflect": _first, "refract": _first, "transpose": _first, "cross": _cross,
    "dFdx": _first, "dFdy": _first, "fwidth": _first, "faceforward": _first,
    "any": lambda t: "bool", "all": lambda t: "bool", "not": _first,
    "float": _scalar, "int": lambda t: "int", "uint": lambda t: "uint",
}

TEXTURE_CALLS = {"texture": "textureSample", "textureGrad": "textureSampleGrad", "textureLod": "textureSampleLevel",
                 "textureSize": "textureDimensions", "texelFetch": "textureLoad"}

RENAMED = {"inversesqrt": "inverseSqrt", ("atan", 2): "atan2", "dFdx": "dpdx"}

WGSL_RESERVED = set("""
alias break case const const_assert continue continuing default diagnostic discard else enable false fn for if let
loop override requires return struct switch true var while NULL Self abstract active alignas alignof as asm
asm_fragment async attribute auto await become binding_array cast catch class co_await co_return co_yield coherent
column_major common compile compile_fragment concept const_cast consteval constexpr constinit crate debugger decltype
delete demote demote_to_helper do dynamic_cast enum explicit export extends extern external fallthrough filter final
finally friend from fxgroup get goto groupshared highp impl implements import inline instanceof interface layout
lowp macro macro_rules match mediump meta mod module move mut mutable namespace new nil noexcept noinline
nointerpolation noperspective null nullptr of operator package packoffset partition pass patch pixelfragment
precise precision premerge priv protected pub public readonly ref regardless register reinterpret_cast require
resource restrict self set shared sizeof smooth snorm static static_assert static_cast std subroutine super target
template this thread_local throw trait try type typedef typeid typename typeof union unless unorm unsafe unsized
use using varying virtual volatile wgsl where with writeonly yield
f32 i32 u32 f16 bool vec2 vec3 vec4 mat2x2 mat3x3 mat4x4 array ptr sampler texture_2d
""".split())
