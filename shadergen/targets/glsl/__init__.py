"""Lexical facts of GLSL 4.00 and ESSL 3.00: type names, literals, declarations, reserved words.

A Syntax knows nothing of graphs; the generator asks it how to spell things.
"""
import math
import re
from functools import lru_cache

from ...types import TYPES, default_value
from ..names import RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES

# Closure and shader types are structs in the hardware targets (the PBR library fills them in).
STRUCTS = {
    "surfaceshader": "struct surfaceshader { vec3 color; vec3 transparency; };",
    "volumeshader": "struct volumeshader { vec3 color; vec3 transparency; };",
    "displacementshader": "struct displacementshader { vec3 offset; float scale; };",
    "lightshader": "struct lightshader { vec3 intensity; vec3 direction; };",
    "BSDF": "struct BSDF { vec3 response; vec3 throughput; };",
    "EDF": "#define EDF vec3",
    "VDF": "struct VDF { vec3 response; vec3 throughput; };",
    "material": "#define material surfaceshader",
    "LightData": ("#define MAX_LIGHT_SOURCES 3\n"
                  "struct LightData { int type; vec3 position; vec3 direction; vec3 color; float intensity; "
                  "float decay_rate; float inner_angle; float outer_angle; };"),
}
LIGHT_DATA_MEMBERS = (("type", "integer"), ("position", "vector3"), ("direction", "vector3"), ("color", "color3"),
                      ("intensity", "float"), ("decay_rate", "float"), ("inner_angle", "float"),
                      ("outer_angle", "float"))
# Only the functions a stage calls are written (deadcode.py), so only the structs they name are
# declared; a material is a surface shader.
STRUCT_DEPENDENCIES = {"material": ("surfaceshader",)}
STRUCT_ZERO = {
    "surfaceshader": "surfaceshader(vec3(0.0), vec3(0.0))",
    "volumeshader": "volumeshader(vec3(0.0), vec3(0.0))",
    "displacementshader": "displacementshader(vec3(0.0), 1.0)",
    "lightshader": "lightshader(vec3(0.0), vec3(0.0))",
    "BSDF": "BSDF(vec3(0.0), vec3(1.0))",
    "EDF": "EDF(0.0)",
    "VDF": "VDF(vec3(0.0), vec3(1.0))",
    "material": "material(vec3(0.0), vec3(0.0))",
}
TYPE_NAMES = {
    "float": "float", "integer": "int", "boolean": "bool", "color3": "vec3", "color4": "vec4",
    "vector2": "vec2", "vector3": "vec3", "vector4": "vec4", "matrix33": "mat3", "matrix44": "mat4",
    "string": "int", "filename": "sampler2D", "geomname": "int",
}


def _float(x: float) -> str:
    if math.isnan(x):
        return "0.0"
    if math.isinf(x):
        return "3.402823e38" if x > 0 else "-3.402823e38"
    text = repr(float(x))
    if "e" in text or "E" in text:
        mantissa, exp = text.lower().split("e")
        if "." not in mantissa:
            mantissa += ".0"
        return f"{mantissa}e{int(exp)}"
    return text


