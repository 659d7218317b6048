"""The MaterialX type system: component counts, value parsing, and default values.

Values are plain Python data so they hash, compare and serialise to JSON without help:
float/int/bool/str for scalars and strings, tuples of floats for vectors, colours and
matrices (row-major), None for closures and shaders.
"""
import math
import struct
from collections import namedtuple

from .errors import ShaderGenError


class TypeDesc(namedtuple("TypeDesc", "name size base semantic", defaults=("",))):
    """A type: `size` scalar components (0 for strings, closures and shaders), its `base`
    ("float", "integer", "boolean", "string", "closure") and `semantic` ("color", "shader",
    "material", "closure" or ""). A named tuple, not a dataclass: see graph.py."""
    __slots__ = ()

    @property
    def is_closure(self) -> bool:
        return self.base == "closure"


_TYPES = [
    TypeDesc("float", 1, "float"),
    TypeDesc("integer", 1, "integer"),
    TypeDesc("boolean", 1, "boolean"),
    TypeDesc("color3", 3, "float", "color"),
    TypeDesc("color4", 4, "float", "color"),
    TypeDesc("vector2", 2, "float"),
    TypeDesc("vector3", 3, "float"),
    TypeDesc("vector4", 4, "float"),
    TypeDesc("matrix33", 9, "float"),
    TypeDesc("matrix44", 16, "float"),
    TypeDesc("string", 0, "string"),
    TypeDesc("filename", 0, "string"),
    TypeDesc("geomname", 0, "string"),
    TypeDesc("integerarray", 0, "integer"),
    TypeDesc("floatarray", 0, "float"),
    TypeDesc("BSDF", 0, "closure", "closure"),
    TypeDesc("EDF", 0, "closure", "closure"),
    TypeDesc("VDF", 0, "closure", "closure"),
    TypeDesc("surfaceshader", 0, "closure", "shader"),
    TypeDesc("volumeshader", 0, "closure", "shader"),
    TypeDesc("displacementshader", 0, "closure", "shader"),
    TypeDesc("lightshader", 0, "closure", "shader"),
    TypeDesc("material", 0, "closure", "material"),
    TypeDesc("none", 0, "closure"),
]
TYPES = {t.name: t for t in _TYPES}


def type_desc(name: str, where: str | None = None) -> TypeDesc:
    try:
        return TYPES[name]
    except KeyError:
        raise ShaderGenError("type_mismatch", f"unknown type '{name}'", where) from None


def parse_value(type_name: str, text: str | None, where: str | None = None):
    """Parse a MaterialX value string of the given type; None when there is no value. A number a
    shader cannot hold (not finite, beyond a 32-bit float or integer) is an `invalid_value`."""
    if text is None:
        return None
    t = type_desc(type_name, where)
    try:
        if t.base == "string" and t.size == 0 and not type_name.endswith("array"):
            return text
        if t.is_closure:
            return None
        if type_name == "boolean":
            low = text.strip().lower()
            if low not in ("true", "false", "1", "0"):
                raise ValueError(text)
            return low in ("true", "1")
        if type_name == "integer":
            return _shader_int(text)
        if type_name == "float":
            return _shader_float(text)
        if type_name == "integerarray":
            return tuple(_shader_int(p) for p in text.replace(",", " ").split())
        if type_name == "floatarray":
            return tuple(_shader_float(p) for p in text.replace(",", " ").split())
        parts = tuple(_shader_float(p) for p in text.replace(",", " ").split())  # some writers separate with spaces
        if len(parts) != t.size:
            raise ValueError(text)
        return parts
    except OutOfRange as e:
        raise ShaderGenError("invalid_value", f"'{text.strip()}' is not a valid {type_name} value: {e}", where) from None
    except ValueError:
        raise ShaderGenError("invalid_value", f"'{text}' is not a valid {type_name} value", where) from None


class OutOfRange(ValueError):
    """A number beyond what a shading language's 32-bit types hold."""


INT32_RANGE = range(-2**31, 2**31)


def _shader_int(text: str) -> int:
    """An integer a shader can hold: shading languages have 32-bit ints, so 10**400 is no value."""
    value = int(text.strip())
    if value not in INT32_RANGE:
        raise OutOfRange(f"{value} is beyond a 32-bit integer ({INT32_RANGE.start} to {INT32_RANGE.stop - 1})")
    return value


def _shader_float(text: str) -> float:
    """A float a shader can hold. `1e400` parses to inf, which no shading language can write as a
    literal; `1e39` is finite here but beyond float32 (GPUs compute it as inf, WGSL refuses it as a
    literal). Refused rather than clamped: a value that silently became another is a material the
    user did not write, and the listing would disagree with the source."""
    value = float(text.strip())
    if not math.isfinite(value):
        raise ValueError(text)
    if not is_float32(value):
        raise OutOfRange(f"beyond a 32-bit float (magnitudes up to {FLOAT32_MAX:.8g})")
    return value


FLOAT32_MAX = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]


def is_float32(value: float) -> bool:
    """Whether a finite value rounds to a finite float32 (what naga requires of a literal)."""
    try:
        struct.pack("<f", value)
    except OverflowError:
        return False
    return True


def default_value(type_name: str):
    """The zero value of a type (MaterialX's default for an input without a value)."""
    t = type_desc(type_name)
    if t.is_closure:
        return None
    if t.base == "string":
        return "" if t.size == 0 and not type_name.endswith("array") else ()
    if type_name == "boolean":
        return False
    if type_name == "integer":
        return 0
    if type_name == "float":
        return 0.0
    if type_name == "matrix33":
        return (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    if type_name == "matrix44":
        return tuple(1.0 if i % 5 == 0 else 0.0 for i in range(16))
    return (0.0,) * t.size


# ui metadata read as a value of the input's own type; names and docs stay text
UI_TYPED_HINTS = frozenset(("min", "max", "softmin", "softmax", "step"))


def parse_ui_hint(key: str, type_name: str, text: str, where: str | None = None):
    """A listing's ui hint as JSON data typed like its input: ranges as numbers or arrays,
    `advanced` as a boolean, `enum` as a list of names, `enumvalues` as a list of values."""
    if key in UI_TYPED_HINTS:
        return value_to_json(parse_value(type_name, text, where))
    if key == "advanced":
        return parse_value("boolean", text, where)
    if key == "enum":
        return [name.strip() for name in text.split(",")]
    if key == "enumvalues":
        size = type_desc(type_name, where).size
        if size == 0:
            return [value.strip() for value in text.split(",")]
        parts = text.replace(",", " ").split()
        return [value_to_json(parse_value(type_name, " ".join(parts[i:i + size]), where))
                for i in range(0, len(parts), size)]
    return text


def value_to_json(value):
    """Listings carry values as JSON numbers, booleans, strings or arrays."""
    return list(value) if isinstance(value, tuple) else value
