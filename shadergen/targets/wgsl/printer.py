"""Typed IR (code/ir.py) printed as WGSL.

WGSL differs from GLSL where only types settle it, and the IR carries them: no implicit
conversion (every Convert is written), no scalar arguments to vector built-ins (scalars spread),
pointers instead of `out` parameters (`ptr<function, T>`, read through `*p`, passed as `&a`),
immutable parameters (one assigned in the body is copied to a `var`), no overloading (the
caller's `function_names` spells each overload apart; `function_names()` makes one), a GLSL
sampler is a texture and its sampler, `select()` for `?:`, braces around every body, `==` of
vectors component-wise, and stricter grammar for mixing operators (`a < b == c`, `a & b | c` need
parentheses). Built-ins are renamed or rewritten (builtins.py); those WGSL lacks are helper
functions (`helpers()`), which the assembler writes once. Sections of macros still in the IR take
the side WGSL stands on: GL_ES defined (a web target, as ESSL), every other macro undefined.
What has no WGSL form raises ShaderGenError("unsupported_node", ...).
"""
from functools import lru_cache

from ...code import ir
from ...code.types import array_element, array_size, is_array, is_matrix, is_vector, scalar_of, size_of, vector_of
from ...errors import ShaderGenError
from ..glsl.printer import literal_text as glsl_literal
from ..printing import INDENT, WIDTH, arguments, binary_text, comment_lines, end_column, with_trailing
from .builtins import (BITCASTS, COMPONENTWISE, HELPER_FUNCTIONS, INVERSE_HELPERS, IR_RENAMED, SELECT_HELPERS,
                       TEXTURE_CALLS, WGSL_RESERVED, WGSL_TYPES)

DEFINED = frozenset({"GL_ES"})

# GLSL's fragment built-in variables: the entry point copies them into private variables of these
# names (target.py), so library code reads them anywhere.
FRAGMENT_BUILTINS = {"gl_FrontFacing": "front_facing"}

# Precedence classes (WGSL section 8.19): which kinds of operand each operator takes unparenthesised.
PRIMARY, UNARY, MUL, ADD, SHIFT, REL, AND, OR, BITS = ("primary", "unary", "mul", "add", "shift", "rel", "and", "or",
                                                        "bits")
CLASS = {"*": MUL, "/": MUL, "%": MUL, "+": ADD, "-": ADD, "<<": SHIFT, ">>": SHIFT, "<": REL, ">": REL, "<=": REL,
         ">=": REL, "==": REL, "!=": REL, "&&": AND, "||": OR, "&": BITS, "|": BITS, "^": BITS}
_TIGHT = {PRIMARY, UNARY}
_ARITH = _TIGHT | {MUL, ADD, SHIFT}
OPERANDS = {  # class -> (left operands, right operands) taken without parentheses
    MUL: (_TIGHT | {MUL}, _TIGHT), ADD: (_TIGHT | {MUL, ADD}, _TIGHT | {MUL}), SHIFT: (_TIGHT, _TIGHT),
    REL: (_ARITH, _ARITH), AND: (_ARITH | {REL, AND}, _ARITH | {REL}), OR: (_ARITH | {REL, OR}, _ARITH | {REL}),
}
COMPARISONS = {"lessThan": "<", "lessThanEqual": "<=", "greaterThan": ">", "greaterThanEqual": ">=", "equal": "==",
               "notEqual": "!="}


def literal_text(node: ir.Literal) -> str:
    """A literal as GLSL spells it, whose suffixes WGSL takes in lower case only (`1.0F`, `2U`)."""
    text = node.text
    if text is None:
        return glsl_literal(node)
    if text[-1] not in "FU":
        return text
    hexadecimal = text.startswith(("0x", "0X"))  # where F is a digit
    return text[:-1] + text[-1].lower() if text[-1] == "U" or (text[-1] == "F" and not hexadecimal) else text


def unsupported(what: str, node) -> ShaderGenError:
    where = getattr(node, "where", None)
    return ShaderGenError("unsupported_node", f"no WGSL form for {what}",
                          None if where is None else f"{where[0]}:{where[1]}:{where[2]}")


def safe_name(name: str) -> str:
    if name in FRAGMENT_BUILTINS:
        return FRAGMENT_BUILTINS[name]
    return f"{name}_" if name in WGSL_RESERVED else name


@lru_cache(maxsize=None)
def wgsl_type(ir_type: str) -> str:
    if is_array(ir_type):
        if array_size(ir_type) is None:
            raise ShaderGenError("unsupported_node", f"no WGSL form for an array of unknown size ({ir_type})")
        return f"array<{wgsl_type(array_element(ir_type))}, {array_size(ir_type)}>"
    if ir_type == "sampler2D":
        return "texture_2d<f32>"
    return WGSL_TYPES.get(ir_type, ir_type)