class Syntax:
    name = "glsl"
    version = "#version 400"
    precision: tuple[str, ...] = ()
    uniform_initializers = True
    vertex_data_block = True  # interface blocks for vertex -> pixel data
    # one spelling of every name in every target (names.py): a client binds the same names in each
    reserved = RESERVED
    reserved_prefixes = RESERVED_PREFIXES
    reserved_suffixes = RESERVED_SUFFIXES
    struct_types = frozenset(STRUCTS)  # types declared as structs (closures, shaders, lights)

    def type_name(self, type_name: str) -> str:
        return TYPE_NAMES.get(type_name, type_name)

    def enum_index(self, value, meta: dict) -> int:
        """String inputs become integers: the index of the value in `enum` (or the matching
        `enumvalues` entry), as MaterialX's hardware generators do."""
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

    def literal(self, type_name: str, value, meta: dict | None = None) -> str:
        if type_name in STRUCT_ZERO:
            return STRUCT_ZERO[type_name]
        if value is None:
            value = default_value(type_name) if type_name in TYPES else 0.0
        if type_name in ("string", "geomname"):
            return str(self.enum_index(value, meta or {}))
        if type_name == "boolean":
            return "true" if value else "false"
        if type_name == "integer":
            return str(int(value))
        if type_name == "float":
            return _float(value)
        if isinstance(value, tuple):
            return f"{self.type_name(type_name)}({', '.join(_float(v) for v in value)})"
        return _float(value)

    def negative_safe(self, text: str) -> str:
        """Inline expressions substitute literals into operators: keep `a - -1.0` unambiguous."""
        return f"({text})" if text.startswith("-") else text

    def struct_definitions(self, used: set[str]) -> list[str]:
        needed = set(used)
        for t in used:
            needed.update(STRUCT_DEPENDENCIES.get(t, ()))
        return [STRUCTS[t] for t in STRUCTS if t in needed]

    def uniform_declaration(self, var_type: str, name: str, value, meta: dict | None = None) -> str:
        if var_type == "LightData":
            return f"uniform LightData {name}[MAX_LIGHT_SOURCES];"
        glsl = self.type_name(var_type)
        if self.uniform_initializers and var_type not in ("filename",) and var_type not in STRUCTS and value is not None:
            return f"uniform {glsl} {name} = {self.literal(var_type, value, meta)};"
        return f"uniform {glsl} {name};"

    def header(self) -> list[str]:
        return [self.version, *self.precision]

    def vertex_data_member(self, name: str) -> str:
        return f"vd.{name}" if self.vertex_data_block else f"vd_{name}"


class GlslSyntax(Syntax):
    pass


class EsslSyntax(Syntax):
    name = "essl"
    version = "#version 300 es"
    precision = ("precision highp float;", "precision highp int;")
    uniform_initializers = False  # ESSL has no uniform initialisers: values come from the listing
    vertex_data_block = False  # ESSL 3.00 has no in/out interface blocks


# `void <lobe>_prepare(<parameters>)`; the word boundary before `void` is checked by hand, since a
# leading \b would stop the regex engine from scanning for the literal.
PREPARE_FUNCTION = re.compile(r"void\s+(\w+)_prepare\s*\(([^)]*)\)")


@lru_cache(maxsize=256)
def prepare_functions(source: str) -> dict[str, str]:
    """Lobe name -> the parameter list of its first `<lobe>_prepare` definition in the source (one
    scan per library source, not a pattern compiled per lobe)."""
    found: dict[str, str] = {}
    for m in PREPARE_FUNCTION.finditer(source):
        if starts_word(source, m.start()):
            found.setdefault(m.group(1), m.group(2))
    return found


def starts_word(source: str, index: int) -> bool:
    """Whether an identifier of `source` can begin at `index` (what a leading \\b would check; the
    scans that need it do without \\b, which stops the regex engine from searching for a literal)."""
    return index == 0 or not (source[index - 1].isalnum() or source[index - 1] == "_")


class ClosureConvention:
    """How the GLSL closure functions behave, read from their source: which shading contexts a
    lobe answers, and what a lobe gives at zero weight."""
    transmission_context = "CLOSURE_TYPE_TRANSMISSION"

    def handles_transmission(self, source: str) -> bool:
        return self.transmission_context in source

    def prepared_state(self, source: str, function: str) -> str | None:
        """The type of the state `<function>_prepare` writes (its last parameter, `out`), where the
        source prepares the lobe once per shading point; None where it does not."""
        parameters = prepare_functions(source).get(function)
        if parameters is None:
            return None
        last = parameters.split(",")[-1].split()
        return last[1] if len(last) == 3 and last[0] == "out" else None

    def empty_at_zero_weight(self, source: str, function: str) -> bool:
        """A lobe that returns before it writes its throughput leaves the closure's zero (no
        response, everything let through): removing it is exact. A lobe that marks itself opaque
        first (diffuse, conductor) is not the closure's zero."""
        start = source.find(f"void {function}(")
        if start < 0:
            return False
        body = source[start:]
        early = body.find("return;")
        return early >= 0 and "throughput" not in body[:early] and "weight" in body[:early]
