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
# more of them, for the IR printer (wgsl/printer.py; the translator keeps to the above): WGSL's
# round() is GLSL's roundEven(), and findMSB() of a negative int is firstLeadingBit()'s highest 0
IR_RENAMED = {**RENAMED, "bitCount": "countOneBits", "findLSB": "firstTrailingBit", "findMSB": "firstLeadingBit",
              "roundEven": "round"}
BITCASTS = {"floatBitsToInt": "int", "floatBitsToUint": "uint", "intBitsToFloat": "float", "uintBitsToFloat": "float"}

# GLSL built-ins WGSL lacks, as WGSL functions every stage may call (the dead-code pass drops
# those it does not). inverse(): the adjugate over the determinant. For a 3x3 matrix of columns
# a, b, c the rows of the inverse are b x c, c x a, a x b over det = a . (b x c). For a 4x4 matrix
# a[i][j] (column i, row j), Laplace expansion along the first two columns (s: their 2x2 minors;
# c: the complementary minors of the last two); the cofactors of a's transpose, transposed back by
# writing them column after column.
INVERSE_HELPERS = {"mat3": "mx_inverse_mat3", "mat4": "mx_inverse_mat4"}
HELPER_FUNCTIONS = {"mx_inverse_mat3": """\
fn mx_inverse_mat3(m: mat3x3f) -> mat3x3f {
    let r0 = cross(m[1], m[2]);
    let r1 = cross(m[2], m[0]);
    let r2 = cross(m[0], m[1]);
    return transpose(mat3x3f(r0, r1, r2)) * (1.0 / dot(m[0], r0));
}
""", "mx_inverse_mat4": """\
fn mx_inverse_mat4(a: mat4x4f) -> mat4x4f {
    let s0 = a[0][0] * a[1][1] - a[1][0] * a[0][1];
    let s1 = a[0][0] * a[1][2] - a[1][0] * a[0][2];
    let s2 = a[0][0] * a[1][3] - a[1][0] * a[0][3];
    let s3 = a[0][1] * a[1][2] - a[1][1] * a[0][2];
    let s4 = a[0][1] * a[1][3] - a[1][1] * a[0][3];
    let s5 = a[0][2] * a[1][3] - a[1][2] * a[0][3];
    let c5 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
    let c4 = a[2][1] * a[3][3] - a[3][1] * a[2][3];
    let c3 = a[2][1] * a[3][2] - a[3][1] * a[2][2];
    let c2 = a[2][0] * a[3][3] - a[3][0] * a[2][3];
    let c1 = a[2][0] * a[3][2] - a[3][0] * a[2][2];
    let c0 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
    let inv_det = 1.0 / (s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0);
    return mat4x4f(
        a[1][1] * c5 - a[1][2] * c4 + a[1][3] * c3, -a[0][1] * c5 + a[0][2] * c4 - a[0][3] * c3,
        a[3][1] * s5 - a[3][2] * s4 + a[3][3] * s3, -a[2][1] * s5 + a[2][2] * s4 - a[2][3] * s3,
        -a[1][0] * c5 + a[1][2] * c2 - a[1][3] * c1, a[0][0] * c5 - a[0][2] * c2 + a[0][3] * c1,
        -a[3][0] * s5 + a[3][2] * s2 - a[3][3] * s1, a[2][0] * s5 - a[2][2] * s2 + a[2][3] * s1,
        a[1][0] * c4 - a[1][1] * c2 + a[1][3] * c0, -a[0][0] * c4 + a[0][1] * c2 - a[0][3] * c0,
        a[3][0] * s4 - a[3][1] * s2 + a[3][3] * s0, -a[2][0] * s4 + a[2][1] * s2 - a[2][3] * s0,
        -a[1][0] * c3 + a[1][1] * c1 - a[1][2] * c0, a[0][0] * c3 - a[0][1] * c1 + a[0][2] * c0,
        -a[3][0] * s3 + a[3][1] * s1 - a[3][2] * s0, a[2][0] * s3 - a[2][1] * s1 + a[2][2] * s0) * inv_det;
}
"""}

# Identity functions, one per type (WGSL has no generic ones), through which WgslTarget.inline reads
# the literals of an expression made of literals alone. WGSL evaluates such an expression when it
# compiles, and rejects it where its value is not finite (1.0 / 0.0: GLSL gives infinity) or where
# a built-in it calls has no constant form for its abstract-typed literals (mix(0.0, 1.0, 0.5));
# a function call is never a constant expression, so the GPU computes it as GLSL's would.
RUNTIME_TYPES = ("f32", "i32", "bool", "vec2f", "vec3f", "vec4f", "mat3x3f", "mat4x4f")
HELPER_FUNCTIONS.update((f"mx_runtime_{t}", f"fn mx_runtime_{t}(value: {t}) -> {t} {{ return value; }}\n")
                        for t in RUNTIME_TYPES)
# all of them as one text (the IR printer, wgsl/printer.py, writes only those a stage calls)
HELPERS = "\n".join(HELPER_FUNCTIONS.values())

# `?:` between matrices: WGSL's select() takes scalars and vectors only (the IR printer's; the
# text translator chooses column by column between names)
SELECT_HELPERS = {"mat2": "mx_select_mat2x2f", "mat3": "mx_select_mat3x3f", "mat4": "mx_select_mat4x4f"}
HELPER_FUNCTIONS.update(
    (name, f"fn {name}(f: {t}, t: {t}, condition: bool) -> {t} {{\n    if (condition) {{ return t; }}\n    return f;\n}}\n")
    for name, t in ((n, n.removeprefix("mx_select_")) for n in SELECT_HELPERS.values()))

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
