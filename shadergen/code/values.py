"""MaterialX values as IR expressions: a document's value (or a type's default) as the literal or
constructor every target prints in its own way.

Strings become integers, as MaterialX's hardware generators do: an enum input's value is its index
in `enum` (or the matching `enumvalues` entry). Shader and closure types start from their zero:
no response, everything let through. A float a 32-bit target cannot hold is clamped to the largest
it can (infinity), and NaN is 0 (types.py refuses them in documents; folded values may still be).
"""
import math
from functools import lru_cache

from ..types import TYPES, default_value
from . import ir
from .types import ir_type

FLOAT_MAX = 3.402823e38
# zero values of the shader and closure structs, member by member: (IR type, value)
STRUCT_ZERO = {
    "surfaceshader": (("vec3", 0.0), ("vec3", 0.0)),
    "volumeshader": (("vec3", 0.0), ("vec3", 0.0)),
    "displacementshader": (("vec3", 0.0), ("float", 1.0)),
    "lightshader": (("vec3", 0.0), ("vec3", 0.0)),
    "BSDF": (("vec3", 0.0), ("vec3", 1.0)),
    "VDF": (("vec3", 0.0), ("vec3", 1.0)),
}


def enum_index(value, meta: dict) -> int:
    enum = [e.strip() for e in meta.get("enum", "").split(",")] if meta.get("enum") else []
    if not isinstance(value, str) or value not in enum:
        return 0
    i = enum.index(value)
    values = [v.strip() for v in meta.get("enumvalues", "").split(",")] if meta.get("enumvalues") else []
    if values and i < len(values):
        try:
            return int(float(values[i]))
        except ValueError:
            return i
    return i


def finite(x: float) -> float:
    if math.isnan(x):
        return 0.0
    return max(-FLOAT_MAX, min(FLOAT_MAX, float(x)))


def scalar(type: str, value) -> ir.Literal:
    if type == "bool":
        return ir.Literal(bool(value), None, type="bool")
    if type == "int":
        return ir.Literal(int(value), None, type="int")
    return ir.Literal(finite(value), None, type="float")


def value_expr(materialx_type: str, value, meta: dict | None = None) -> ir.Expr:
    """The IR of a value of a MaterialX type (None: the type's default). The nodes are shared by
    every use of an equal value (nothing changes a typed node: passes build new ones)."""
    if materialx_type in ("string", "geomname") or isinstance(value, list):
        return _value_expr(materialx_type, value, meta)
    return _shared_value(materialx_type, value)


@lru_cache(maxsize=4096)
def _shared_value(materialx_type: str, value) -> ir.Expr:
    return _value_expr(materialx_type, value, None)


def _value_expr(materialx_type: str, value, meta: dict | None) -> ir.Expr:
    t = ir_type(materialx_type)
    if t in STRUCT_ZERO:
        return ir.Construct(t, [ir.Construct(mt, [scalar("float", v)], exact=True) if mt != "float"
                                else scalar("float", v) for mt, v in STRUCT_ZERO[t]], exact=True)
    if value is None:
        value = default_value(materialx_type) if materialx_type in TYPES else None
        value = 0.0 if value is None else value  # an EDF: no emission
    if materialx_type in ("string", "geomname"):
        return scalar("int", enum_index(value, meta or {}))
    if t in ("bool", "int", "float"):
        return scalar(t, value)
    # a vector's or matrix's components are floats (MaterialX has no integer or boolean vectors)
    if isinstance(value, tuple):
        return ir.Construct(t, [scalar("float", v) for v in value], exact=True)
    return ir.Construct(t, [scalar("float", value)], exact=True)
