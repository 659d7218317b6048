"""Typed IR (code/ir.py) printed as OSL 1.13.

OSL is C-like, so the GLSL printer's statements, precedence and wrapping serve (its subclass
below); what differs is settled by the IR's types:
- types: `vec3` is OSL's `vector`; `vec2` and `vec4` are the `vector2` and `vector4` structs of
  OSL's own `vector2.h` and `vector4.h` (their operators and maths functions come with them),
  `mat4` is `matrix`, `mat3` the `matrix33` struct of `matrix33.h`; `bool` and `uint` are `int`
  (OSL has neither), a texture is its file name (`string`);
- integer and boolean vectors (OSL has none) are structs of ints written where a shader uses them
  (`ivec2`..`ivec4`, unsigned ones among them, and `bvec2`..`bvec4`), with the operators, the
  component-wise built-ins and the relations (`lessThan`, `any`, `mix` by a `bvec`) it calls, as
  helpers;
- `uint` keeps its meaning in an `int`: `>>` of one is a logical shift (`osl_ushr`), its float is
  taken modulo 2^32 (`osl_uint_float`), a literal above 2^31 - 1 is written as the int of the
  same bits;
- components: a `vector`'s are indexed (`v[0]`), the structs' are fields (`.x`); a swizzle of
  several components is a constructor of them; a write to several is one write per component;
- constructors take every component (OSL spreads no vector into another), a scalar spread over a
  struct is written once per component;
- a matrix holds GLSL's column-major values in OSL's row-major order, so it is the transpose of
  GLSL's: `M * v` is `transform(M, v)`, `v * M` is `transform(transpose(M), v)`, `A * B` is `B * A`;
- `out` and `inout` parameters are `output`; `const` is dropped (OSL has none);
- built-ins are renamed (`atan(y, x)` -> `atan2`, `dFdx` -> `Dx`, `fwidth` -> `filterwidth`);
  those OSL lacks (`fract`, `step` of a vector2, a texture read as a vector4) are helper functions
  (`helpers()`), written once by the assembler where a shader calls them;
- a library name that is an OSL keyword or global (`color`, `point`, `N`, `u`) gets a `_` after it
  (`safe_name`), as in WGSL.
What has no OSL form raises ShaderGenError("unsupported_node", ...).
"""
from ...code import ir
from ...code.types import array_element, array_size, is_array, is_matrix, scalar_of, size_of
from ...errors import ShaderGenError
from ..glsl.printer import BINARY, UNARY, PRIMARY, GlslPrinter, literal_text
from ..printing import INDENT, binary_text

# OSL's keywords, reserved words, shader globals and the standard library's functions a library
# name would hide or misuse
OSL_RESERVED = frozenset("""
and break closure color continue do else emit float for if illuminance illuminate int matrix normal not or
output point public return string struct vector void while shader surface displacement volume
bool case catch char class const delete default double enum extern false friend goto inline long new
operator private protected short signed sizeof static switch template this throw true try typedef uniform
union unsigned varying virtual
P I N Ng u v dPdu dPdv Ps time dtime dPdtime Ci
vector2 vector4 color2 color4 matrix33 transform transformu texture texture3d environment gettextureinfo
noise pnoise snoise psnoise cellnoise hashnoise filterwidth Dx Dy Dz area calculatenormal backfacing
raytype getattribute setmessage getmessage trace surfacearea displace bump luminance blackbody wavelength_color
step linearstep smooth_linearstep smoothstep mix select hypot inversesqrt cbrt logb exp2 expm1 log10 fabs
fmod erf erfc round trunc isfinite sincos radians degrees atan2 determinant transpose rotate faceforward
reflect refract fresnel distance ptlined ptlinefar concat endswith format getchar hash regex_match
regex_search startswith stof stoi strlen substr split printf warning error fprintf exit spline splineinverse
dielectric_bsdf conductor_bsdf generalized_schlick_bsdf translucent_bsdf transparent_bsdf subsurface_bsdf
sheen_bsdf oren_nayar_diffuse_bsdf burley_diffuse_bsdf chiang_hair_bsdf uniform_edf anisotropic_vdf
medium_vdf layer diffuse oren_nayar phong ward microfacet reflection refraction transparent translucent
emission background holdout debug subsurface isotropic henyey_greenstein absorption
M_PI M_PI_2 M_2PI M_4PI M_2_PI M_1_PI M_2_SQRTPI M_E M_LN2 M_LN10 M_LOG2E M_LOG10E M_SQRT2 M_SQRT1_2
""".split())

