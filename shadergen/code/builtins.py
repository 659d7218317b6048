"""The built-in functions library code calls, as target-neutral signatures (code/check.py
resolves calls against them; each target's printer spells them).

A signature's parameter and return types are patterns over one generic type T, bound per call:
  "T"   T itself (the first T argument fixes it: the common type of the T arguments, int ones
        taken as float where the family has no int form, which is GLSL's implicit conversion)
  "t"   T or T's scalar: a scalar argument is spread over T's components (GLSL's overloads such
        as clamp(genType, float, float)); the checker writes that spread as an implicit Convert
  "S"   T's scalar; "bT", "iT", "uT", "fT": a bool, int, uint, float vector of T's size
  any other name: that IR type (an int argument converts to a float one implicitly)
`families` are the types T may be. The table covers what the libraries call and their GLSL
neighbours; a call of anything else is an error of the library source.
"""
from collections import namedtuple

__all__ = ["Builtin", "BUILTINS", "BUILTIN_VARIABLES", "FAMILIES"]

F = ("float", "vec2", "vec3", "vec4")
I = ("int", "ivec2", "ivec3", "ivec4")
U = ("uint", "uvec2", "uvec3", "uvec4")
B = ("bool", "bvec2", "bvec3", "bvec4")
M = ("mat2", "mat3", "mat4")
FAMILIES = {"F": F, "FIU": F + I + U, "FI": F + I, "V": F[1:] + I[1:] + U[1:], "VB": F[1:] + I[1:] + U[1:] + B[1:],
            "BV": B[1:], "M": M, "I": I, "U": U, "": ()}


# name, params (IR types), returns, families (collections' namedtuple: typing's import costs a
# cold process)
Builtin = namedtuple("Builtin", "name params returns families")


def _table(rows) -> dict[str, tuple[Builtin, ...]]:
    out: dict[str, list[Builtin]] = {}
    for names, params, returns, family in rows:
        for name in names.split():
            out.setdefault(name, []).append(Builtin(name, tuple(params.split()), returns, FAMILIES[family]))
    return {name: tuple(sigs) for name, sigs in out.items()}


BUILTINS = _table([
    # angle, trigonometry, exponential (GLSL 4.00 section 8.1, 8.2)
    ("radians degrees sin cos tan asin acos sinh cosh tanh asinh acosh atanh exp log exp2 log2 sqrt inversesqrt",
     "T", "T", "F"),
    ("atan", "T", "T", "F"), ("atan", "T T", "T", "F"), ("pow", "T T", "T", "F"),
    # common (8.3)
    ("abs sign", "T", "T", "FI"),
    ("floor ceil fract round roundEven trunc", "T", "T", "F"),
    ("min max", "T t", "T", "FIU"), ("clamp", "T t t", "T", "FIU"),
    ("mod", "T t", "T", "F"),
    ("mix", "T T t", "T", "F"), ("mix", "T T bT", "T", "F"),
    ("step", "t T", "T", "F"), ("smoothstep", "t t T", "T", "F"),
    ("fma", "T T T", "T", "F"),
    ("isnan isinf", "T", "bT", "F"),
    ("floatBitsToInt", "T", "iT", "F"), ("floatBitsToUint", "T", "uT", "F"),
    ("intBitsToFloat", "T", "fT", "I"), ("uintBitsToFloat", "T", "fT", "U"),
    # geometric (8.5)
    ("length", "T", "S", "F"), ("distance dot", "T T", "S", "F"),
    ("cross", "vec3 vec3", "vec3", ""), ("normalize", "T", "T", "F"),
    ("faceforward", "T T T", "T", "F"), ("reflect", "T T", "T", "F"), ("refract", "T T float", "T", "F"),
    # matrix (8.6)
    ("transpose inverse", "T", "T", "M"), ("determinant", "T", "float", "M"), ("matrixCompMult", "T T", "T", "M"),
    # vector relational (8.7)
    ("lessThan lessThanEqual greaterThan greaterThanEqual", "T T", "bT", "V"),
    ("equal notEqual", "T T", "bT", "VB"),
    ("any all", "T", "bool", "BV"), ("not", "T", "T", "BV"),
    # integer (8.8)
    ("bitCount findLSB findMSB", "T", "iT", "I"), ("bitCount findLSB findMSB", "T", "iT", "U"),
    # texture lookup (8.9): a sampler2D is a texture with its sampler
    ("texture", "sampler2D vec2", "vec4", ""), ("texture", "sampler2D vec2 float", "vec4", ""),
    ("textureLod", "sampler2D vec2 float", "vec4", ""),
    ("textureGrad", "sampler2D vec2 vec2 vec2", "vec4", ""),
    ("textureSize", "sampler2D int", "ivec2", ""),
    ("texelFetch", "sampler2D ivec2 int", "vec4", ""),
    ("textureQueryLod", "sampler2D vec2", "vec2", ""),
    ("textureQueryLevels", "sampler2D", "int", ""),
    # fragment processing (8.13)
    ("dFdx dFdy fwidth", "T", "T", "F"),
])

# Variables of the fragment stage every target provides (Name.kind "builtin").
BUILTIN_VARIABLES = {"gl_FrontFacing": "bool"}