def function_names(functions) -> dict[str, str]:
    """Function.key -> WGSL name for `functions`: an overloaded name takes its parameter types
    (`mx_mix_vec3_float`; an array `vec3[3]` as `vec3_3`); the same list gives the same names
    whatever its order."""
    keys_by_name: dict[str, set[str]] = {}
    params_by_key = {}
    for f in functions:
        keys_by_name.setdefault(f.name, set()).add(f.key)
        params_by_key[f.key] = f
    names = {}
    for name, keys in keys_by_name.items():
        for key in sorted(keys):
            if len(keys) == 1:
                names[key] = name
            else:
                types = [p.type.replace("[", "_").replace("]", "") for p in params_by_key[key].params]
                names[key] = "_".join([name, *types])
    return names


def helpers(items) -> list[str]:
    """The helper functions (builtins.HELPER_FUNCTIONS) that printing `items` calls, in a fixed
    order, for the assembler to write once."""
    wanted = set()
    for item in items:
        for node in ir.walk(item):
            if type(node) is ir.Call and node.builtin and node.name == "inverse":
                if node.args[0].type in INVERSE_HELPERS:
                    wanted.add(INVERSE_HELPERS[node.args[0].type])
            elif type(node) is ir.Select and node.type in SELECT_HELPERS:
                wanted.add(SELECT_HELPERS[node.type])
    return [line for name, text in HELPER_FUNCTIONS.items() if name in wanted for line in [*text.splitlines(), ""]]


def resolve_sections(stmts, defined) -> list:
    """Statements (or items) with their macro sections replaced by the side WGSL takes (`defined`:
    the macros taken as defined)."""
    out = []
    for s in stmts:
        if type(s) is ir.Section:
            out.extend(resolve_sections(s.body if (s.macro in defined) == s.defined else (s.other or []), defined))
        else:
            out.append(s)
    return out


def else_chain(parts, defined):
    """What follows an `else` as one statement: sections resolved, an `#ifdef X else ... #endif`
    after an `else if` attached to that `if` as the preprocessor would."""
    if not parts:
        return None
    head, rest = parts[0], parts[1:]
    if not rest:
        return head
    if type(head) is not ir.If:
        raise unsupported("several else branches of one if", head)
    after = [] if head.other is None else else_parts(head.other, defined)
    return ir.replace(head, other=ir.Block([else_chain(after + rest, defined)], False))


def else_parts(other, defined) -> list:
    """The else clauses `other` stands for, its sections resolved (none where all of them drop
    theirs)."""
    if type(other) is not ir.Block or other.scoped or not any(type(s) is ir.Section for s in other.body):
        return [other]
    return [part for s in resolve_sections(other.body, defined) for part in else_parts(s, defined)]


class Native(ir.Expr):
    """A WGSL built-in call the printer writes for a GLSL one: `args` IR expressions or text."""
    __slots__ = ("name", "args")
    FIELDS = ("name", "args")


def assigned_roots(body) -> set[str]:
    """Names a body assigns or passes as an out argument (WGSL parameters are immutable)."""
    names: set[str] = set()
    _assigned(body, names)
    return names


def _assigned(node, names: set) -> None:
    cls = type(node)
    if cls is ir.Assign:
        _add_root(node.target, names)
    elif cls is ir.Call and node.callee is not None:
        for p, a in zip(node.callee.params, node.args):
            if p.qualifier != "in":
                _add_root(a, names)
    elif cls is ir.Name or cls is ir.Literal:
        return
    for field in cls.CHILDREN:  # (ir.walk, but without a list per node: this runs per function printed)
        value = getattr(node, field)
        if isinstance(value, ir.Node):
            _assigned(value, names)
        elif type(value) is list or type(value) is tuple:
            for v in value:
                if isinstance(v, ir.Node):
                    _assigned(v, names)


def _add_root(target, names: set) -> None:
    while type(target) is ir.Field or type(target) is ir.Index:
        target = target.base
    if type(target) is ir.Name:
        names.add(target.name)