TYPES = {"float": "float", "int": "int", "uint": "int", "bool": "int", "vec2": "vector2", "vec3": "vector",
         "vec4": "vector4", "mat4": "matrix", "mat3": "matrix33", "sampler2D": "string", "void": "void"}
# closures and the shaders made of them are OSL's closures
TYPES.update({t: "closure color" for t in ("BSDF", "VDF", "surfaceshader", "volumeshader", "lightshader")})
# integer and boolean vectors -> the struct of ints each is written as (uint is int: OSL has no unsigned)
INT_VECTORS = {f"{prefix}{n}": f"{'b' if prefix == 'bvec' else 'i'}vec{n}" for prefix in ("ivec", "uvec", "bvec")
               for n in (2, 3, 4)}
TYPES.update(INT_VECTORS)
STRUCT_FIELDS = "xyzw"  # the members of vector2, vector4 and the integer vectors
STRUCT_SIZES = {"vector2": 2, "vector4": 4, **{osl: int(osl[-1]) for osl in INT_VECTORS.values()}}
OPERATORS = {"+": "add", "-": "sub", "*": "mul", "/": "div", "%": "mod", "&": "bitand", "|": "bitor",
             "^": "xor", "<<": "shl", ">>": "shr", "==": "eq", "!=": "neq"}
RELATIONS = {"lessThan": "<", "lessThanEqual": "<=", "greaterThan": ">", "greaterThanEqual": ">=", "equal": "==",
             "notEqual": "!="}
COMPONENTS = {c: i for names in ("xyzw", "rgba", "stpq") for i, c in enumerate(names)}
RENAMED = {"dFdx": "Dx", "dFdy": "Dy", "fwidth": "filterwidth"}
# built-ins OSL lacks in every type -> their helpers (a struct's calls the float one per component)
OWN_HELPERS = {"fract": "osl_fract", "roundEven": "osl_round_even"}
# the struct overloads OSL's vector2.h and vector4.h declare (S: either struct)
PROVIDED = frozenset(f"{name}({args})".replace("S", struct) for struct in ("vector2", "vector4") for name, args in (
    ("abs", "S"), ("ceil", "S"), ("floor", "S"), ("sqrt", "S"), ("exp", "S"), ("log", "S"), ("log2", "S"),
    ("mix", "S,S,float"), ("dot", "S,S"), ("length", "S"), ("smoothstep", "S,S,S"), ("smoothstep", "float,float,S"),
    ("clamp", "S,S,S"), ("clamp", "S,float,float"), ("max", "S,S"), ("min", "S,S"), ("min", "S,float"),
    ("max", "S,float"), ("normalize", "S"), ("fmod", "S,S"), ("fmod", "S,float"), ("pow", "S,S"), ("pow", "S,float"),
    ("sign", "S"), ("sin", "S"), ("cos", "S"), ("tan", "S"), ("asin", "S"), ("acos", "S"), ("atan2", "S,float"),
    ("atan2", "S,S"))) | {"mod(vector2,vector2)"}
# GLSL built-ins taken component by component: on a struct OSL lacks, a helper overload of the name
COMPONENTWISE = frozenset("""abs sign floor ceil trunc round fract mod min max clamp mix step smoothstep pow exp exp2
log log2 sqrt inversesqrt sin cos tan asin acos atan2 sinh cosh tanh radians degrees fmod Dx Dy filterwidth""".split())
STRUCT_TYPES = ("vec2", "vec4", *INT_VECTORS)
def unsupported(what: str, node) -> ShaderGenError:
    where = getattr(node, "where", None)
    return ShaderGenError("unsupported_node", f"no OSL form for {what}",
                          None if where is None else f"{where[0]}:{where[1]}:{where[2]}")


def safe_name(name: str) -> str:
    return f"{name}_" if name in OSL_RESERVED else name


def osl_type(ir_type: str) -> str:
    if ir_type in TYPES:
        return TYPES[ir_type]
    if ir_type == "mat2":
        raise ShaderGenError("unsupported_node", f"no OSL form for a {ir_type}")
    return ir_type  # a struct's own name


