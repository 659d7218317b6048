"""Typed IR (code/ir.py) printed as GLSL 4.00 or ESSL 3.00.

The IR keeps no parentheses: they come from GLSL's precedence and associativity, only where the
grammar needs them (and around a negated negation, which `--` would misread). Blocks without
braces in the source stay without; comments stay where they were; sections of macros still in the
IR are written as `#ifdef/#ifndef ... #else ... #endif`. Conversions the checker made explicit
where the source relied on an implicit one are left implicit in GLSL 4.00; ESSL 3.00 converts
nothing implicitly, so there a conversion between scalar kinds is written. Long argument lists
wrap at 110 columns (targets/printing.py).
"""
from ...code import ir
from ...code.types import array_element, is_array, scalar_of
from ...errors import ShaderGenError
from ..printing import HANGING, INDENT, WIDTH, arguments, binary_text, comment_lines, end_column, with_trailing
from . import _float

# Binary operators' precedence, GLSL 4.00 section 5.1 (higher binds tighter); all left-associative.
BINARY = {"||": 2, "&&": 4, "|": 5, "^": 6, "&": 7, "==": 8, "!=": 8, "<": 9, ">": 9, "<=": 9, ">=": 9,
          "<<": 10, ">>": 10, "+": 11, "-": 11, "*": 12, "/": 12, "%": 12}
SELECT, UNARY, PRIMARY = 1, 13, 15
BITWISE, SHIFTS, ARITHMETIC = frozenset("&|^"), frozenset({"<<", ">>"}), frozenset("+-*/%")

DIALECTS = ("glsl", "essl")
# a value's constructor node -> its text on one line, in every printer that prints with `line`
# (numbers are spelled alike in GLSL and ESSL); at most MAX_VALUE_LINES, then printed each time
VALUE_LINES: dict = {}
MAX_VALUE_LINES = 8192
# the methods whose rules `GlslPrinter.line` inlines
ONE_LINE_RULES = ("render", "operand", "call")


def literal_text(node: ir.Literal) -> str:
    """A literal as the source spelled it, else as the GLSL targets spell values."""
    if node.text is not None:
        return node.text
    value = node.value
    if isinstance(value, bool) or node.type == "bool":
        return "true" if value else "false"
    if node.type == "uint":
        return f"{int(value)}u"
    if node.type == "int" or (node.type is None and isinstance(value, int)):
        return str(int(value))
    return _float(value)


def unsupported(what: str, node) -> ShaderGenError:
    where = node.where
    return ShaderGenError("unsupported_node", f"cannot print {what}",
                          None if where is None else f"{where[0]}:{where[1]}:{where[2]}")


