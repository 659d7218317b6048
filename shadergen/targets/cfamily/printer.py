"""Typed IR (code/ir.py) printed as HLSL, Slang or MSL: one printer, the language a Syntax table
(syntax.py).

The three are C with vector types, as GLSL is: precedence, statements, sections (their
preprocessors read `#ifdef`) and line wrapping are the GLSL printer's (glsl/printer.py), which
this one extends where they differ. Types are `float3`, `float3x3`; GLSL built-ins are renamed or
rewritten (`mod` is floored: `x - y * floor(x / y)`, as GLSL defines it; HLSL's fmod truncates);
a comparison of vectors `==` is reduced with all(); conversions between scalar kinds are written;
a sampler2D is a texture object and its sampler (`<name>_sampler`), sampled by methods; a struct
value is a constructor, braces, or (HLSL, which has neither) a helper function; an array's value
is a braced initialiser. HLSL and Slang keep each matrix as its transpose (syntax.py), so a product
is mul() with its operands swapped. What a language lacks (inverse, HLSL's texture size) is a
helper function the assembler writes once (`helpers()`).
"""
from ...code import ir
from ...code.types import array_element, array_size, is_array, is_matrix, is_vector, scalar_of, size_of, vector_of
from ...errors import ShaderGenError
from ..glsl.printer import PRIMARY, SELECT, UNARY, GlslPrinter
from ..printing import INDENT, arguments, comment_lines
from .syntax import TYPES, Syntax

COMPARISONS = {"lessThan": "<", "lessThanEqual": "<=", "greaterThan": ">", "greaterThanEqual": ">=", "equal": "==",
               "notEqual": "!="}

# GLSL's fragment built-in variables: the entry point copies them into variables of these names
FRAGMENT_BUILTINS = {"gl_FrontFacing": "front_facing"}


class Native(ir.Expr):
    """A call the printer writes for one of the IR: `name(args)`, args IR expressions or text."""
    __slots__ = ("name", "args")
    FIELDS = ("name", "args")


class Cast(ir.Expr):
    """`(type)operand`: HLSL's spread of a scalar over a vector."""
    __slots__ = ("operand",)
    FIELDS = ("operand",)


class Braces(ir.Expr):
    """`{a, b, ...}`: an array's (MSL: a struct's `S{...}`) initialiser; `name` before it or ""."""
    __slots__ = ("name", "args")
    FIELDS = ("name", "args")


class VectorTernary(ir.Expr):
    """`c ? b : a` of a bool vector `c`: HLSL 5's component-wise choice."""
    __slots__ = ("condition", "if_true", "if_false")
    FIELDS = ("condition", "if_true", "if_false")


class Text(ir.Expr):
    """Text the printer wrote from a format (a texture method call): `text`, of precedence PRIMARY."""
    __slots__ = ("text",)
    FIELDS = ("text",)


def unsupported(syntax: Syntax, what: str, node) -> ShaderGenError:
    where = getattr(node, "where", None)
    return ShaderGenError("unsupported_node", f"no {syntax.name} form for {what}",
                          None if where is None else f"{where[0]}:{where[1]}:{where[2]}")


def type_name(ir_type: str, syntax: Syntax) -> str:
    if ir_type == "sampler2D":
        return syntax.texture
    return TYPES.get(ir_type, ir_type)