def helpers(items, texture_width: float | None = None) -> list[str]:
    """What printing `items` needs that OSL lacks, in a fixed order, for the assembler to write
    once: the integer vector structs they use, then the helper functions they call (operators of
    those structs, component-wise overloads of built-ins, a ternary of structs, a component of a
    value that is not a variable, uint arithmetic). `texture_width`: the filter width of their
    texture() calls (None: OIIO's default)."""
    wanted, structs = set(), set()
    for item in items:
        for node in ir.walk(item):
            cls = type(node)
            if getattr(node, "type", None) in INT_VECTORS:
                structs.add(INT_VECTORS[node.type])
            if cls is ir.Call and node.builtin and node.callee is None:
                helper = builtin_helper(node)
                if helper is not None:
                    wanted.add(helper)
            elif cls is ir.Binary or (cls is ir.Unary and node.op == "-"):
                helper = operator_helper(node)
                if helper is not None:
                    wanted.add(helper)
            elif cls is ir.Index and is_matrix(node.base.type or ""):
                wanted.add(column_helper(node))
            elif cls is ir.Select and node.type in STRUCT_TYPES + ("mat3",):
                wanted.add(("osl_select", ("int", osl_type(node.type), osl_type(node.type)), osl_type(node.type)))
            elif cls is ir.Convert and node.type == "float" and node.operand.type == "uint":
                wanted.add(UINT_FLOAT)
            if cls is ir.Construct:  # components of a value that is not a variable (component())
                if node.type == "float" and len(node.args) == 1 and node.args[0].type == "uint":
                    wanted.add(UINT_FLOAT)
                for arg in node.args:
                    if arg.type in STRUCT_TYPES + ("vec3",) and not lvalue(arg) and arg.type != node.type:
                        wanted.add(("osl_component", (osl_type(arg.type), "int"), "float"))
            elif (cls is ir.Field and node.swizzle) or cls is ir.Index:
                base = node.base
                if base.type in STRUCT_TYPES + ("vec3",) and (not lvalue(base) or (
                        cls is ir.Index and base.type in STRUCT_TYPES and type(node.index) is not ir.Literal)):
                    wanted.add(("osl_component", (osl_type(base.type), "int"), "float"))
    if any(h[0] == "osl_fract" and h[2] in STRUCT_SIZES for h in wanted):
        wanted.add(("osl_fract", ("float",), "float"))
    if any(h[0] == "osl_round_even" and h[2] != "float" for h in wanted):  # (a triple's too)
        wanted.add(("osl_round_even", ("float",), "float"))
    declarations = [line for name in sorted(structs) for line in [
        f"struct {name}", "{", *(f"{INDENT}int {c};" for c in STRUCT_FIELDS[:int(name[-1])]), "};", ""]]
    return declarations + [line for helper in sorted(wanted, key=lambda h: (h[0], h[2] != "float", h))
                           for line in [*helper_text(*helper, texture_width), ""]]


UINT_FLOAT = ("osl_uint_float", ("int",), "float")
# MaterialX's hair closure as later OSL releases declare it in stdosl.h (OSL 1.13's has none): a
# renderer that registers it integrates it; declaring it again where stdosl.h has it is allowed
HAIR = ("chiang_hair_bsdf", (
    ("normal", "N"), ("vector", "curve_direction"), ("color", "tint_R"), ("color", "tint_TT"), ("color", "tint_TRT"),
    ("float", "ior"), ("float", "longitudual_roughness_R"), ("float", "longitudual_roughness_TT"),
    ("float", "longitudual_roughness_TRT"), ("float", "azimuthal_roughness_R"), ("float", "azimuthal_roughness_TT"),
    ("float", "azimuthal_roughness_TRT"), ("float", "cuticle_angle"), ("color", "absorption_coefficient")),
    "closure color")
USHR = ("osl_ushr", ("int", "int"), "int")


def lvalue(e) -> bool:
    """Whether OSL may index `e` or read its members (a variable, a member, an element)."""
    while type(e) is ir.Field or type(e) is ir.Index:
        e = e.base
    return type(e) is ir.Name and e.kind != "vertexdata"  # (vertex data are spelled as expressions of globals)


def operator_helper(e):
    """(name, OSL argument types, OSL return type) of the helper an operator needs: an operator of
    integer vector structs (OSL calls `__operator__add__` and the like for `+` of structs), a
    logical shift of a uint; or None."""
    if type(e) is ir.Unary:
        return ("__operator__neg__", (osl_type(e.type),), osl_type(e.type)) if e.type in INT_VECTORS else None
    if e.op == ">>" and e.left.type == "uint":
        return USHR
    if e.op in ("+", "-") and (is_matrix(e.left.type or "") or is_matrix(e.right.type or "")):
        return (f"osl_matrix_{OPERATORS[e.op]}", (osl_type(e.left.type), osl_type(e.right.type)), osl_type(e.type))
    if (e.left.type in INT_VECTORS or e.right.type in INT_VECTORS) and e.op in OPERATORS:
        return (f"__operator__{OPERATORS[e.op]}__", (osl_type(e.left.type), osl_type(e.right.type)),
                osl_type(e.type))
    return None