class WgslPrinter:
    """`item`, `statements` and `expression` of typed IR as WGSL. `function_names`: Function.key ->
    WGSL name (function_names() makes one); `spell(name_node)`: how a Name is written; `defined`:
    the macros whose sections count as defined where a section is still in the IR."""
    __slots__ = ("function_names", "spell", "defined")

    def __init__(self, function_names: dict[str, str] | None = None, spell=None, defined=DEFINED):
        self.function_names = function_names or {}
        self.spell = spell
        self.defined = frozenset(defined)

    def expression(self, expr) -> str:
        writer = _Writer(self, frozenset())
        text = writer.render(expr, None, 0)
        if writer.before or writer.after:
            raise unsupported("an out argument of a member or element inside an expression", expr)
        return text

    def statements(self, stmts, depth: int) -> list[str]:
        lines: list[str] = []
        _Writer(self, frozenset()).statements(stmts, depth, lines)
        return lines

    def item(self, item) -> list[str]:
        cls = type(item)
        if cls is ir.Section:
            return [line for x in resolve_sections([item], self.defined) for line in self.item(x)]
        lines = comment_lines(item.comment) if getattr(item, "comment", None) and cls is not ir.Comment else []
        writer = _Writer(self, frozenset())
        if cls is ir.Function:
            lines.extend(self.function(item))
        elif cls is ir.Struct:
            lines.append(f"struct {item.name} {{")
            lines.extend(f"{INDENT}{safe_name(n)}: {wgsl_type(t)}," for t, n in item.members)
            lines.append("}")
        elif cls is ir.Constant:
            ir_type = self.sized(item.type, item.value)
            # A constant array indexed at run time is a value naga copies into a local at every
            # index (SPIR-V cannot index a value), which makes drivers compile for minutes; a
            # private variable is indexed in place.
            keyword = "var<private>" if is_array(ir_type) else "const"
            head = f"{keyword} {safe_name(item.name)}: {wgsl_type(ir_type)} = "
            value = writer.converted(item.value, ir_type)
            lines.extend((head + writer.render(value, len(head), 0) + ";").split("\n"))
        elif cls is ir.Global:
            # a module-scope variable; uniforms and stage inputs and outputs are the assembler's
            # (bound buffers, entry point parameters), which declares them itself
            if item.kind != "builtin":  # the target's own variable: nothing to declare
                head = f"var<private> {safe_name(item.name)}: {wgsl_type(self.sized(item.type, item.init))}"
                if item.init is not None:
                    head += " = " + writer.render(writer.converted(item.init, item.type), len(head) + 3, 0)
                lines.extend((head + ";").split("\n"))
        elif cls is ir.Comment:
            lines.extend(comment_lines(item.lines))
        else:
            raise unsupported(f"a {cls.__name__} item", item)
        return lines

    @staticmethod
    def sized(ir_type: str, value) -> str:
        """`T[]` sized by its constructor's arguments."""
        if is_array(ir_type) and array_size(ir_type) is None and type(value) is ir.Construct:
            return f"{array_element(ir_type)}[{len(value.args)}]"
        return ir_type

    def function(self, f: ir.Function) -> list[str]:
        body = f.body.body if type(f.body) is ir.Block else f.body
        assigned = assigned_roots(f.body)
        pointers = frozenset(p.name for p in f.params if p.qualifier != "in")
        parts, copies = [], []
        writer = _Writer(self, pointers, f.returns, assigned)
        for p in f.params:
            name = writer.spelled(ir.Name(p.name, "param"))
            if p.type == "sampler2D":
                parts.append(f"{name}: texture_2d<f32>")
                parts.append(f"{name}_sampler: sampler")
            elif p.qualifier != "in":
                parts.append(f"{name}: ptr<function, {wgsl_type(p.type)}>")
            elif p.name in assigned:
                # `__`: no document name has it (targets/names.py), so the copy's source is unique
                parts.append(f"{p.name}__in: {wgsl_type(p.type)}")
                copies.append(f"{INDENT}var {name}: {wgsl_type(p.type)} = {p.name}__in;")
            else:
                parts.append(f"{name}: {wgsl_type(p.type)}")
        head = f"fn {self.function_names.get(f.key, f.name)}("
        arrow = "" if f.returns == "void" else f" -> {wgsl_type(f.returns)}"
        signature = head + arguments(lambda text, column, indent: text, parts, len(head), 0) + ")" + arrow + " {"
        lines = [*signature.split("\n"), *copies]
        writer.statements(body, 1, lines)
        lines.append("}")
        return lines