class CFamilyPrinter(GlslPrinter):
    """`item`, `statements` and `expression` of typed IR in the language of `syntax`;
    `spell(name_node)` decides how a Name is written (the assembler's `vd.x`); `safe(name)` how a
    name the language reserves is respelled (a struct member, a library's local)."""
    __slots__ = ("syntax", "safe")

    def __init__(self, syntax: Syntax, spell, safe):
        super().__init__("essl", spell)  # (conversions between scalar kinds written, as ESSL needs)
        self.syntax = syntax
        self.safe = safe

    # -- expressions -------------------------------------------------------------------------------
    def precedence(self, e) -> int:
        cls = type(e)
        if cls is str or cls is Native or cls is Braces or cls is Text:
            return PRIMARY
        if cls is Cast:
            return UNARY
        if cls is VectorTernary:
            return SELECT
        lowered = self.lowered(e)
        if lowered is not e:
            return self.precedence(lowered)
        return super().precedence(e)

    def lowered(self, e):
        """`e` as this language writes it, in nodes the GLSL printer or this one prints (`e`
        itself where it is written as GLSL writes it)."""
        cls = type(e)
        if cls is ir.Call:
            return self.lower_call(e) if e.builtin else e
        if cls is ir.Construct:
            return self.construct(e)
        if cls is ir.Convert:
            if not self.written(e) and not (self.syntax.spread_written and self.spread(e)):
                return e
            return self.conversion(e.operand, e.type, e)
        if cls is ir.Binary:
            return self.binary(e)
        if cls is ir.Select and e.condition.type is not None and is_vector(e.condition.type):
            return self.vector_select(e.condition, e.if_true, e.if_false, e.type)
        return e

    def vector_select(self, condition, if_true, if_false, t):
        """Component by component: `c ? b : a` (HLSL 5), select(c, b, a) (Slang), select(a, b, c) (MSL)."""
        if self.syntax.vector_select == "ternary":
            return VectorTernary(condition, if_true, if_false, type=t)
        if self.syntax.vector_select == "select":
            return Native("select", [condition, if_true, if_false], type=t)
        return Native("select", [if_false, if_true, condition], type=t)

    @staticmethod
    def spread(e: ir.Convert) -> bool:
        return e.operand.type is not None and size_of(e.operand.type) == 1 and is_vector(e.type)

    def render(self, e, column, indent) -> str:
        cls = type(e)
        if cls is str:
            return e
        if cls is ir.Name:
            return self.spell(e)
        if cls is Native:
            return self.call(e.name, e.args, column, indent)
        if cls is Text:
            return e.text
        if cls is Cast:
            inner = self.precedence(e.operand) < UNARY
            return f"({type_name(e.type, self.syntax)})" + self.operand(e.operand, None, indent, inner)
        if cls is VectorTernary:
            condition = self.operand(e.condition, None, indent, self.precedence(e.condition) <= SELECT
                                     or type(e.condition) is ir.Binary)
            if_true = self.operand(e.if_true, None, indent, self.precedence(e.if_true) <= SELECT)
            return f"{condition} ? {if_true} : {self.operand(e.if_false, None, indent, self.precedence(e.if_false) < SELECT)}"
        if cls is Braces:
            at = None if column is None else column + len(e.name) + 1
            if at is None:
                return e.name + "{" + ", ".join(self.render(a, None, indent) for a in e.args) + "}"
            return e.name + "{" + arguments(self.render, e.args, at, indent) + "}"
        if cls is ir.Call and not e.builtin:
            return self.user_call(e, column, indent)
        if cls is ir.Field and not e.swizzle:
            return self.operand(e.base, column, indent, self.precedence(e.base) < PRIMARY) + "." + self.safe(e.name)
        lowered = self.lowered(e)
        if lowered is not e:
            return self.render(lowered, column, indent)
        if cls is ir.Convert:  # an implicit one the language makes itself
            return self.render(e.operand, column, indent)
        return super().render(e, column, indent)

    def user_call(self, e: ir.Call, column, indent) -> str:
        args = []
        params = e.callee.params if e.callee is not None else [None] * len(e.args)
        for p, a in zip(params, e.args):
            args.append(a)
            if p is not None and p.type == "sampler2D":  # the texture and its sampler
                args.append(self.texture_sampler(a, e)[1])
        return self.call(e.name, args, column, indent)

    def texture_sampler(self, texture, node) -> tuple[str, str]:
        if type(texture) is not ir.Name:
            raise unsupported(self.syntax, "a texture that is not a name", node)
        name = self.spell(texture)
        return name, name + "_sampler"

    def binary(self, e: ir.Binary):
        """Matrix products as mul() (HLSL, Slang); `==` of vectors reduced to one bool."""
        ta, tb = e.left.type, e.right.type
        if ta is None or tb is None:
            return e
        if e.op == "*" and self.syntax.transposed and (is_matrix(ta) or is_matrix(tb)) \
                and (size_of(ta) > 1 and size_of(tb) > 1):
            return Native("mul", [e.right, e.left], type=e.type)  # (A B)^T = B^T A^T; M v = (v^T M^T)^T
        if e.op in ("==", "!=") and e.type == "bool" and is_vector(ta):
            reduce = "all" if e.op == "==" else "any"
            return Native(reduce, [ir.replace(e, type=vector_of("bool", size_of(ta)))], type="bool")
        return e

    def conversion(self, operand, to: str, node=None):
        """`operand` as type `to`: a scalar spread over a vector, else the type's constructor."""
        t = operand.type
        if t == to or t is None:
            return operand
        if is_vector(to) and size_of(t) == 1:
            if self.syntax.splat == "cast":
                return Cast(operand, type=to)
            return Native(type_name(to, self.syntax), [operand], type=to)
        if scalar_of(to) is None or scalar_of(t) is None:
            raise unsupported(self.syntax, f"a conversion of {t} to {to}", node or operand)
        return Native(type_name(to, self.syntax), [operand], type=to)

    def converted(self, e, to: str | None):
        """`e` with the scalar kind of `to` (its own size kept)."""
        if to is None or e.type is None or scalar_of(e.type) is None or scalar_of(to) is None or is_matrix(e.type):
            return e
        target = vector_of(scalar_of(to), size_of(e.type))
        if target == e.type:
            return e
        if type(e) is ir.Literal and target == "float" and not isinstance(e.value, bool):
            return ir.Literal(float(e.value), None, type="float")
        return self.conversion(e, target, e)

    def construct(self, e: ir.Construct):
        """A GLSL constructor as the language's."""
        t, args = e.type, e.args
        syntax = self.syntax
        if is_array(t):
            element = array_element(t)
            return Braces("", [self.converted(a, element) for a in args], type=t)
        scalar = scalar_of(t)
        if scalar is None:  # a struct: members in order
            if syntax.structs == "helper":
                return Native(f"mx_make_{t}", list(args), type=t)
            if syntax.structs == "braces":
                return Braces(t, list(args), type=t)
            return Native(t, list(args), type=t)
        types = [a.type for a in args]
        name = type_name(t, syntax)
        if is_matrix(t):
            n = int(t[3])
            if len(args) == 1 and types[0] is not None and size_of(types[0]) == 1:
                diagonal = self.converted(args[0], "float")
                zero = ir.Literal(0.0, "0.0", type="float")
                return Native(name, [diagonal if i % (n + 1) == 0 else zero for i in range(n * n)], type=t)
            if len(args) == 1 and is_matrix(types[0]) and types[0] != t:
                return Native(name, self.resized_columns(args[0], int(types[0][3]), n), type=t)
            return Native(name, [self.converted(a, "float") for a in args], type=t)
        if size_of(t) == 1:  # float(x), int(x): a vector's first component
            (arg,) = args
            if arg.type is not None and size_of(arg.type) > 1:
                arg = ir.Field(arg, "x", type=scalar_of(arg.type), swizzle=True)
            if arg.type == t:
                return arg
            return Native(name, [arg], type=t)
        if len(args) == 1 and types[0] is not None and size_of(types[0]) == 1:
            return self.conversion(args[0], t, e)  # a splat
        if len(args) == 1 and types[0] is not None and is_vector(types[0]) and size_of(types[0]) > size_of(t):
            arg = ir.Field(args[0], "xyzw"[:size_of(t)], type=vector_of(scalar_of(types[0]), size_of(t)), swizzle=True)
            return self.converted(arg, t)  # vec3(v4): its first components
        return Native(name, [self.converted(a, vector_of(scalar, size_of(ta)) if ta else None)
                             for a, ta in zip(args, types)], type=t)

    def resized_columns(self, matrix, k: int, n: int) -> list:
        """The columns of `mat<n>(mat<k>)` as GLSL fills it (the top-left of a larger matrix; a
        smaller one in the top-left of the identity): indexed alike in either matrix order."""
        columns = []
        vector = type_name(f"vec{n}", self.syntax)
        for i in range(n):
            if i >= k:
                columns.append(Native(vector, [ir.Literal(float(j == i), None, type="float") for j in range(n)],
                                      type=f"vec{n}"))
                continue
            column = ir.Index(matrix, ir.Literal(i, None, type="int"), type=f"vec{k}")
            if k > n:
                columns.append(ir.Field(column, "xyzw"[:n], type=f"vec{n}", swizzle=True))
            elif k == n:
                columns.append(column)
            else:
                columns.append(Native(vector, [column] + [ir.Literal(0.0, None, type="float")] * (n - k),
                                      type=f"vec{n}"))
        return columns

    def lower_call(self, e: ir.Call):
        """A GLSL built-in call as the language's."""
        name, args, syntax = e.name, e.args, self.syntax
        types = [a.type for a in args]
        t = e.type
        if name == "mod":  # GLSL's is floored: x - y * floor(x / y)
            x, y = (self.converted(a, t) if size_of(a.type or "") == size_of(t) else a for a in args)
            floor = Native("floor", [ir.Binary("/", x, y, type=t)], type=t)
            return ir.Binary("-", x, ir.Binary("*", y, floor, type=t), type=t)
        if name in COMPARISONS:
            return ir.Binary(COMPARISONS[name], args[0], args[1], type=t)
        if name == "not":
            return ir.Unary("!", args[0], type=t)
        if name == "inverse":
            if types[0] not in ("mat3", "mat4"):
                raise unsupported(syntax, f"inverse of a {types[0]}", e)
            return Native(f"mx_inverse_{types[0]}", list(args), type=t)
        if name == "matrixCompMult":  # column by column (or row by row: alike)
            n = int(t[3])
            index = [ir.Literal(i, None, type="int") for i in range(n)]
            return Native(type_name(t, syntax), [ir.Binary("*", ir.Index(args[0], i, type=f"vec{n}"),
                                                           ir.Index(args[1], i, type=f"vec{n}"), type=f"vec{n}")
                                                 for i in index], type=t)
        if (name, len(args)) in syntax.texture_calls:
            texture, sampler = self.texture_sampler(args[0], e)
            rest = [self.render(a, None, 0) for a in args[1:]]
            return Text(syntax.texture_calls[(name, len(args))].format(*rest, t=texture, s=sampler), type=t)
        if name == "mix" and types[2] is not None and scalar_of(types[2]) == "bool":
            if size_of(types[2]) == 1:
                return ir.Select(args[2], args[1], args[0], type=t)
            return self.vector_select(args[2], args[1], args[0], t)
        if name in ("findMSB", "findLSB", "bitCount") and not syntax.transposed:
            raise unsupported(syntax, name, e)
        renamed = syntax.renamed.get((name, len(args)), syntax.renamed.get(name, name))
        call = Native(renamed, list(args), type=t)
        if syntax.transposed and (name == "sign" and scalar_of(t) == "float" or name in ("findMSB", "findLSB", "bitCount")):
            call = Native(renamed, list(args), type=vector_of("uint" if name != "sign" else "int", size_of(t)))
            call = Native(type_name(t, syntax), [call], type=t)  # HLSL's return ints (uints)
        elif name in ("floatBitsToInt", "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat") and not syntax.transposed:
            call = Native(f"as_type<{type_name(t, syntax)}>", list(args), type=t)
        if name == "dFdy":  # GL's window y runs up, the others' framebuffer y down
            return ir.Unary("-", call, type=t)
        return call

    # -- statements --------------------------------------------------------------------------------
    def simple(self, s, column, indent) -> str:
        cls = type(s)
        if cls is ir.Assign and s.op == "*=" and self.syntax.transposed and s.value is not None \
                and s.target.type is not None and s.value.type is not None \
                and (is_matrix(s.target.type) or is_matrix(s.value.type)) and size_of(s.value.type) > 1:
            product = ir.Binary("*", s.target, s.value, type=s.target.type)
            return super().simple(ir.replace(s, op="=", value=product), column, indent)
        if cls is ir.Declare and s.init is not None and is_array(s.type) and type(s.init) is not ir.Construct:
            raise unsupported(self.syntax, "an array initialised by a value that is not its constructor", s)
        return super().simple(s, column, indent)

    def declarator(self, ir_type: str, name: str) -> str:
        if is_array(ir_type):
            size = ir_type[ir_type.rindex('['):]
            return f"{type_name(array_element(ir_type), self.syntax)} {name}{size}"
        return f"{type_name(ir_type, self.syntax)} {name}"

    # -- items -------------------------------------------------------------------------------------
    def item(self, item) -> list[str]:
        cls = type(item)
        if cls is ir.Struct:
            lines = comment_lines(item.comment) if item.comment else []
            lines.append(f"struct {item.name}")
            lines.append("{")
            lines.extend(f"{INDENT}{self.declarator(t, self.safe(n))};" for t, n in item.members)
            lines.append("};")
            return lines
        if cls is ir.Constant and item.type is not None:
            lines = comment_lines(item.comment) if item.comment else []
            ir_type = self.sized(item.type, item.value)
            keyword = self.syntax.constant_array if is_array(ir_type) and self.syntax.constant_array else \
                self.syntax.constant
            head = f"{keyword} " + self.declarator(ir_type, self.safe(item.name)) + " = "
            lines.extend((head + self.render(item.value, len(head), 0) + ";").split("\n"))
            return lines
        return super().item(item)

    @staticmethod
    def sized(ir_type: str, value) -> str:
        """`T[]` sized by its constructor's arguments."""
        if is_array(ir_type) and array_size(ir_type) is None and type(value) is ir.Construct:
            return f"{array_element(ir_type)}[{len(value.args)}]"
        return ir_type

    def global_declaration(self, g: ir.Global) -> str:
        keyword = self.syntax.mutable_global
        text = (keyword + " " if keyword else "") + self.declarator(g.type, self.spell(ir.Name(g.name, "global")))
        if g.init is not None:
            text += " = " + self.render(g.init, len(text) + 3, 0)
        return text + ";"

    def parameter(self, p: ir.Param) -> str:
        name = self.spell(ir.Name(p.name, "param"))
        if p.type == "sampler2D":
            return f"{self.syntax.texture} {name}, {self.syntax.sampler} {name}_sampler"
        if p.qualifier == "in":
            return ("const " if p.const else "") + self.declarator(p.type, name)
        if is_array(p.type):
            raise unsupported(self.syntax, "an out parameter of an array", p)
        return self.syntax.out_parameter.format(qualifier=p.qualifier, type=type_name(p.type, self.syntax), name=name)

    def signature(self, f: ir.Function) -> str:
        head = f"{type_name(f.returns, self.syntax)} {f.name}("
        params = [self.parameter(p) for p in f.params]
        return head + arguments(lambda text, column, indent: text, params, len(head), 0) + ")"