def column_helper(e: ir.Index):
    return "osl_column", (osl_type(e.base.type), "int"), osl_type(e.type)


def builtin_helper(call: ir.Call):
    """(name, OSL argument types, OSL return type) of the helper a built-in call needs, or None."""
    name = "atan2" if call.name == "atan" and len(call.args) == 2 else RENAMED.get(call.name, call.name)
    types = tuple(osl_type(a.type) for a in call.args)
    if name in OWN_HELPERS:
        return OWN_HELPERS[name], types, osl_type(call.type)
    if name == HAIR[0]:
        return HAIR
    if name == "texture":
        return "osl_texture", ("string", "vector2"), "vector4"
    if name == "textureGrad":
        return "osl_texture_grad", ("string", "vector2", "vector2", "vector2"), "vector4"
    if name == "distance" and types[0] in ("vector2", "vector4"):
        return "distance", types, "float"
    if name in RELATIONS or name in ("any", "all", "not"):
        return name, types, osl_type(call.type)
    if name in COMPONENTWISE and any(t in STRUCT_SIZES for t in types) \
            and f"{name}({','.join(types)})" not in PROVIDED:
        return name, types, osl_type(call.type)
    return None


def part(osl: str, value: str, i: int) -> str:
    """Component `i` of the parameter `value` of OSL type `osl` (a scalar is its own component)."""
    if osl == "vector":
        return f"{value}[{i}]"
    if osl in STRUCT_SIZES:
        return f"{value}.{STRUCT_FIELDS[i]}"
    return value


def width_option(texture_width: float | None) -> str:
    """texture()'s "width" option for `texture_width` (api.prepare_all), none for OIIO's default."""
    return "" if texture_width is None else f'"width", {float(texture_width)!r}, '