class _Writer:
    """Prints one function's statements: knows its pointer parameters, and gathers the lines a
    statement needs before and after it (copies through which a member is passed as an out
    argument: naga's SPIR-V writer in wgpu 0.32 panics on a pointer into a composite)."""
    __slots__ = ("printer", "pointers", "returns", "assigned", "before", "after", "temporaries")

    def __init__(self, printer: WgslPrinter, pointers, returns=None, assigned=None):
        self.printer = printer
        self.pointers = pointers
        self.returns = returns
        self.assigned = assigned  # names the body assigns (None: unknown, every local a var)
        self.before: list[str] = []
        self.after: list[str] = []
        self.temporaries = 0

    # -- expressions -------------------------------------------------------------------------------
    def spelled(self, e: ir.Name) -> str:
        return self.printer.spell(e) if self.printer.spell is not None else safe_name(e.name)

    def is_pointer(self, e) -> bool:
        return type(e) is ir.Name and e.kind == "param" and e.name in self.pointers

    def klass(self, e) -> str:
        cls = type(e)
        if cls is ir.Binary:
            return CLASS[e.op]
        if cls is ir.Unary or (cls is ir.Literal and literal_text(e).startswith("-")) or self.is_pointer(e):
            return UNARY
        return PRIMARY

    def render(self, e, column, indent) -> str:
        cls = type(e)
        if cls is str:
            return e
        if cls is ir.Name:
            return "*" + self.spelled(e) if self.is_pointer(e) else self.spelled(e)
        if cls is ir.Literal:
            return literal_text(e)
        if column is not None:
            flat = self.render(e, None, indent)
            if column + len(flat) <= WIDTH:
                return flat
        if cls is ir.Binary:
            return self.binary(e, column, indent)
        if cls is ir.Unary:
            # `-(-x)` (`--` is a decrement) and `-(*p)` read better with parentheses
            inner = self.klass(e.operand) != PRIMARY
            return e.op + self.operand(e.operand, None if column is None else column + len(e.op), indent, inner)
        if cls is ir.Call:
            return self.render(self.lower_call(e), column, indent) if e.builtin else self.call(e, column, indent)
        if cls is Native:
            return self.call_text(e.name, e.args, column, indent)
        if cls is ir.Construct:
            return self.render(self.construct(e), column, indent)
        if cls is ir.Field:
            base = self.operand(e.base, column, indent, self.klass(e.base) != PRIMARY)
            return base + "." + (e.name if e.swizzle else safe_name(e.name))
        if cls is ir.Index:
            base = self.operand(e.base, column, indent, self.klass(e.base) != PRIMARY)
            at = None if column is None else end_column(column, base) + 1
            return f"{base}[{self.render(e.index, at, indent)}]"
        if cls is ir.Select:
            return self.render(self.select(e), column, indent)
        if cls is ir.Convert:
            return self.render(self.conversion(e.operand, e.type, e), column, indent)
        if cls is ir.Placeholder:
            raise unsupported(f"the placeholder {{{{{e.name}}}}} (not instantiated)", e)
        raise unsupported(f"a {cls.__name__} expression", e)

    def operand(self, e, column, indent, parenthesised: bool) -> str:
        if not parenthesised:
            return self.render(e, column, indent)
        return "(" + self.render(e, None if column is None else column + 1, indent) + ")"

    def call_text(self, name: str, args, column, indent) -> str:
        if column is None:
            return name + "(" + ", ".join([self.render(a, None, indent) for a in args]) + ")"
        return name + "(" + arguments(self.render, args, column + len(name) + 1, indent) + ")"

    def binary(self, e: ir.Binary, column, indent) -> str:
        e = self.binary_operands(e)
        if type(e) is not ir.Binary:
            return self.render(e, column, indent)
        kind = CLASS[e.op]
        if kind is BITS:
            left_ok, right_ok = _TIGHT | ({BITS} if type(e.left) is ir.Binary and e.left.op == e.op else set()), _TIGHT
        else:
            left_ok, right_ok = OPERANDS[kind]
        left, right = self.klass(e.left) not in left_ok, self.klass(e.right) not in right_ok
        if column is None:  # (the common case, without the wrapping's closures)
            return f"{self.operand(e.left, None, indent, left)} {e.op} {self.operand(e.right, None, indent, right)}"
        return binary_text(lambda at, indent: self.operand(e.left, at, indent, left), e.op,
                           lambda at, indent: self.operand(e.right, at, indent, right), column, indent)

    def binary_operands(self, e: ir.Binary):
        """GLSL's binary operators as WGSL takes them: scalar kinds made equal, a scalar added to
        a matrix spread over it, a matrix divided by a scalar multiplied by its inverse, `==` of
        vectors reduced to one bool, a shift by a signed amount by an unsigned one."""
        ta, tb = e.left.type, e.right.type
        if ta is None or tb is None or e.op in ("&&", "||"):
            return e
        if e.op in ("<<", ">>"):  # WGSL shifts by u32 only (a literal amount is abstract)
            if scalar_of(tb) != "int" or type(e.right) is ir.Literal:
                return e
            return ir.replace(e, right=ir.Convert(vector_of("uint", size_of(tb)), e.right, implicit=True))
        left, right = e.left, e.right
        sa, sb = scalar_of(ta), scalar_of(tb)
        if sa and sb and sa != sb and "bool" not in (sa, sb) and not (is_matrix(ta) or is_matrix(tb)):
            wider = "float" if "float" in (sa, sb) else "uint"
            if sa != wider:
                left = ir.Convert(vector_of(wider, size_of(ta)), left, implicit=True)
            else:
                right = ir.Convert(vector_of(wider, size_of(tb)), right, implicit=True)
        if is_matrix(ta) != is_matrix(tb) and e.op in ("+", "-", "/"):
            matrix, scalar = (ta, right) if is_matrix(ta) else (tb, left)
            if e.op == "/" and is_matrix(ta) and scalar_of(tb) == "float" and size_of(tb) == 1:
                one = ir.Literal(1.0, "1.0", type="float")
                return ir.Binary("*", left, ir.Binary("/", one, right, type=tb), type=ta)
            if e.op == "/" or size_of(scalar.type) != 1:
                raise unsupported(f"{ta} {e.op} {tb}", e)
            n = int(matrix[3])
            column = ir.Construct(f"vec{n}", [scalar])
            spread = ir.Construct(matrix, [column] * n)
            return ir.replace(e, left=spread if left is scalar else left, right=spread if right is scalar else right)
        if e.op in ("==", "!=") and e.type == "bool" and is_vector(ta):
            reduce = "all" if e.op == "==" else "any"
            return Native(reduce, [ir.replace(e, left=left, right=right, type=vector_of("bool", size_of(ta)))],
                          type="bool")
        if left is e.left and right is e.right:
            return e
        return ir.replace(e, left=left, right=right)

    def conversion(self, operand, to: str, node=None):
        """`operand` as type `to`, as WGSL writes it: a literal respelled, a scalar spread over a
        vector, a conversion by constructor."""
        t = operand.type
        if t == to or t is None:
            return operand
        if type(operand) is ir.Literal and size_of(to) == 1 and not isinstance(operand.value, bool):
            kind = scalar_of(to)
            if kind == "float":
                return ir.Literal(float(operand.value), None, type="float")
            if kind in ("int", "uint") and float(operand.value).is_integer():
                return ir.Literal(int(operand.value), None, type=kind)
        if size_of(to) > 1 and size_of(t) == 1 and not is_matrix(to):
            scalar = scalar_of(to)
            inner = operand if scalar_of(t) == scalar else Native(wgsl_type(scalar), [operand], type=scalar)
            return Native(wgsl_type(to), [inner], type=to)
        if scalar_of(to) is None or scalar_of(t) is None:
            raise unsupported(f"a conversion of {t} to {to}", node or operand)
        return Native(wgsl_type(to), [operand], type=to)

    def converted(self, e, to: str | None):
        return e if to is None or e.type is None or e.type == to else self.conversion(e, to, e)

    def construct(self, e: ir.Construct):
        """A GLSL constructor as WGSL's: arguments converted to the component type, a matrix's
        diagonal or the top-left of a larger matrix, an array's element type and size."""
        t, args = e.type, e.args
        if is_array(t):
            element = array_element(t)
            size = array_size(t) or len(args)
            return Native(f"array<{wgsl_type(element)}, {size}>", [self.converted(a, element) for a in args], type=t)
        scalar = scalar_of(t)
        if scalar is None:  # a struct: members in order
            return Native(t, list(args), type=t)
        types = [a.type for a in args]
        if is_matrix(t):
            n = int(t[3])
            if len(args) == 1 and types[0] is not None and size_of(types[0]) == 1 and not is_matrix(types[0]):
                diagonal = self.converted(args[0], "float")
                zero = ir.Literal(0.0, "0.0", type="float")
                return Native(wgsl_type(t), [diagonal if i % (n + 1) == 0 else zero for i in range(n * n)], type=t)
            if len(args) == 1 and is_matrix(types[0]) and types[0] != t:
                return Native(wgsl_type(t), self.resized_columns(args[0], int(types[0][3]), n), type=t)
            floats = [a if ta is None or scalar_of(ta) == "float" else
                      self.conversion(a, vector_of("float", size_of(ta))) for a, ta in zip(args, types)]
            return Native(wgsl_type(t), floats, type=t)
        if size_of(t) == 1:  # float(x), int(x): a vector's first component
            (arg,) = args
            if arg.type is not None and size_of(arg.type) > 1:
                arg = ir.Field(arg, "x", type=scalar_of(arg.type), swizzle=True)
            if arg.type == t:
                return arg
            return self.conversion(arg, t, e) if arg.type is not None else Native(wgsl_type(t), [arg], type=t)
        if len(args) == 1 and types[0] is not None and is_vector(types[0]):
            arg = args[0]
            if size_of(types[0]) > size_of(t):  # vec3(v4): its first components
                arg = ir.Field(arg, "xyzw"[:size_of(t)], type=vector_of(scalar_of(types[0]), size_of(t)), swizzle=True)
            return self.converted(arg, t)  # vec2(ivec2): the conversion itself
        return Native(wgsl_type(t), [a if ta is None or scalar_of(ta) == scalar else
                                     self.conversion(a, vector_of(scalar, size_of(ta))) for a, ta in zip(args, types)],
                      type=t)

    @staticmethod
    def resized_columns(matrix, k: int, n: int) -> list:
        """The columns of `mat<n>(mat<k>)` as GLSL fills it: the top-left of a larger matrix; a
        smaller one in the top-left of the identity."""
        columns = []
        for i in range(n):
            if i >= k:  # the identity's column
                columns.append(Native(f"vec{n}f", [ir.Literal(float(j == i), None, type="float") for j in range(n)],
                                      type=f"vec{n}"))
                continue
            column = ir.Index(matrix, ir.Literal(i, None, type="int"), type=f"vec{k}")
            if k >= n:
                columns.append(ir.Field(column, "xyzw"[:n], type=f"vec{n}", swizzle=True) if k > n else column)
            else:
                zeros = [ir.Literal(0.0, None, type="float")] * (n - k)
                columns.append(Native(f"vec{n}f", [column, *zeros], type=f"vec{n}"))
        return columns

    def select(self, e: ir.Select):
        t = e.type
        if_true, if_false = self.converted(e.if_true, t), self.converted(e.if_false, t)
        if is_matrix(t):  # select() takes scalars and vectors: a helper function (helpers())
            return Native(SELECT_HELPERS[t], [if_false, if_true, e.condition], type=t)
        return Native("select", [if_false, if_true, e.condition], type=t)

    def lower_call(self, e: ir.Call):
        """A GLSL built-in call as WGSL's (builtins.py)."""
        name, args = e.name, e.args
        types = [a.type for a in args]
        if name == "mod":  # GLSL's is floored: x - y * floor(x / y)
            t = e.type
            x, y = (self.converted(a, t) for a in args)
            floor = Native("floor", [ir.Binary("/", x, y, type=t)], type=t)
            return ir.Binary("-", x, ir.Binary("*", y, floor, type=t), type=t)
        if name in COMPARISONS:
            return ir.Binary(COMPARISONS[name], args[0], args[1], type=e.type)
        if name in ("isnan", "isinf"):  # by the bits: WGSL may assume no NaN or infinity in arithmetic
            n = size_of(types[0])
            bits_type = "u32" if n == 1 else f"vec{n}u"
            bits = Native(f"bitcast<{bits_type}>", [args[0]], type=vector_of("uint", n))
            mask, inf = ("0x7fffffffu", "0x7f800000u") if n == 1 else (f"vec{n}u(0x7fffffffu)", f"vec{n}u(0x7f800000u)")
            masked = ir.Binary("&", bits, ir.Literal(None, mask, type=vector_of("uint", n)), type=vector_of("uint", n))
            return ir.Binary(">" if name == "isnan" else "==", masked, ir.Literal(None, inf, type=vector_of("uint", n)),
                             type=e.type)
        if name == "inverse":  # WGSL has none: a helper function (helpers())
            if types[0] not in INVERSE_HELPERS:
                raise unsupported(f"inverse of a {types[0]}", e)
            return Native(INVERSE_HELPERS[types[0]], list(args), type=e.type)
        if name == "dFdy":  # GL's window y runs up, WebGPU's framebuffer y down
            return ir.Unary("-", Native("dpdy", list(args), type=e.type), type=e.type)
        if name == "not":
            return ir.Unary("!", args[0], type=e.type)
        if name in BITCASTS:  # the bits of one scalar kind as another's
            t = vector_of(BITCASTS[name], size_of(types[0]))
            return Native(f"bitcast<{wgsl_type(t)}>", list(args), type=t)
        if name == "matrixCompMult":  # column by column
            n = int(e.type[3])
            index = [ir.Literal(i, None, type="int") for i in range(n)]
            columns = [ir.Binary("*", ir.Index(args[0], index[i], type=f"vec{n}"), ir.Index(args[1], index[i], type=f"vec{n}"),
                                 type=f"vec{n}") for i in range(n)]
            return Native(wgsl_type(e.type), columns, type=e.type)
        if name == "textureQueryLevels":
            if type(args[0]) is not ir.Name:
                raise unsupported("textureQueryLevels of a texture that is not a name", e)
            return Native("i32", [Native("textureNumLevels", [args[0]], type="uint")], type="int")
        if name in TEXTURE_CALLS:
            return self.texture_call(e)
        if name == "textureQueryLod":
            raise unsupported("textureQueryLod (WGSL has no query of the level of detail)", e)
        wgsl = IR_RENAMED.get((name, len(args)), IR_RENAMED.get(name, name))
        if name in COMPONENTWISE:
            if name == "mix" and types[2] is not None and scalar_of(types[2]) == "bool":
                return Native("select", list(args), type=e.type)
            common = self.common(types, e.type)
            return Native(wgsl, [self.converted(a, common) for a in args], type=e.type)
        return Native(wgsl, list(args), type=e.type)

    @staticmethod
    def common(types, result):
        """The type GLSL computes a component-wise built-in in: the widest argument, float if any."""
        if any(t is None for t in types):
            return None
        if any(is_matrix(t) for t in types):
            return next(t for t in types if is_matrix(t))
        scalar = "float" if any(scalar_of(t) == "float" for t in types) else scalar_of(types[0])
        return vector_of(scalar, max(size_of(t) for t in types))

    def texture_call(self, e: ir.Call):
        texture, rest = e.args[0], list(e.args[1:])
        if texture.type != "sampler2D" or type(texture) is not ir.Name:
            raise unsupported(f"{e.name} of a {texture.type}", e)
        sampler = self.spelled(texture) + "_sampler"
        if e.name == "textureSize":
            return Native("vec2i", [Native("textureDimensions", [texture, *rest], type="uvec2")], type="ivec2")
        if e.name == "texelFetch":
            return Native("textureLoad", [texture, *rest], type="vec4")
        if e.name == "textureLod":
            rest[1] = self.converted(rest[1], "float")
        return Native(TEXTURE_CALLS[e.name], [texture, sampler, *rest], type="vec4")

    def call(self, e: ir.Call, column, indent) -> str:
        f = e.callee
        if f is None:
            raise unsupported(f"a call of '{e.name}', which is not resolved", e)
        args = []
        for p, a in zip(f.params, e.args):
            if p.type == "sampler2D":
                if type(a) is not ir.Name:
                    raise unsupported("a texture argument that is not a name", a)
                args.append(a)
                args.append(self.spelled(a) + "_sampler")
            elif p.qualifier == "in":
                args.append(self.converted(a, p.type))
            elif self.is_pointer(a):
                args.append(self.spelled(a))
            elif type(a) is ir.Name:
                args.append("&" + self.spelled(a))
            else:  # a member or element goes through a copy (see _Writer)
                temporary = f"written_{self.temporaries}"
                self.temporaries += 1
                target = self.render(a, None, 0)
                self.before.append(f"var {temporary}: {wgsl_type(p.type)} = {target};")
                self.after.append(f"{target} = {temporary};")
                args.append("&" + temporary)
        return self.call_text(self.printer.function_names.get(f.key, f.name), args, column, indent)

    # -- statements --------------------------------------------------------------------------------
    def statements(self, stmts, depth: int, lines: list[str]) -> None:
        for s in resolve_sections(stmts, self.printer.defined):
            self.statement(s, depth, lines)

    def statement(self, s, depth: int, lines: list[str]) -> None:
        cls = type(s)
        pad = INDENT * depth
        if cls is ir.Comment:
            lines.extend(pad + line for line in comment_lines(s.lines))
        elif cls is ir.Block:
            if s.scoped:
                lines.append(with_trailing(pad + "{", s.comment))
                self.statements(s.body, depth + 1, lines)
                lines.append(pad + "}")
            else:
                self.statements(s.body, depth, lines)
        elif cls is ir.If:
            self.if_chain(s, depth, lines, "")
        elif cls is ir.For:
            init = self.simple(s.init, None, 0) if s.init is not None else ""
            condition = self.render(s.condition, None, 0) if s.condition is not None else ""
            update = self.simple(s.update, None, 0) if s.update is not None else ""
            self.header_done(s)
            self.braced(f"{pad}for ({init}; {condition}; {update})", s.body, depth, lines, s.comment)
        elif cls is ir.While:
            condition = self.render(s.condition, None, 0)
            self.header_done(s)
            self.braced(f"{pad}while ({condition})", s.body, depth, lines, s.comment)
        elif cls is ir.Assign and s.op != "=" and s.value is None:
            self.flush(with_trailing(pad + self.step(s) + ";", s.comment), depth, lines)
        elif cls is ir.Assign and type(s.target) is ir.Field and s.target.swizzle and len(s.target.name) > 1:
            self.swizzle_assign(s, depth, lines)
        elif cls is ir.Return and s.value is not None:
            value = self.render(self.converted(s.value, self.returns), len(pad) + 7, len(pad))
            if self.after:  # the copies back happen before the function returns
                self.flush(f"{pad}let returned = {value};", depth, lines, keep_after=True)
                lines.extend(pad + line for line in self.after)
                self.after.clear()
                lines.append(with_trailing(pad + "return returned;", s.comment))
            else:
                self.flush(with_trailing(f"{pad}return {value};", s.comment), depth, lines)
        else:
            self.flush(with_trailing(pad + self.simple(s, len(pad), len(pad)) + ";", s.comment), depth, lines)

    def flush(self, text: str, depth: int, lines: list[str], keep_after: bool = False) -> None:
        """A statement's text with the copies it needs before and after it."""
        pad = INDENT * depth
        lines.extend(pad + line for line in self.before)
        self.before.clear()
        lines.extend(text.split("\n"))
        if not keep_after:
            lines.extend(pad + line for line in self.after)
            self.after.clear()

    def header_done(self, s) -> None:
        if self.before or self.after:
            raise unsupported("an out argument of a member or element in a loop's header", s)

    def step(self, s: ir.Assign) -> str:
        """`i++`: WGSL increments integers only; a float steps by `+= 1.0`."""
        target = self.render(s.target, None, 0)
        if s.target.type is not None and scalar_of(s.target.type) == "float":
            return f"{target} {s.op[0]}= 1.0"
        return target + s.op

    def simple(self, s, column, indent) -> str:
        cls = type(s)
        if cls is ir.Declare:
            ir_type = self.printer.sized(s.type, s.init)
            # a local nothing assigns is a `let` (an array stays a variable: indexed at run time,
            # a value would be copied)
            constant = s.const or (self.assigned is not None and s.name not in self.assigned)
            keyword = "let" if constant and s.init is not None and not is_array(ir_type) else "var"
            head = f"{keyword} {self.spelled(ir.Name(s.name, 'local'))}: {wgsl_type(ir_type)}"
            if s.init is None:
                return head
            at = None if column is None else column + len(head) + 3
            return head + " = " + self.render(self.converted(s.init, ir_type), at, indent)
        if cls is ir.Assign:
            if s.value is None:
                return self.step(s)
            target = self.render(s.target, column, indent)
            value = s.value
            if s.op == "=":
                value = self.converted(value, s.target.type)
            elif s.op in ("<<=", ">>=") and value.type and scalar_of(value.type) == "int" and type(value) is not ir.Literal:
                value = self.conversion(value, vector_of("uint", size_of(value.type)))  # shifts by u32 only
            at = None if column is None else end_column(column, target) + len(s.op) + 2
            return f"{target} {s.op} {self.render(value, at, indent)}"
        if cls is ir.ExprStatement:
            e = s.expr
            text = self.render(e, None if column is None else column + 4, indent)
            void = e.type == "void" or (type(e) is ir.Call and e.callee is not None and e.callee.returns == "void")
            return text if void else "_ = " + text
        if cls is ir.Return:
            return "return"
        if cls is ir.Break:
            return "break"
        if cls is ir.Continue:
            return "continue"
        if cls is ir.Discard:
            return "discard"
        raise unsupported(f"a {cls.__name__} statement", s)

    def swizzle_assign(self, s: ir.Assign, depth: int, lines: list[str]) -> None:
        """`v.xy = e`: WGSL writes one component at a time, from `e` evaluated once."""
        pad = INDENT * depth
        target = s.target
        if any(type(n) is ir.Call for n in ir.walk(target.base)):
            raise unsupported("a write to several components of a vector computed by a call", s)
        value = s.value
        if type(value) not in (ir.Name, ir.Literal):
            temporary = f"swizzled_{self.temporaries}"
            self.temporaries += 1
            self.flush(f"{pad}let {temporary} = {self.render(value, len(pad) + len(temporary) + 7, len(pad))};",
                       depth, lines)
            value = ir.Name(temporary, "local", type=value.type)
        base = self.operand(target.base, None, 0, self.klass(target.base) != PRIMARY)
        spread = value.type is not None and size_of(value.type) > 1
        rendered = self.operand(value, None, 0, self.klass(value) != PRIMARY)
        for i, component in enumerate(target.name):
            source = f"{rendered}.{'xyzw'[i]}" if spread else rendered
            lines.append(f"{pad}{base}.{component} {s.op} {source};")
        if s.comment:
            lines[-1] = with_trailing(lines[-1], s.comment)

    def braced(self, opener: str, body, depth: int, lines: list[str], comment=None) -> None:
        """`opener {`, the body, `}`; a brace-less body of one line in the source stays one line.
        `comment`: the opener's own, after the source's `)` or `else`."""
        inner: list[str] = []
        self.statements(body.body if type(body) is ir.Block else [body], depth + 1, inner)
        if type(body) is ir.Block and not body.scoped and len(inner) == 1 and "//" not in inner[0] \
                and len(opener) + len(inner[0].strip()) + 6 <= WIDTH:
            lines.append(with_trailing(f"{opener} {{ {inner[0].strip()} }}", comment))
            return
        lines.append(with_trailing(opener + " {", comment or (body.comment if type(body) is ir.Block else None)))
        lines.extend(inner)
        lines.append(INDENT * depth + "}")

    def if_chain(self, s: ir.If, depth: int, lines: list[str], prefix: str) -> None:
        pad = INDENT * depth
        condition = self.render(s.condition, len(pad) + len(prefix) + 4, len(pad))
        if self.after or (prefix and self.before):
            raise unsupported("an out argument of a member or element in an if's condition", s)
        lines.extend(pad + line for line in self.before)
        self.before.clear()
        self.braced(f"{pad}{prefix}if ({condition})", s.then, depth, lines, s.comment)
        if s.other is None:
            return
        defined = self.printer.defined
        other = else_chain(else_parts(s.other, defined), defined)
        if other is None:
            return
        if type(other) is ir.If:
            self.if_chain(other, depth, lines, "else ")
        else:
            self.braced(f"{pad}else", other, depth, lines)