# -- helper functions ------------------------------------------------------------------------------
# inverse(): the adjugate over the determinant, as WGSL's helpers (wgsl/builtins.py) write it. The
# same text inverts in either matrix order: inverse(M^T) = inverse(M)^T, and m[i][j], read as
# column-row or row-column, flips with the constructor's order.
HELPERS = {"mx_inverse_mat3": """\
float3x3 mx_inverse_mat3(float3x3 m)
{
    float3 r0 = cross(m[1], m[2]);
    float3 r1 = cross(m[2], m[0]);
    float3 r2 = cross(m[0], m[1]);
    return transpose(float3x3(r0, r1, r2)) * (1.0 / dot(m[0], r0));
}
""", "mx_inverse_mat4": """\
float4x4 mx_inverse_mat4(float4x4 a)
{
    float s0 = a[0][0] * a[1][1] - a[1][0] * a[0][1];
    float s1 = a[0][0] * a[1][2] - a[1][0] * a[0][2];
    float s2 = a[0][0] * a[1][3] - a[1][0] * a[0][3];
    float s3 = a[0][1] * a[1][2] - a[1][1] * a[0][2];
    float s4 = a[0][1] * a[1][3] - a[1][1] * a[0][3];
    float s5 = a[0][2] * a[1][3] - a[1][2] * a[0][3];
    float c5 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
    float c4 = a[2][1] * a[3][3] - a[3][1] * a[2][3];
    float c3 = a[2][1] * a[3][2] - a[3][1] * a[2][2];
    float c2 = a[2][0] * a[3][3] - a[3][0] * a[2][3];
    float c1 = a[2][0] * a[3][2] - a[3][0] * a[2][2];
    float c0 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
    float inv_det = 1.0 / (s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0);
    return float4x4(
        a[1][1] * c5 - a[1][2] * c4 + a[1][3] * c3, -a[0][1] * c5 + a[0][2] * c4 - a[0][3] * c3,
        a[3][1] * s5 - a[3][2] * s4 + a[3][3] * s3, -a[2][1] * s5 + a[2][2] * s4 - a[2][3] * s3,
        -a[1][0] * c5 + a[1][2] * c2 - a[1][3] * c1, a[0][0] * c5 - a[0][2] * c2 + a[0][3] * c1,
        -a[3][0] * s5 + a[3][2] * s2 - a[3][3] * s1, a[2][0] * s5 - a[2][2] * s2 + a[2][3] * s1,
        a[1][0] * c4 - a[1][1] * c2 + a[1][3] * c0, -a[0][0] * c4 + a[0][1] * c2 - a[0][3] * c0,
        a[3][0] * s4 - a[3][1] * s2 + a[3][3] * s0, -a[2][0] * s4 + a[2][1] * s2 - a[2][3] * s0,
        -a[1][0] * c3 + a[1][1] * c1 - a[1][2] * c0, a[0][0] * c3 - a[0][1] * c1 + a[0][2] * c0,
        -a[3][0] * s3 + a[3][1] * s1 - a[3][2] * s0, a[2][0] * s3 - a[2][1] * s1 + a[2][2] * s0) * inv_det;
}
""", "mx_texture_size": """\
int2 mx_texture_size(Texture2D t, int lod)
{
    uint width, height, levels;
    t.GetDimensions(uint(lod), width, height, levels);
    return int2(int(width), int(height));
}
""", "mx_texture_levels": """\
int mx_texture_levels(Texture2D t)
{
    uint width, height, levels;
    t.GetDimensions(0, width, height, levels);
    return int(levels);
}
"""}
TEXTURE_HELPERS = {("textureSize", 2): "mx_texture_size", ("textureQueryLevels", 1): "mx_texture_levels"}