def helper_text(name: str, types: tuple, returns: str, texture_width: float | None = None) -> list[str]:
    if name == HAIR[0]:
        params = [f"{t} {p}" for t, p in types]
        return [f"{returns} {name}({', '.join(params[:5])},",
                *(f"{INDENT * 2}{', '.join(params[i:i + 3])}," for i in range(5, len(params) - 3, 3)),
                f"{INDENT * 2}{', '.join(params[-3:])}) [[ int builtin = 1 ]];"]
    params = ", ".join(f"{t} {p}" for t, p in zip(types, "abcd"))
    head = f"{returns} {name}({params})"
    # (the library's coordinates are the image's already: t from the top row, as OSL's; a texture the
    # library samples itself repeats and filters linearly, as the GL renderer's sampler does, where
    # OSL's defaults are black and "smartcubic")
    if name == "osl_texture":
        return [head, "{", "    float alpha = 1.0;",
                '    color rgb = texture(a, b.x, b.y, "wrap", "periodic", "interp", "linear", '
                f'{width_option(texture_width)}"alpha", alpha,',
                '                        "fill", 1.0, "missingcolor", color(0.0), "missingalpha", 0.0);',
                "    return vector4(rgb[0], rgb[1], rgb[2], alpha);", "}"]
    if name == "osl_texture_grad":  # with the derivatives of the coordinate
        return [head, "{", "    float alpha = 1.0;",
                '    color rgb = texture(a, b.x, b.y, c.x, c.y, d.x, d.y, "wrap", "periodic", "interp", "linear",',
                f'                        {width_option(texture_width)}"alpha", alpha, "fill", 1.0, "missingcolor", '
                'color(0.0), "missingalpha", 0.0);',
                "    return vector4(rgb[0], rgb[1], rgb[2], alpha);", "}"]
    if name == "osl_select":
        return [head, "{", "    if (a)", "        return b;", "    return c;", "}"]
    if name == "osl_component":
        if types[0] == "vector":
            return [head, "{", "    return a[b];", "}"]
        fields = STRUCT_FIELDS[:STRUCT_SIZES[types[0]]]
        lines = [head, "{"] + [f"    if (b == {i})\n        return a.{c};" for i, c in enumerate(fields[:-1])]
        return [line for text in lines for line in text.split("\n")] + [f"    return a.{fields[-1]};", "}"]
    if name == "distance":
        return [head, "{", "    return length(a - b);", "}"]
    if name == "osl_ushr":  # OSL's >> of an int copies the sign bit; a uint's shifts in zeros
        return [head, "{", "    return b == 0 ? a : (a >> b) & ((1 << (32 - b)) - 1);", "}"]
    if name == "osl_uint_float":  # the int holding a uint's bits is negative from 2^31 on
        return [head, "{", "    return a < 0 ? float(a) + 4294967296.0 : float(a);", "}"]
    if name.startswith("osl_matrix_"):  # element by element (the 3x3 of a matrix33 only)
        size = 3 if returns == "matrix33" else 4
        symbol = {v: k for k, v in OPERATORS.items()}[name[11:]]

        def element(t: str, p: str, i: int, j: int) -> str:
            return {"matrix": f"{p}[{i}][{j}]", "matrix33": f"{p}.m[{i}][{j}]"}.get(t, p)
        values = [f"{element(types[0], 'a', i, j)} {symbol} {element(types[1], 'b', i, j)}"
                  if i < size and j < size else ("1.0" if i == j else "0.0") for i in range(4) for j in range(4)]
        opening = "    return matrix33(matrix(" if returns == "matrix33" else "    return matrix("
        rows = [", ".join(values[4 * i:4 * i + 4]) for i in range(4)]
        lines = [opening + rows[0] + ","] + [" " * len(opening) + row + "," for row in rows[1:3]]
        return [head, "{", *lines, " " * len(opening) + rows[3] + (")" if returns == "matrix33" else "") + ");", "}"]
    if name == "osl_column":  # GLSL's column i is row i of OSL's transposed storage
        m = "a.m" if types[0] == "matrix33" else "a"
        return [head, "{", f"    return {returns}({', '.join(f'{m}[b][{j}]' for j in range(STRUCT_SIZES.get(returns, 3)))});",
                "}"]
    if name in ("any", "all"):
        joined = (" || " if name == "any" else " && ").join(part(types[0], "a", i) for i in range(STRUCT_SIZES[types[0]]))
        return [head, "{", f"    return {joined};", "}"]
    size = STRUCT_SIZES.get(returns, 3)
    if name in ("__operator__eq__", "__operator__neq__"):
        size = STRUCT_SIZES.get(types[0]) or STRUCT_SIZES[types[1]]
        test = " && ".join(f"{part(types[0], 'a', i)} == {part(types[1], 'b', i)}" for i in range(size))
        return [head, "{", f"    return {test};" if name == "__operator__eq__" else f"    return !({test});", "}"]
    if name.startswith("__operator__"):
        symbol = {v: k for k, v in OPERATORS.items()}.get(name[12:-2], "-")
        if len(types) == 1:
            parts = [f"-{part(types[0], 'a', i)}" for i in range(size)]
        else:
            parts = [f"{part(types[0], 'a', i)} {symbol} {part(types[1], 'b', i)}" for i in range(size)]
    elif name in RELATIONS:
        parts = [f"{part(types[0], 'a', i)} {RELATIONS[name]} {part(types[1], 'b', i)}" for i in range(size)]
    elif name == "not":
        parts = [f"!{part(types[0], 'a', i)}" for i in range(size)]
    elif name == "mix" and types[2].startswith("bvec"):  # GLSL's mix by booleans: a selection per component
        parts = [f"{part(types[2], 'c', i)} ? {part(types[1], 'b', i)} : {part(types[0], 'a', i)}" for i in range(size)]
    elif returns in ("float", "vector") and name == "osl_fract":  # fract of a float or a triple
        return [head, "{", "    return a - floor(a);", "}"]
    elif returns == "float" and name == "osl_round_even":  # OSL's round takes a tie away from zero
        return [head, "{", "    return abs(a - trunc(a)) == 0.5 ? 2.0 * round(0.5 * a) : round(a);", "}"]
    else:
        parts = [f"{name}({', '.join(part(t, p, i) for t, p in zip(types, 'abcd'))})" for i in range(size)]
    return [head, "{", f"    return {returns}({', '.join(parts)});", "}"]


