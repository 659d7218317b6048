"""IR types (code/ir.py spells them as GLSL does: `float`, `vec3`, `mat4`, `T[N]`, a struct's name)
and MaterialX types as IR types. Facts about a type are read from its name: all are pure and
memoised (a type is a short string, there are a few dozen of them).
"""
from functools import lru_cache

__all__ = [
    "ir_type", "SCALARS", "GLSL_TYPES", "is_scalar", "is_vector", "is_matrix", "is_array", "is_numeric", "scalar_of",
    "size_of", "columns_of", "column_of", "vector_of", "array_element", "array_size", "array_of",
]

MATERIALX_TYPES = {
    "float": "float", "integer": "int", "boolean": "bool", "color3": "vec3", "color4": "vec4",
    "vector2": "vec2", "vector3": "vec3", "vector4": "vec4", "matrix33": "mat3", "matrix44": "mat4",
    "string": "int", "filename": "sampler2D", "geomname": "int",
    # closures and shaders are the prelude's structs (code/prelude.glsl); an EDF is its radiance
    "BSDF": "BSDF", "EDF": "vec3", "VDF": "VDF", "surfaceshader": "surfaceshader", "volumeshader": "volumeshader",
    "displacementshader": "displacementshader", "lightshader": "lightshader", "material": "surfaceshader",
}
SCALARS = ("bool", "int", "uint", "float")
GLSL_TYPES = frozenset({  # the type names the sources may write that are not structs
    "void", "bool", "int", "uint", "float", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3",
    "uvec4", "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "sampler2D"})
VECTOR_PREFIX = {"float": "vec", "int": "ivec", "uint": "uvec", "bool": "bvec"}
PREFIX_SCALAR = {"vec": "float", "ivec": "int", "uvec": "uint", "bvec": "bool"}


def ir_type(materialx_type: str) -> str:
    """The IR type of a MaterialX type (KeyError for one the IR has none of)."""
    return MATERIALX_TYPES[materialx_type]


def is_scalar(t: str) -> bool:
    return t in SCALARS


@lru_cache(maxsize=None)
def is_vector(t: str) -> bool:
    return len(t) >= 4 and t[-1] in "234" and t[:-1] in PREFIX_SCALAR


def is_matrix(t: str) -> bool:
    return t in ("mat2", "mat3", "mat4")


def is_array(t: str) -> bool:
    return t.endswith("]")


def is_numeric(t: str) -> bool:
    """A scalar, vector or matrix (what operators and component-wise built-ins take)."""
    return t in SCALARS or is_vector(t) or is_matrix(t)


@lru_cache(maxsize=None)
def scalar_of(t: str) -> str | None:
    """The component type of a scalar, vector or matrix; None for anything else."""
    if t in SCALARS:
        return t
    if is_vector(t):
        return PREFIX_SCALAR[t[:-1]]
    if is_matrix(t):
        return "float"
    return None


def size_of(t: str) -> int:
    """Components of a vector, 1 for a scalar, columns times rows for a matrix (0: not numeric)."""
    if t in SCALARS:
        return 1
    if is_vector(t):
        return int(t[-1])
    if is_matrix(t):
        return int(t[-1]) ** 2
    return 0


def columns_of(t: str) -> int:
    """Columns of a (square) matrix."""
    return int(t[-1])


def column_of(t: str) -> str:
    """The type of a matrix's column."""
    return "vec" + t[-1]


def vector_of(scalar: str, n: int) -> str:
    """The scalar itself for n == 1, else its vector of n components."""
    return scalar if n == 1 else f"{VECTOR_PREFIX[scalar]}{n}"


def array_element(t: str) -> str:
    return t[:t.rindex("[")]


def array_size(t: str) -> int | None:
    """The size of `T[N]`; None for `T[]` (not yet known)."""
    size = t[t.rindex("[") + 1:-1]
    return int(size) if size.isdigit() else None


def array_of(element: str, size: int | None) -> str:
    return f"{element}[{'' if size is None else size}]"