def helpers(items, syntax: Syntax, structs, safe) -> list[str]:
    """The helper functions printing `items` calls, in a fixed order, for the assembler to write
    once: inverse(), HLSL's texture queries, and (HLSL) a function making each struct value."""
    wanted, made = set(), set()
    for item in items:
        for node in ir.walk(item):
            if type(node) is ir.Call and node.builtin:
                if node.name == "inverse":
                    wanted.add(f"mx_inverse_{node.args[0].type}")
                elif syntax.transposed and (node.name, len(node.args)) in TEXTURE_HELPERS:
                    wanted.add(TEXTURE_HELPERS[(node.name, len(node.args))])
            elif type(node) is ir.Construct and syntax.structs == "helper" and scalar_of(node.type) is None \
                    and not is_array(node.type):
                made.add(node.type)
    lines = [line for name, text in HELPERS.items() if name in wanted for line in [*text.splitlines(), ""]]
    for struct in structs:
        if struct.name in made:
            lines.extend(struct_maker(struct, syntax, safe))
    return lines


def struct_maker(struct: ir.Struct, syntax: Syntax, safe) -> list[str]:
    """`S mx_make_S(members...)`: a struct value from its members, which HLSL cannot construct."""
    members = [(t, safe(n)) for t, n in struct.members]
    params = ", ".join(f"{type_name(t, syntax)} {n}" for t, n in members)
    lines = [f"{struct.name} mx_make_{struct.name}({params})", "{", f"{INDENT}{struct.name} made;"]
    lines += [f"{INDENT}made.{n} = {n};" for _, n in members]
    return lines + [f"{INDENT}return made;", "}", ""]