class OslPrinter(GlslPrinter):
    """`item`, `statements` and `expression` of typed IR as OSL text; `spell(name_node)` decides
    how a Name is written (the assembler's shader globals for vertex data)."""
    __slots__ = ()

    def __init__(self, spell=None):
        super().__init__("glsl", spell)

    # -- expressions -------------------------------------------------------------------------------
    def render(self, e, column, indent) -> str:
        cls = type(e)
        if cls is str:  # a component already written (components())
            return e
        if cls is ir.Name:
            return self.spell(e) if self.spell is not None else safe_name(e.name)
        if cls is ir.Literal:
            return self.literal(e)
        if cls is ir.Construct:
            return self.construct(e, column, indent)
        if cls is ir.Field and e.swizzle:
            return self.swizzle(e, column, indent)
        if cls is ir.Field:
            return self.operand(e.base, column, indent, self.precedence(e.base) < 15) + "." + safe_name(e.name)
        if cls is ir.Call:
            return self.call_of(e, column, indent)
        if cls is ir.Select and e.type in STRUCT_TYPES + ("mat3",):  # OSL's ?: takes no struct
            return self.call("osl_select", [e.condition, e.if_true, e.if_false], column, indent)
        if cls is ir.Index and is_matrix(e.base.type or ""):
            return self.call("osl_column", [e.base, e.index], column, indent)
        if cls is ir.Index and e.base.type in STRUCT_TYPES + ("vec3",):
            if type(e.index) is ir.Literal and lvalue(e.base):
                return self.component(e.base, int(e.index.value))
            if e.base.type in STRUCT_TYPES or not lvalue(e.base):
                return self.call("osl_component", [e.base, e.index], column, indent)
        if cls is ir.Convert:
            return self.convert(e, column, indent)
        if cls is ir.Binary and e.op == "*" and (is_matrix(e.left.type or "") or is_matrix(e.right.type or "")):
            return self.product(e, column, indent)
        if cls is ir.Binary and (operator_helper(e) or ("",))[0].startswith("osl_"):  # (USHR, matrix sums)
            return self.call(operator_helper(e)[0], [e.left, e.right], column, indent)
        return super().render(e, column, indent)

    def precedence(self, e) -> int:
        if type(e) is ir.Literal:  # (a uint's bits may be written as a negative int)
            return UNARY if self.literal(e).startswith("-") else PRIMARY
        if type(e) is ir.Call and e.builtin and e.callee is None and e.name == "inverse":  # `1.0 / m`
            return BINARY["/"]
        return super().precedence(e)

    @staticmethod
    def literal(e: ir.Literal) -> str:
        if e.type == "bool" or isinstance(e.value, bool):
            return "1" if e.value else "0"
        text = literal_text(e)
        if e.type == "uint":  # the int of the same bits
            value = int(text.rstrip("uU"), 0)
            return str(value - (1 << 32) if value >= 1 << 31 else value)
        if e.type == "float" and text[-1] in "fF" and not text.startswith(("0x", "0X")):
            return text[:-1]
        return text

    def components(self, e) -> list:
        """`e`'s components as expressions (text or IR), in order."""
        t = e.type
        if t is None or size_of(t) == 1:
            return [e]
        if is_matrix(t):
            raise unsupported(f"a {t} spread into a constructor", e)
        return [self.component(e, i) for i in range(size_of(t))]

    def component(self, base, i: int) -> str:
        if type(base) is ir.Field and base.swizzle and len(base.name) > 1:  # of `v.xyz`: of `v` itself
            return self.component(base.base, COMPONENTS[base.name[i]])
        if base.type in STRUCT_TYPES + ("vec3",) and not lvalue(base):
            return f"osl_component({self.render(base, None, 0)}, {i})"
        text = self.operand(base, None, 0, self.precedence(base) < 15)
        if base.type in STRUCT_TYPES:
            return f"{text}.{STRUCT_FIELDS[i]}"
        return f"{text}[{i}]"

    def construct(self, e: ir.Construct, column, indent) -> str:
        t = e.type
        if is_array(t):
            return "{" + ", ".join(self.render(a, None, indent) for a in e.args) + "}"
        if osl_type(t) == "closure color":  # a closure's zero: none
            return "0"
        if t not in TYPES and not t.startswith(("ivec", "uvec", "bvec", "mat")):  # a struct
            return self.call(safe_name(t), e.args, column, indent)
        name = osl_type(t)
        if t == "mat4":
            if len(e.args) == 1 and size_of(e.args[0].type) == 1:
                return self.call("matrix", e.args, column, indent)
            if len(e.args) == 1:  # from a mat3
                raise unsupported("a mat4 of a mat3", e)
            return self.call("matrix", [c for a in e.args for c in self.components(a)], column, indent)
        if t == "mat3":
            if len(e.args) == 1 and size_of(e.args[0].type) == 1:
                s = e.args[0]
                zero = ir.Literal(0.0, "0.0", type="float")
                one = ir.Literal(1.0, "1.0", type="float")
                return self.call("matrix33", [ir.Construct("mat4", [s, zero, zero, zero, zero, s, zero, zero, zero, zero, s,
                                                                    zero, zero, zero, zero, one])], column, indent)
            values = [c for a in e.args for c in self.components(a)]
            if len(values) != 9:
                raise unsupported("a mat3 of a matrix", e)
            zero, one = "0.0", "1.0"
            rows = values[0:3] + [zero] + values[3:6] + [zero] + values[6:9] + [zero, zero, zero, zero, one]
            return "matrix33(" + self.call("matrix", rows, None, indent) + ")"
        n = size_of(t)
        args = e.args
        if n == 1 and len(args) == 1:  # a scalar's constructor is a conversion
            return self.convert(ir.Convert(t, args[0]), column, indent)
        if len(args) == 1 and size_of(args[0].type) == 1:
            value = self.scalar(args[0], args[0].type, scalar_of(t))
            if t == "vec3":
                return self.call("vector", [value], column, indent)
            return self.call(name, [value] * n, column, indent)
        if len(args) == 1 and args[0].type == t:
            return self.render(args[0], column, indent)
        values = [self.scalar(c, scalar_of(a.type), scalar_of(t)) for a in args for c in self.components(a)][:n]
        return self.call(name, values, column, indent)

    def scalar(self, value, source: str | None, target: str | None):
        """A component (IR or text) of scalar type `source` as one of `target`: OSL converts an int
        to a float by itself, nothing else."""
        if source == target or source is None or target is None or (source, target) in (("int", "uint"), ("uint", "int")):
            return value
        text = value if type(value) is str else self.render(value, None, 0)
        if target == "bool":
            return f"{text} != 0"
        if target == "float":
            return f"osl_uint_float({text})" if source == "uint" else text
        return f"int({text})"

    def swizzle(self, e: ir.Field, column, indent) -> str:
        indices = [COMPONENTS[c] for c in e.name]
        if len(indices) == 1:
            return self.component(e.base, indices[0])
        parts = [self.component(e.base, i) for i in indices]
        return self.call(osl_type(e.type), parts, column, indent)

    def convert(self, e: ir.Convert, column, indent) -> str:
        target, source = e.type, e.operand.type
        if target == source or osl_type(target) == osl_type(source or target):
            return self.render(e.operand, column, indent)
        if target == "bool":
            return f"({self.render(e.operand, None, indent)} != 0)"
        if target == "float" and source == "uint":
            return self.call("osl_uint_float", [e.operand], column, indent)
        if size_of(target) == 1:
            return self.call(osl_type(target), [e.operand], column, indent)
        if source is not None and size_of(source) == 1:  # a scalar spread
            return self.construct(ir.Construct(target, [e.operand]), column, indent)
        if source is not None and size_of(source) == size_of(target):
            return self.construct(ir.Construct(target, [e.operand]), column, indent)
        raise unsupported(f"a conversion of a {source} to a {target}", e)

    def product(self, e: ir.Binary, column, indent) -> str:
        left, right = e.left, e.right
        if is_matrix(left.type) and is_matrix(right.type):  # transposed storage: (AB)' = B'A'
            # written here: the GLSL printer's render prints a wrapped node once more through this
            # render, which would swap a swapped product back
            return binary_text(lambda at, i: self.operand(right, at, i, self.precedence(right) < BINARY["*"]), "*",
                               lambda at, i: self.operand(left, at, i, self.precedence(left) <= BINARY["*"]),
                               column, indent)
        if is_matrix(left.type):
            return self.call("transform", [left, right], column, indent)
        return self.call("transform", [ir.Call("transpose", [right], type=right.type, builtin=True), left],
                         column, indent)

    def call_of(self, e: ir.Call, column, indent) -> str:
        if e.callee is not None or not e.builtin:
            return self.call(safe_name(e.name), e.args, column, indent)
        helper = builtin_helper(e)
        if helper is not None:
            return self.call(helper[0], e.args, column, indent)
        name, args = e.name, list(e.args)
        if name == "atan" and len(args) == 2:
            return self.call("atan2", args, column, indent)
        if name == "inverse":
            return "1.0 / " + self.operand(args[0], None, indent, self.precedence(args[0]) <= BINARY["/"])
        if name in ("textureLod", "textureSize", "texelFetch", "textureQueryLod", "textureQueryLevels",
                    "floatBitsToInt", "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat",
                    "matrixCompMult", "outerProduct"):
            raise unsupported(f"the built-in '{name}'", e)
        return self.call(RENAMED.get(name, name), args, column, indent)

    # -- statements --------------------------------------------------------------------------------
    def simple(self, s, column, indent) -> str:
        cls = type(s)
        if cls is ir.Declare:
            name = self.spell(ir.Name(s.name, "local")) if self.spell is not None else safe_name(s.name)
            head = self.declarator(self.sized(s.type, s.init), name)
            if s.init is None:
                return head
            return head + " = " + self.render(s.init, None if column is None else column + len(head) + 3, indent)
        if cls is ir.Discard:
            return "exit()"
        return super().simple(s, column, indent)

    def statement(self, s, depth: int, lines: list[str]) -> None:
        if type(s) is ir.Assign and type(s.target) is ir.Field and s.target.swizzle and len(s.target.name) > 1:
            self.swizzle_assign(s, depth, lines)
            return
        super().statement(s, depth, lines)

    def swizzle_assign(self, s: ir.Assign, depth: int, lines: list[str]) -> None:
        """`v.xy = e`: one write per component, of `e` evaluated once before them."""
        pad = INDENT * depth
        target = s.target
        value = s.value
        if type(value) not in (ir.Name, ir.Literal):
            lines.append(f"{pad}{{")
            temp = ir.Name("swizzled", "local", type=value.type)
            lines.append(f"{pad}{INDENT}{self.declarator(value.type, 'swizzled')} = {self.render(value, None, 0)};")
            self.swizzle_assign(ir.replace(s, value=temp), depth + 1, lines)
            lines.append(f"{pad}}}")
            return
        spread = value.type is not None and size_of(value.type) > 1
        for i, c in enumerate(target.name):
            source = self.component(value, i) if spread else self.render(value, None, 0)
            lines.append(f"{pad}{self.component(target.base, COMPONENTS[c])} {s.op} {source};")

    @staticmethod
    def sized(ir_type: str, value) -> str:
        if is_array(ir_type) and array_size(ir_type) is None and type(value) is ir.Construct:
            return f"{array_element(ir_type)}[{len(value.args)}]"
        return ir_type

    def declarator(self, ir_type: str, name: str) -> str:
        if is_array(ir_type):
            size = ir_type[ir_type.rindex('['):]
            return f"{osl_type(array_element(ir_type))} {name}{size}"
        return f"{osl_type(ir_type)} {name}"

    # -- items -------------------------------------------------------------------------------------
    def item(self, item) -> list[str]:
        cls = type(item)
        if cls is ir.Constant and item.type is not None:
            if is_array(item.type):
                raise unsupported("a constant array at file scope", item)
            return [*([f"// {item.comment}"] if isinstance(getattr(item, "comment", None), str) else []),
                    f"#define {safe_name(item.name)} {self.render(item.value, None, 0)}"]
        if cls is ir.Struct:
            lines = [f"struct {safe_name(item.name)}", "{"]
            lines.extend(f"{INDENT}{self.declarator(t, safe_name(n))};" for t, n in item.members)
            return lines + ["};"]
        if cls is ir.Function and item.body is not None:
            item = with_written_copies(item)
        return super().item(item)

    def signature(self, f: ir.Function) -> str:
        from ..printing import arguments
        head = f"{osl_type(f.returns)} {safe_name(f.name)}("
        params = [self.parameter(p) for p in f.params]
        return head + arguments(lambda text, column, indent: text, params, len(head), 0) + ")"

    def parameter(self, p: ir.Param) -> str:
        qualifier = "" if p.qualifier == "in" else "output "
        name = self.spell(ir.Name(p.name, "param")) if self.spell is not None else safe_name(p.name)
        return qualifier + self.declarator(p.type, name)