def same(a, b) -> bool:
    """The same IR, field by field (`where`, types and comments aside)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, ir.Node):
        return all(same(getattr(a, n), getattr(b, n)) for n in a.FIELDS)
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b


def else_links(side: list) -> list:
    """The else clauses of a section's side in chain order: the clause, then each `else` of the
    `if ... else if ...` it starts."""
    links = list(side[:1])
    while links:
        last = links[-1]
        if last.scoped or len(last.body) != 1 or type(last.body[0]) is not ir.If or last.body[0].other is None:
            break
        links.append(last.body[0].other)
    return links


def cut_chain(clause: ir.Block, keep: int) -> ir.Block:
    """`clause` with its else chain ending after `keep` links."""
    node = clause.body[0]
    other = None if keep == 1 else cut_chain(node.other, keep - 1)
    return ir.replace(clause, body=[ir.replace(node, other=other)])


def split_else_section(section: ir.Section):
    """A section holding an `else` (ir.Section else_branch) as the source wrote it: the parser
    carries what follows its `#endif` into both of its sides; here that shared rest comes out
    again, to be printed once after the `#endif` (None where the sides share none)."""
    body, other = else_links(section.body), else_links(section.other or [])
    for i in range(1, len(body)):
        for j, link in enumerate(other):
            if same(body[i], link):
                kept_other = [] if j == 0 else [cut_chain(section.other[0], j)]
                return ir.replace(section, body=[cut_chain(section.body[0], i)], other=kept_other), body[i]
    return section, None


class GlslPrinter:
    """`item`, `statements` and `expression` of typed IR as GLSL text; `spell(name_node)` decides
    how a Name is written (the stage assembler's vertex data `vd.x` against `vd_x`)."""
    __slots__ = ("dialect", "spell", "convert_implicit", "one_line", "shared")

    def __init__(self, dialect: str = "glsl", spell=None):
        if dialect not in DIALECTS:
            raise ValueError(f"dialect {dialect!r}: one of {DIALECTS}")
        self.dialect = dialect
        self.spell = spell
        self.shared = None  # while generated code is printed: (id -> shared statement's Entry, the target's key)
        self.convert_implicit = dialect == "essl"  # ESSL 3.00 has no implicit conversions
        # `line` prints what `render` prints on one line, in fewer calls; a printer that changes
        # how an expression is rendered (OSL's, the C family's) renders every part itself
        cls = type(self)
        self.one_line = all(getattr(cls, m) is getattr(GlslPrinter, m) for m in ONE_LINE_RULES)

    # -- expressions -------------------------------------------------------------------------------
    def expression(self, expr: ir.Expr) -> str:
        return self.render(expr, None, 0)

    def precedence(self, e) -> int:
        cls = type(e)
        if cls is ir.Binary:
            return BINARY[e.op]
        if cls is ir.Select:
            return SELECT
        if cls is ir.Unary:
            return UNARY
        if cls is ir.Literal:
            return UNARY if literal_text(e).startswith("-") else PRIMARY
        if cls is ir.Convert and not self.written(e):
            return self.precedence(e.operand)
        return PRIMARY

    def written(self, e: ir.Convert) -> bool:
        """Whether a conversion is written: an explicit one always; an implicit one in ESSL where
        it changes the scalar kind (a scalar spread over a vector is GLSL's own rule)."""
        if not e.implicit:
            return True
        if not self.convert_implicit:
            return False
        operand = e.operand.type
        return operand is not None and scalar_of(operand) != scalar_of(e.type)

    def line(self, e) -> str:
        """`render(e, None, indent)`: `e` on one line (what every statement of main is, printed in
        every request: render's rules for column None, inlined)."""
        cls = type(e)
        if cls is ir.Name:
            return self.spell(e) if self.spell is not None else e.name
        if cls is ir.Literal:
            return literal_text(e)
        if cls is ir.Call:
            return e.name + "(" + ", ".join([self.line(a) for a in self.call_arguments(e)]) + ")"
        if cls is ir.Binary:
            p = BINARY[e.op]
            left, right = self.line(e.left), self.line(e.right)
            if self.precedence(e.left) < p or (type(e.left) is not ir.Literal and self.mixed(e, e.left)):
                left = "(" + left + ")"
            if self.precedence(e.right) <= p or self.mixed(e, e.right):
                right = "(" + right + ")"
            return left + " " + e.op + " " + right
        if cls is ir.Construct:
            if e.exact:
                return self.value_line(e)
            return e.type + "(" + ", ".join([self.line(a) for a in e.args]) + ")"
        if cls is ir.Field:
            base = self.line(e.base)
            return ("(" + base + ")" if self.precedence(e.base) < PRIMARY else base) + "." + e.name
        if cls is ir.Unary:
            operand = self.line(e.operand)
            return e.op + ("(" + operand + ")" if self.precedence(e.operand) <= UNARY else operand)
        if cls is ir.Index:
            base = self.line(e.base)
            return ("(" + base + ")" if self.precedence(e.base) < PRIMARY else base) + "[" + self.line(e.index) + "]"
        if cls is ir.Select:
            condition, if_true = self.line(e.condition), self.line(e.if_true)
            if self.precedence(e.condition) <= SELECT or type(e.condition) is ir.Binary:
                condition = "(" + condition + ")"
            if type(e.if_true) is ir.Select:
                if_true = "(" + if_true + ")"
            return condition + " ? " + if_true + " : " + self.line(e.if_false)
        if cls is ir.Convert:
            if not self.written(e):
                return self.line(e.operand)
            if type(e.operand) is ir.Literal and e.type == "float" and isinstance(e.operand.value, int):
                return _float(float(e.operand.value))
            return e.type + "(" + self.line(e.operand) + ")"
        raise unsupported(f"a {cls.__name__} expression", e)

    def value_line(self, e: ir.Construct) -> str:
        """A value's constructor (code/values.py: numbers only) on one line. Equal values are one
        node, shared by every use and never changed (passes build new nodes), so the text is kept
        per node: most of a main's literals are in them, printed again in every request."""
        text = VALUE_LINES.get(e)
        if text is None:
            text = e.type + "(" + ", ".join([self.line(a) for a in e.args]) + ")"
            if len(VALUE_LINES) < MAX_VALUE_LINES:
                VALUE_LINES[e] = text  # (the key holds the node: its id is not reused)
        return text

    def render(self, e, column, indent) -> str:
        """`e` as text starting at `column` (None: on one line), wrapping long argument lists."""
        if column is None and self.one_line:
            return self.line(e)
        cls = type(e)
        if cls is ir.Name:
            return self.spell(e) if self.spell is not None else e.name
        if cls is ir.Literal:
            return literal_text(e)
        if column is not None:
            flat = self.line(e) if self.one_line else self.render(e, None, indent)
            if column + len(flat) <= WIDTH:
                return flat
        if cls is ir.Binary:
            p = BINARY[e.op]
            left = self.precedence(e.left) < p or (type(e.left) is not ir.Literal and self.mixed(e, e.left))
            right = self.precedence(e.right) <= p or self.mixed(e, e.right)
            if column is None:  # (the common case, without the wrapping's closures)
                return f"{self.operand(e.left, None, indent, left)} {e.op} {self.operand(e.right, None, indent, right)}"
            return binary_text(lambda at, indent: self.operand(e.left, at, indent, left), e.op,
                               lambda at, indent: self.operand(e.right, at, indent, right), column, indent)
        if cls is ir.Unary:
            inner = self.precedence(e.operand) <= UNARY  # also `-(-x)`: `--x` is a decrement
            return e.op + self.operand(e.operand, None if column is None else column + len(e.op), indent, inner)
        if cls is ir.Call:
            return self.call(e.name, self.call_arguments(e), column, indent)
        if cls is ir.Construct:
            return self.call(e.type, e.args, column, indent)  # IR types are GLSL's spellings
        if cls is ir.Field:
            return self.operand(e.base, column, indent, self.precedence(e.base) < PRIMARY) + "." + e.name
        if cls is ir.Index:
            base = self.operand(e.base, column, indent, self.precedence(e.base) < PRIMARY)
            at = None if column is None else end_column(column, base) + 1
            return f"{base}[{self.render(e.index, at, indent)}]"
        if cls is ir.Select:
            # a comparison as the condition in parentheses, as the sources write it
            condition = self.operand(e.condition, column, indent, self.precedence(e.condition) <= SELECT or
                                     type(e.condition) is ir.Binary)
            at = None if column is None else end_column(column, condition) + 3
            if_true = self.operand(e.if_true, at, indent, type(e.if_true) is ir.Select)
            at = None if column is None else end_column(at, if_true) + 3
            if_false = self.render(e.if_false, at, indent)
            if column is not None and "\n" not in if_true + if_false and at + len(if_false) > WIDTH:
                # too long: the other branch on a line of its own, its `:` under the `?`
                question = end_column(column, condition) + 1
                if question <= HANGING and question + 2 + len(if_false) <= WIDTH:
                    return f"{condition} ? {if_true}\n{' ' * question}: {if_false}"
            return f"{condition} ? {if_true} : {if_false}"
        if cls is ir.Convert:
            if not self.written(e):
                return self.render(e.operand, column, indent)
            if type(e.operand) is ir.Literal and e.type == "float" and isinstance(e.operand.value, int):
                return _float(float(e.operand.value))
            return self.call(e.type, [e.operand], column, indent)
        raise unsupported(f"a {cls.__name__} expression", e)

    @staticmethod
    def mixed(parent: ir.Binary, child) -> bool:
        """Parentheses the grammar does without but a reader wants (the sources write them; C
        compilers warn without them): `a || (b && c)`; a shift or arithmetic inside a bitwise
        operator, arithmetic inside a shift (`(x << k) | (x >> (32u - k))`); a negative literal
        after an operator (`a - (-0.5)`)."""
        if type(child) is ir.Literal:
            return literal_text(child).startswith("-")
        if type(child) is not ir.Binary:
            return False
        if parent.op == "||":
            return child.op == "&&"
        if parent.op in BITWISE:
            return child.op in SHIFTS or child.op in ARITHMETIC
        return parent.op in SHIFTS and child.op in ARITHMETIC

    def operand(self, e, column, indent, parenthesised: bool) -> str:
        if not parenthesised:
            return self.render(e, column, indent)
        return "(" + self.render(e, None if column is None else column + 1, indent) + ")"

    def call_arguments(self, e: ir.Call) -> list:
        """A call's arguments as written (Vulkan's printer passes a texture with its sampler)."""
        return e.args

    def call(self, name: str, args, column, indent) -> str:
        if column is None:
            return name + "(" + ", ".join([self.render(a, None, indent) for a in args]) + ")"
        return name + "(" + arguments(self.render, args, column + len(name) + 1, indent) + ")"

    # -- statements --------------------------------------------------------------------------------
    def statements(self, stmts, depth: int) -> list[str]:
        lines: list[str] = []
        self.statements_into(stmts, depth, lines)
        return lines

    def statement(self, s, depth: int, lines: list[str]) -> None:
        """`s`'s lines, at `depth`; a statement of generated code shared across requests
        (code/statements.py) is printed once per target and depth."""
        shared = self.shared
        entry = shared[0].get(id(s)) if shared is not None else None
        if entry is None:
            return self._statement(s, depth, lines)
        key = (shared[1], depth)
        found = entry.lines.get(key)
        if found is None:
            own: list[str] = []
            self._statement(s, depth, own)
            found = entry.lines[key] = tuple(own)
        lines.extend(found)

    def _statement(self, s, depth: int, lines: list[str]) -> None:
        cls = type(s)
        pad = INDENT * depth
        if cls is ir.Comment:
            lines.extend(pad + line for line in comment_lines(s.lines))
        elif cls is ir.Section:
            self.section(s, lambda body: self.statements(body, depth), lines)
        elif cls is ir.Block:
            if s.scoped:
                lines.append(with_trailing(pad + "{", s.comment))
                self.statements_into(s.body, depth + 1, lines)
                lines.append(pad + "}")
            else:
                self.statements_into(s.body, depth, lines)
        elif cls is ir.If:
            self.if_chain(s, depth, lines, "")
        elif cls is ir.For:
            head = f"for ({self.simple(s.init, None, 0) if s.init else ''}; "
            head += (self.render(s.condition, None, 0) if s.condition is not None else "") + "; "
            head += (self.simple(s.update, None, 0) if s.update else "") + ")"
            lines.append(with_trailing(pad + head, s.comment))
            self.body(s.body, depth, lines)
        elif cls is ir.While:
            lines.append(with_trailing(pad + f"while ({self.render(s.condition, None, 0)})", s.comment))
            self.body(s.body, depth, lines)
        else:
            text = self.simple(s, len(pad), len(pad))
            if s.comment is None and "\n" not in text:  # most statements: one line, no comment
                lines.append(pad + text + ";")
            else:
                lines.extend(with_trailing(pad + text + ";", s.comment).split("\n"))

    def statements_into(self, stmts, depth: int, lines: list[str]) -> None:
        for s in stmts:
            self.statement(s, depth, lines)

    def simple(self, s, column, indent) -> str:
        """A statement that is one line of code (without its `;`): also a for loop's parts."""
        cls = type(s)
        if cls is ir.Declare:
            name = s.name if self.spell is None else self.spell(ir.Name(s.name, "local"))
            head = ("const " if s.const else "") + self.declarator(s.type, name)
            if s.init is None:
                return head
            return head + " = " + self.render(s.init, None if column is None else column + len(head) + 3, indent)
        if cls is ir.Assign:
            target = self.render(s.target, column, indent)
            if s.value is None:
                return target + s.op
            at = None if column is None else end_column(column, target) + len(s.op) + 2
            return f"{target} {s.op} {self.render(s.value, at, indent)}"
        if cls is ir.ExprStatement:
            return self.render(s.expr, column, indent)
        if cls is ir.Return:
            if s.value is None:
                return "return"
            return "return " + self.render(s.value, None if column is None else column + 7, indent)
        if cls is ir.Break:
            return "break"
        if cls is ir.Continue:
            return "continue"
        if cls is ir.Discard:
            return "discard"
        raise unsupported(f"a {cls.__name__} statement", s)

    def declarator(self, ir_type: str, name: str) -> str:
        """`T name`, an array `T name[N]` as the library sources write it."""
        if is_array(ir_type):  # the size as written: a number, or a constant's name before checking
            return f"{array_element(ir_type)} {name}{ir_type[ir_type.rindex('['):]}"
        return f"{ir_type} {name}"

    def body(self, block, depth: int, lines: list[str]) -> None:
        """The body of an if, else or loop: braced where the source braced it."""
        if type(block) is ir.Block and not block.scoped and len(block.body) == 1 \
                and type(block.body[0]) not in (ir.Section, ir.Comment):
            self.statement(block.body[0], depth + 1, lines)
        elif type(block) is ir.Block and block.scoped:
            self.statement(block, depth, lines)
        else:  # several statements grouped without braces (generated code): braced
            lines.append(INDENT * depth + "{")
            self.statements_into(block.body if type(block) is ir.Block else [block], depth + 1, lines)
            lines.append(INDENT * depth + "}")

    def if_chain(self, s: ir.If, depth: int, lines: list[str], prefix: str) -> None:
        pad = INDENT * depth
        lines.append(with_trailing(f"{pad}{prefix}if ({self.render(s.condition, None, 0)})", s.comment))
        self.body(s.then, depth, lines)
        if s.other is not None:
            self.else_branch(s.other, depth, lines)

    def else_branch(self, other, depth: int, lines: list[str]) -> None:
        """`else` and what follows it: `else if`, a block, or sections of else branches
        (`#ifdef X else {...} #endif`, ir.Section)."""
        pad = INDENT * depth
        inner = other.body if type(other) is ir.Block and not other.scoped else None
        if inner is not None and len(inner) == 1 and type(inner[0]) is ir.If:
            self.if_chain(inner[0], depth, lines, "else ")
        elif inner is not None and len(inner) == 1 and type(inner[0]) is ir.Section:
            section, rest = split_else_section(inner[0])
            self.section(section, lambda body: self.else_parts(body, depth), lines)
            if rest is not None:
                self.else_branch(rest, depth, lines)
        else:
            comment = other.comment if type(other) is ir.Block else None
            lines.append(with_trailing(pad + "else", comment))
            if type(other) is ir.Block and other.scoped:
                lines.append(pad + "{")
                self.statements_into(other.body, depth + 1, lines)
                lines.append(pad + "}")
            else:
                self.body(other, depth, lines)

    def else_parts(self, body, depth: int) -> list[str]:
        lines: list[str] = []
        for part in body:
            if type(part) is ir.Comment:
                self.statement(part, depth, lines)
            else:
                self.else_branch(part if type(part) is ir.Block else ir.Block([part], False), depth, lines)
        return lines

    def section(self, s: ir.Section, body_lines, lines: list[str]) -> None:
        lines.append(("#ifdef " if s.defined else "#ifndef ") + s.macro)
        lines.extend(body_lines(s.body))
        if s.other:
            lines.append("#else")
            lines.extend(body_lines(s.other))
        lines.append("#endif")

    # -- items -------------------------------------------------------------------------------------
    def item(self, item) -> list[str]:
        cls = type(item)
        lines = comment_lines(item.comment) if getattr(item, "comment", None) and cls is not ir.Comment else []
        if cls is ir.Function:
            lines.extend(self.signature(item).split("\n"))
            lines.append("{")
            self.statements_into(item.body.body if type(item.body) is ir.Block else item.body, 1, lines)
            lines.append("}")
        elif cls is ir.Struct:
            lines.append(f"struct {item.name}")
            lines.append("{")
            lines.extend(f"{INDENT}{self.declarator(t, n)};" for t, n in item.members)
            lines.append("};")
        elif cls is ir.Constant and item.type is None:  # a #define the checker has not typed
            lines.append(f"#define {item.name} {self.render(item.value, None, 0)}")
        elif cls is ir.Constant:
            head = self.constant_qualifier(item) + self.declarator(item.type, item.name) + " = "
            lines.extend((head + self.render(item.value, len(head), 0) + ";").split("\n"))
        elif cls is ir.Global:
            if item.kind != "builtin":  # the target's own variable: nothing to declare
                lines.extend(self.global_declaration(item).split("\n"))
        elif cls is ir.Section:
            self.section(item, lambda body: [line for x in body for line in self.item(x)], lines)
        elif cls is ir.Comment:
            lines.extend(comment_lines(item.lines))
        else:
            raise unsupported(f"a {cls.__name__} item", item)
        return lines

    def constant_qualifier(self, item: ir.Constant) -> str:
        """What a module-scope constant is declared with (a target may declare some otherwise)."""
        return "const "

    def signature(self, f: ir.Function) -> str:
        head = f"{f.returns} {f.name}("
        params = [text for p in f.params for text in self.parameters(p)]
        return head + arguments(lambda text, column, indent: text, params, len(head), 0) + ")"

    def parameters(self, p: ir.Param) -> list[str]:
        """The declarations one IR parameter is written as (Vulkan's texture: two)."""
        return [self.parameter(p)]

    def parameter(self, p: ir.Param) -> str:
        qualifier = "" if p.qualifier == "in" else p.qualifier + " "
        name = p.name if self.spell is None else self.spell(ir.Name(p.name, "param"))
        return ("const " if p.const else "") + qualifier + self.declarator(p.type, name)

    def global_declaration(self, g: ir.Global) -> str:
        """A uniform, stage input or output, or a library global. (A variable of a block is
        declared by the stage assembler inside its block: here it is the member line.)"""
        declared = self.declarator(g.type, g.name)
        if g.block is not None:
            return declared + ";"
        qualifier = {"uniform": "uniform ", "input": "in ", "output": "out ", "vertexdata": ""}.get(g.kind, "")
        text = qualifier + declared
        if g.init is not None and (g.kind != "uniform" or self.dialect == "glsl"):
            text += " = " + self.render(g.init, len(text) + 3, 0)
        return text + ";"