def written_names(body) -> set[str]:
    """The names `body` assigns or passes to an `out`/`inout` parameter."""
    written = set()

    def root(e):
        while type(e) is ir.Field or type(e) is ir.Index:
            e = e.base
        return e.name if type(e) is ir.Name else None

    for node in ir.walk(body):
        if type(node) is ir.Assign:
            written.add(root(node.target))
        elif type(node) is ir.Call and isinstance(node.callee, ir.Function):
            written.update(root(a) for a, p in zip(node.args, node.callee.params) if p.qualifier != "in")
    return written


def with_written_copies(f: ir.Function) -> ir.Function:
    """`f` with each `in` parameter its body writes (GLSL allows it, OSL does not) taken as
    `<name>_in` and copied into a local of its own name first."""
    written = written_names(f.body) & {p.name for p in f.params if p.qualifier == "in"}
    if not written:
        return f
    params = [ir.replace(p, name=f"{p.name}_in") if p.name in written else p for p in f.params]
    copies = [ir.Declare(p.type, p.name, ir.Name(f"{p.name}_in", "param", type=p.type), False)
              for p in f.params if p.name in written]
    body = f.body.body if type(f.body) is ir.Block else [f.body]
    return ir.replace(f, params=params, body=ir.Block(copies + list(body), True))
