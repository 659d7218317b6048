"""GLSL subset -> WGSL, for the node libraries' function files and inline expressions.

Approach: a small typed translator (tokens -> syntax tree -> WGSL), not text substitution. WGSL
differs from GLSL in ways only types can settle: no implicit int -> float conversion, no scalar
arguments to vector built-ins (`clamp(v, 0.0, 1.0)`), pointers instead of `out` parameters,
immutable parameters, no overloading, braces around every branch. So every expression is emitted
with its GLSL type, and the emitter converts where GLSL would have converted implicitly.
What it cannot take (swizzle writes, unknown built-ins) raises Untranslatable with the reason; the
generator reports that as a generation error of the node. Comments go along: those on a line of
their own above the statement or definition that follows them, those after code at the end of the
line WGSL writes for that code (inside an expression they are dropped).
"""
import re
from dataclasses import dataclass, field

from ...errors import ShaderGenError
from .builtins import BUILTIN_RETURN, COMPONENTWISE, INVERSE_HELPERS, RENAMED, TEXTURE_CALLS, WGSL_RESERVED, WGSL_TYPES


class Untranslatable(ShaderGenError):
    """GLSL the translator does not take: a generation error of the node that needs it."""

    def __init__(self, message: str, where: str | None = None):
        super().__init__("unsupported_node", f"no WGSL translation: {message}", where)


TOKEN = re.compile(r"""
    (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<ws>\s+)
  | (?P<pp>\#[^\n]*)
  | (?P<num>0[xX][0-9a-fA-F]+u?|(\d+\.\d*|\.\d+|\d+)([eE][+-]?\d+)?[fu]?)
  | (?P<id>[A-Za-z_]\w*)
  | (?P<op><<=|>>=|\+\+|--|\+=|-=|\*=|/=|%=|&=|\|=|\^=|==|!=|<=|>=|&&|\|\||<<|>>|[-+*/%<>=!~&|^?:;,.(){}\[\]])
""", re.X | re.S)


def preprocess(text: str, defined: set[str]) -> str:
    """Conditional sections: WGSL takes the GL_ES side (no textureQueryLod); #defines are kept."""
    out, active = [], [True]
    for line in text.split("\n"):
        m = re.match(r"\s*#\s*(ifdef|ifndef|else|endif|define)\b\s*(\w*)", line)
        if not m or m.group(1) == "define":
            if all(active):
                out.append(line)
                if m:
                    defined.add(m.group(2))
            else:
                out.append("")
            continue
        if m.group(1) in ("ifdef", "ifndef"):
            active.append((m.group(2) in defined) == (m.group(1) == "ifdef"))
        elif m.group(1) == "else":
            active[-1] = not active[-1]
        else:
            active.pop()
        out.append("")
    return "\n".join(out)


TRAILING = "//>"  # marks a comment that follows code on its line


def tokenize(text: str) -> list[str]:
    """Tokens, comments among them as `// text` lines (a block comment gives one per line; a
    comment after code on its line starts with TRAILING instead). A top-level comment block that
    a blank line separates from what follows documents the file, not a definition: it is left
    out, as the GLSL targets leave it out (deadcode.py)."""
    out, pos, line_start, depth = [], 0, True, 0
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m:
            raise Untranslatable(f"unexpected character {text[pos]!r}")
        pos = m.end()
        if m.lastgroup == "ws":
            line_start = line_start or "\n" in m.group()
            if depth == 0 and m.group().count("\n") > 1:
                while out and out[-1].startswith("//") and not out[-1].startswith(TRAILING):
                    out.pop()
            continue
        depth += {"{": 1, "}": -1}.get(m.group(), 0)
        if m.lastgroup == "comment":
            body = m.group()[2:-2] if m.group().startswith("/*") else m.group()[2:]
            lines = [ln.strip().lstrip("*").strip() for ln in body.split("\n")]
            prefix = "//" if line_start else TRAILING
            out += [f"{prefix} {ln}".rstrip() for ln in lines if ln]
            continue
        out.append(m.group())
        line_start = False
    return out


# -- syntax tree -----------------------------------------------------------------------------------
@dataclass
class Expr:
    kind: str  # num, id, call, member, index, unary, binary, assign, ternary, postfix
    value: str = ""
    args: list = field(default_factory=list)


BINARY = [("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", ">", "<=", ">="), ("<<", ">>"),
          ("+", "-"), ("*", "/", "%")]
ASSIGN = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="}
GLSL_TYPES = {"void", "float", "int", "uint", "bool", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4",
              "uvec2", "uvec3", "uvec4",
              "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "sampler2D"}


class Parser:
    def __init__(self, tokens: list[str], structs: set[str]):
        self.t, self.i, self.structs = [], 0, structs
        self.comments: dict[int, list[str]] = {}  # token index -> the comments just before it
        for tok in tokens:
            if tok.startswith("//"):
                self.comments.setdefault(len(self.t), []).append(tok)
            else:
                self.t.append(tok)

    def take_comments(self) -> list:
        """The comments before the next token, as ("comment", text) statements and items."""
        return [("comment", text) for text in self.comments.pop(self.i, [])]

    def peek(self, k=0) -> str:
        return self.t[self.i + k] if self.i + k < len(self.t) else ""

    def next(self) -> str:
        tok = self.peek()
        if not tok:
            raise Untranslatable("unexpected end of source")
        self.i += 1
        return tok

    def expect(self, tok: str) -> None:
        got = self.next()
        if got != tok:
            raise Untranslatable(f"expected '{tok}', found '{got}'")

    def is_type(self, tok: str) -> bool:
        return tok in GLSL_TYPES or tok in self.structs

    # expressions
    def expression(self) -> Expr:
        e = self.assignment()
        if self.peek() == ",":
            raise Untranslatable("comma expressions")
        return e

    def assignment(self) -> Expr:
        left = self.ternary()
        if self.peek() in ASSIGN:
            op = self.next()
            return Expr("assign", op, [left, self.assignment()])
        return left

    def ternary(self) -> Expr:
        cond = self.binary(0)
        if self.peek() == "?":
            self.next()
            a = self.assignment()
            self.expect(":")
            b = self.assignment()
            return Expr("ternary", "", [cond, a, b])
        return cond

    def binary(self, level: int) -> Expr:
        if level == len(BINARY):
            return self.unary()
        left = self.binary(level + 1)
        while self.peek() in BINARY[level]:
            op = self.next()
            left = Expr("binary", op, [left, self.binary(level + 1)])
        return left

    def unary(self) -> Expr:
        if self.peek() in ("-", "+", "!", "~"):
            op = self.next()
            operand = self.unary()
            return operand if op == "+" else Expr("unary", op, [operand])
        if self.peek() in ("++", "--"):  # only as a statement (WGSL's i++), as the emitter checks
            op = self.next()
            return Expr("postfix", op, [self.unary()])
        return self.postfix(self.primary())

    def primary(self) -> Expr:
        tok = self.next()
        if tok == "(":
            e = self.expression()
            self.expect(")")
            return Expr("paren", "", [e])
        if re.match(r"[\d.]", tok):
            return Expr("num", tok)
        if re.match(r"[A-Za-z_]", tok):
            if self.is_type(tok) and self.peek() == "[":  # an array constructor: float[3](a, b, c)
                self.next()
                size = None if self.peek() == "]" else self.expression()
                self.expect("]")
                self.expect("(")
                args = self.arguments()
                return Expr("array", tok, [size or Expr("num", str(len(args))), *args])
            if self.peek() == "(":
                self.next()
                return Expr("call", tok, self.arguments())
            return Expr("id", tok)
        raise Untranslatable(f"unexpected '{tok}'")

    def arguments(self) -> list[Expr]:
        """A call's arguments, after its `(`, up to and including its `)`."""
        args = []
        while self.peek() != ")":
            args.append(self.assignment())
            if self.peek() == ",":
                self.next()
        self.expect(")")
        return args

    def postfix(self, e: Expr) -> Expr:
        while True:
            if self.peek() == ".":
                self.next()
                e = Expr("member", self.next(), [e])
            elif self.peek() == "[":
                self.next()
                index = self.expression()
                self.expect("]")
                e = Expr("index", "", [e, index])
            elif self.peek() in ("++", "--"):
                e = Expr("postfix", self.next(), [e])
            else:
                return e

    # statements: tuples (kind, ...)
    def statement(self):
        tok = self.peek()
        if tok == "{":
            return ("block", self.block())
        if tok == "if":
            self.next()
            self.expect("(")
            cond = self.expression()
            self.expect(")")
            then = self.statement()
            other = None
            if self.peek() == "else":
                self.next()
                other = self.statement()
            return ("if", cond, then, other)
        if tok == "for":
            self.next()
            self.expect("(")
            init = None if self.peek() == ";" else self.simple()
            self.expect(";")
            cond = None if self.peek() == ";" else self.expression()
            self.expect(";")
            step = None if self.peek() == ")" else self.expression()
            self.expect(")")
            return ("for", init, cond, step, self.statement())
        if tok == "while":
            self.next()
            self.expect("(")
            cond = self.expression()
            self.expect(")")
            return ("while", cond, self.statement())
        if tok == "return":
            self.next()
            value = None if self.peek() == ";" else self.expression()
            self.expect(";")
            return ("return", value)
        if tok in ("break", "continue", "discard"):
            self.next()
            self.expect(";")
            return (tok,)
        s = self.simple()
        self.expect(";")
        return s

    def simple(self):
        """A declaration or an expression statement (also a for loop's initialiser)."""
        const = False
        if self.peek() == "const":
            self.next()
            const = True
        if self.is_type(self.peek()) and re.match(r"[A-Za-z_]", self.peek(1)):
            type_name = self.next()
            decls = []
            while True:
                name = self.next()
                size = None
                if self.peek() == "[":
                    self.next()
                    size = self.expression()
                    self.expect("]")
                init = None
                if self.peek() == "=":
                    self.next()
                    init = self.assignment()
                decls.append((name, size, init))
                if self.peek() != ",":
                    break
                self.next()
            return ("decl", const, type_name, decls)
        return ("expr", self.expression())

    def block(self) -> list:
        self.expect("{")
        out = []
        while self.peek() != "}":
            out += self.take_comments()
            out.append(self.statement())
        out += self.take_comments()
        self.expect("}")
        return out

    def top_level(self):
        """Functions, structs, constants and #defines of a library file."""
        items = []
        while self.peek():
            items += self.take_comments()
            tok = self.peek()
            if tok.startswith("#"):
                self.next()
                m = re.match(r"#\s*define\s+(\w+)\s+(.+)$", tok)
                if m and self.is_type(m.group(2).strip()):
                    self.structs.add(m.group(1))
                    items.append(("alias", m.group(1), m.group(2).strip()))
                elif m:
                    items.append(("define", m.group(1), m.group(2).strip()))
                elif not re.match(r"#\s*define\s+\w+\s*$", tok):
                    raise Untranslatable(f"preprocessor line '{tok}'")
                continue
            if tok == "struct":
                self.next()
                name = self.next()
                self.structs.add(name)
                self.expect("{")
                members = []
                while self.peek() != "}":
                    t = self.next()
                    while True:
                        members.append((t, self.next()))
                        if self.peek() != ",":
                            break
                        self.next()
                    self.expect(";")
                self.expect("}")
                self.expect(";")
                items.append(("struct", name, members))
                continue
            if tok == "const" or self.peek(2) in ("=", ";", "["):
                decl = self.simple()
                self.expect(";")
                items.append(("global", decl))
                continue
            ret = self.next()
            name = self.next()
            self.expect("(")
            params = []
            while self.peek() != ")":
                qualifier = "in"
                if self.peek() in ("in", "out", "inout", "const"):
                    qualifier = self.next()
                    qualifier = "in" if qualifier == "const" else qualifier
                params.append((qualifier, self.next(), self.next()))
                if self.peek() == "[":  # an array parameter: `vec3 tint[3]` has type vec3[3]
                    self.next()
                    params[-1] = (qualifier, f"{params[-1][1]}[{self.next()}]", params[-1][2])
                    self.expect("]")
                if self.peek() == ",":
                    self.next()
            self.expect(")")
            if params == [] and self.peek() == ";":
                self.next()
                continue
            if self.peek() == ";":  # a prototype
                self.next()
                continue
            items.append(("function", ret, name, params, self.block()))
        return items + self.take_comments()


# -- types ---------------------------------------------------------------------------------------------
def size_of(t: str) -> int:
    m = re.match(r"[ibu]?vec(\d)$", t)
    return int(m.group(1)) if m else 1


def scalar_of(t: str) -> str:
    if t.startswith("ivec"):
        return "int"
    if t.startswith("bvec"):
        return "bool"
    if t.startswith("uvec"):
        return "uint"
    if t.startswith("vec") or t.startswith("mat"):
        return "float"
    return t


VECTOR_PREFIX = {"float": "vec", "int": "ivec", "uint": "uvec", "bool": "bvec"}


def vector_of(scalar: str, n: int) -> str:
    if n == 1:
        return scalar
    if scalar not in VECTOR_PREFIX:
        raise Untranslatable(f"a swizzle of {scalar}")
    return VECTOR_PREFIX[scalar] + str(n)


def wgsl_type(t: str) -> str:
    return WGSL_TYPES.get(t, t)


def param_type(t: str) -> str:
    """A parameter's WGSL type; a GLSL array parameter `T[N]` is array<T, N>."""
    if t.endswith("]"):
        element, size = t[:-1].split("[")
        return f"array<{wgsl_type(element)}, {size}>"
    return wgsl_type(t)


@dataclass
class Signature:
    name: str  # the WGSL name (suffixed when the GLSL name is overloaded)
    ret: str
    params: list  # (qualifier, type, name)


class Library:
    """What the translated files declare, shared across files: functions by GLSL name (overloads
    each with their WGSL name), structs, constants."""

    def __init__(self):
        self.functions: dict[str, list[Signature]] = {}
        self.structs: dict[str, list[tuple[str, str]]] = {}
        self.globals: dict[str, str] = {}
        self.aliases: dict[str, str] = {}

    def canon(self, t: str) -> str:
        """The type as expressions carry it: aliases resolved, arrays of any size as `T[]`."""
        if t.endswith("]"):
            return self.canon(t[:t.index("[")]) + "[]"
        return self.aliases.get(t, t)

    def resolve(self, name: str, arg_types: list[str]) -> Signature | None:
        family = self.functions.get(name, [])
        for sig in family:
            if [p[1] for p in sig.params] == arg_types:
                return sig
        for sig in family:  # implicit int -> float conversions, as GLSL allows
            if len(sig.params) == len(arg_types) and all(
                    p[1] == a or (scalar_of(p[1]) == "float" and scalar_of(a) == "int" and size_of(p[1]) == size_of(a))
                    for p, a in zip(sig.params, arg_types)):
                return sig
        return None


class FunctionEmitter:
    """Emits one function body; knows the local variables' types and which names are pointers."""

    def __init__(self, lib: Library, params: list, ret: str):
        self.lib, self.ret = lib, lib.canon(ret)
        self.scopes: list[dict[str, str]] = [{}]
        self.pointers: set[str] = set()
        self.lines: list[str] = []
        self.writebacks: list[str] = []  # copies back from out-argument temporaries, after the statement
        self.temporaries = 0
        self.depth = 1
        for q, t, n in params:
            self.scopes[0][n] = lib.canon(t)
            if q in ("out", "inout"):
                self.pointers.add(n)

    def type_of(self, name: str) -> str:
        for scope in reversed(self.scopes):
            if name in scope:
                return scope[name]
        if name in self.lib.globals:
            return self.lib.globals[name]
        if name in FRAGMENT_BUILTINS:
            return FRAGMENT_BUILTINS[name][1]
        raise Untranslatable(f"unknown name '{name}'")

    def line(self, text: str) -> None:
        self.lines.append("    " * self.depth + text)

    def comment(self, text: str) -> None:
        add_comment(self.lines, text, "    " * self.depth)

    # expressions: (wgsl text, glsl type)
    def expr(self, e: Expr) -> tuple[str, str]:
        k = e.kind
        if k == "num":
            if e.value.lower().startswith("0x"):
                return e.value, "uint" if e.value.endswith("u") else "int"
            if e.value.endswith("u"):
                return e.value, "uint"
            text = e.value.rstrip("f")
            return text, "float" if any(c in text for c in ".eE") else "int"
        if k == "paren":
            text, t = self.expr(e.args[0])
            return f"({text})", t
        if k == "id":
            if e.value in ("true", "false"):
                return e.value, "bool"
            t = self.type_of(e.value)
            name = safe_name(e.value)
            return (f"(*{name})" if e.value in self.pointers else name), t
        if k == "member":
            base, t = self.expr(e.args[0])
            if t in self.lib.structs:
                return f"{base}.{safe_name(e.value)}", dict((n, mt) for mt, n in self.lib.structs[t])[e.value]
            if e.value == "length":
                raise Untranslatable("the .length() method")
            return f"{base}.{e.value}", vector_of(scalar_of(t), len(e.value))
        if k == "index":
            base, t = self.expr(e.args[0])
            index, _ = self.expr(e.args[1])
            if t.startswith("mat"):
                element = "vec" + t[3]
            elif t.endswith("[]"):
                element = t[:-2]
            else:
                element = scalar_of(t)
            return f"{base}[{index}]", element
        if k == "unary":
            text, t = self.expr(e.args[0])
            return f"{e.value}{text}", t
        if k == "binary":
            return self.binary(e)
        if k == "ternary":
            cond, _ = self.expr(e.args[0])
            a, ta = self.expr(e.args[1])
            b, tb = self.expr(e.args[2])
            t = self.common([ta, tb])
            a, b = self.convert(a, ta, t), self.convert(b, tb, t)
            if t.startswith("mat"):  # select takes vectors: choose column by column
                if not all(re.fullmatch(r"[\w.]+", x) for x in (a, b)):
                    raise Untranslatable("a choice between matrix expressions")
                columns = ", ".join(f"select({b}[{i}], {a}[{i}], {cond})" for i in range(int(t[3])))
                return f"{wgsl_type(t)}({columns})", t
            return f"select({b}, {a}, {cond})", t
        if k == "call":
            return self.call(e)
        if k == "array":
            size, _ = self.expr(e.args[0])
            items = [self.convert(*self.expr(a), self.lib.canon(e.value)) for a in e.args[1:]]
            return f"array<{wgsl_type(e.value)}, {size}>({', '.join(items)})", self.lib.canon(e.value) + "[]"
        raise Untranslatable(f"{k} inside an expression")

    def binary(self, e: Expr) -> tuple[str, str]:
        a, ta = self.expr(e.args[0])
        b, tb = self.expr(e.args[1])
        op = e.value
        if op in ("&&", "||"):
            return f"{a} {op} {b}", "bool"
        sa, sb = scalar_of(ta), scalar_of(tb)
        if sa != sb and "bool" not in (sa, sb) and op not in ("<<", ">>"):
            # GLSL converts int to uint and both to float
            wider = "float" if "float" in (sa, sb) else "uint"
            if sa != wider:
                a, ta = self.convert(a, ta, vector_of(wider, size_of(ta))), vector_of(wider, size_of(ta))
            else:
                b, tb = self.convert(b, tb, vector_of(wider, size_of(tb))), vector_of(wider, size_of(tb))
        if op in ("==", "!=", "<", ">", "<=", ">="):
            return f"{a} {op} {b}", "bool"
        if ta.startswith("mat") != tb.startswith("mat") and op in ("+", "-", "/"):
            # WGSL has only matrix * scalar: a scalar added to a matrix is added to every element
            m, s = (ta, b) if ta.startswith("mat") else (tb, a)
            if op == "/" and tb == "float":
                return f"{a} * (1.0 / {b})", ta
            splat = f"{wgsl_type(m)}({', '.join([f'vec{m[3]}f({s})'] * int(m[3]))})"
            if op == "/":
                raise Untranslatable("a scalar divided by a matrix")
            return (f"{a} {op} {splat}" if ta.startswith("mat") else f"{splat} {op} {b}"), m
        if ta.startswith("mat") and op == "*":
            t = ta if tb.startswith("mat") or tb == "float" else tb
        elif tb.startswith("mat") and op == "*":
            t = ta if ta.startswith("vec") else tb
        else:
            t = ta if size_of(ta) >= size_of(tb) and not tb.startswith("mat") else tb
        if op == "%" and scalar_of(t) == "float":
            raise Untranslatable("% on floats")
        return f"{a} {op} {b}", t

    def common(self, types: list[str]) -> str:
        """The type GLSL computes component-wise built-ins in: the widest vector, float if any."""
        scalar = "float" if any(scalar_of(t) == "float" for t in types) else scalar_of(types[0])
        if any(t.startswith("mat") for t in types):
            return next(t for t in types if t.startswith("mat"))
        return vector_of(scalar, max(size_of(t) for t in types))

    def convert(self, text: str, t: str, to: str) -> str:
        """A value of GLSL type `t` where `to` is expected: GLSL's implicit conversions, and
        scalars widened to vectors for built-ins WGSL only has in vector form."""
        if t == to:
            return text
        if re.fullmatch(r"\d+", text) and scalar_of(to) in ("float", "uint") and size_of(to) == 1:
            return text + (".0" if scalar_of(to) == "float" else "u")
        if scalar_of(t) == "float" and re.fullmatch(r"[\d.]+([eE][+-]?\d+)?", text) and size_of(to) == 1:
            return text
        return f"{wgsl_type(to)}({text})"

    def call(self, e: Expr) -> tuple[str, str]:
        name = e.value
        if self.lib.canon(name) in GLSL_TYPES or self.lib.canon(name) in self.lib.structs:
            name = self.lib.canon(name)
            return self.construct(name, e.args)
        args = [self.expr(a) for a in e.args]
        sig = self.lib.resolve(name, [t for _, t in args])
        if sig is not None:
            texts = []
            for (q, pt, _), arg, (text, t) in zip(sig.params, e.args, args):
                if pt == "sampler2D":
                    texts.append(f"{text}, {text}_sampler")
                elif q == "in":
                    texts.append(self.convert(text, t, pt))
                elif arg.kind == "id" and arg.value in self.pointers:
                    texts.append(safe_name(arg.value))
                elif arg.kind == "id":
                    texts.append(f"&{text}")
                else:  # a member or element goes through a copy: naga's SPIR-V writer (wgpu 0.32) panics on
                    temp = f"written_{len(self.writebacks) + self.temporaries}"  # a pointer into a composite
                    self.temporaries += 1
                    self.line(f"var {temp}: {wgsl_type(pt)} = {text};")
                    self.writebacks.append(f"{text} = {temp};")
                    texts.append(f"&{temp}")
            return f"{sig.name}({', '.join(texts)})", sig.ret
        if name in self.lib.functions:
            raise Untranslatable(f"no overload of '{name}' takes ({', '.join(t for _, t in args)})")
        return self.builtin(name, args)

    def construct(self, name: str, args: list[Expr]) -> tuple[str, str]:
        values = [self.expr(a) for a in args]
        if size_of(name) == 1 and not name.startswith("mat") and name not in self.lib.structs:
            text, t = values[0]
            return (text if t == name else f"{wgsl_type(name)}({text})"), name
        if name.startswith("mat") and len(values) == 1 and size_of(values[0][1]) == 1 and not values[0][1].startswith("mat"):
            n, s = int(name[3]), self.convert(values[0][0], values[0][1], "float")  # GLSL: the diagonal
            return f"{wgsl_type(name)}({', '.join(s if i % (n + 1) == 0 else '0.0' for i in range(n * n))})", name
        if name.startswith("mat") and len(values) == 1 and values[0][1].startswith("mat") and values[0][1] != name:
            n = int(name[3])
            text = values[0][0]
            if int(values[0][1][3]) < n:
                raise Untranslatable(f"{name} from a smaller matrix")
            cols = ", ".join(f"{text}[{i}].{'xyzw'[:n]}" for i in range(n))
            return f"{wgsl_type(name)}({cols})", name
        scalar = scalar_of(name) if name in GLSL_TYPES else None
        texts = []
        for text, t in values:
            if scalar and scalar_of(t) != scalar and not name.startswith("mat"):
                text = self.convert(text, t, vector_of(scalar, size_of(t)))
            elif scalar == "float" and name.startswith("mat") and scalar_of(t) == "int":
                text = self.convert(text, t, "float")
            texts.append(text)
        return f"{wgsl_type(name)}({', '.join(texts)})", name

    def builtin(self, name: str, args: list[tuple[str, str]]) -> tuple[str, str]:
        types = [t for _, t in args]
        texts = [text for text, _ in args]
        if name == "mod":
            t = self.common(types)
            x, y = (self.convert(text, tt, t) for text, tt in args)
            return f"({x} - {y} * floor({x} / {y}))", t
        if name in ("lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual", "equal", "notEqual"):
            op = {"lessThan": "<", "lessThanEqual": "<=", "greaterThan": ">", "greaterThanEqual": ">=",
                  "equal": "==", "notEqual": "!="}[name]
            return f"({texts[0]} {op} {texts[1]})", vector_of("bool", size_of(types[0]))
        if name in ("isnan", "isinf"):  # by the bits: WGSL may assume no NaN or infinity in arithmetic
            n, (x,) = size_of(types[0]), texts
            bits = f"bitcast<{'u32' if n == 1 else f'vec{n}u'}>({x})"
            mask, inf = ("0x7fffffffu", "0x7f800000u") if n == 1 else (f"vec{n}u(0x7fffffffu)", f"vec{n}u(0x7f800000u)")
            return f"(({bits} & {mask}) {'>' if name == 'isnan' else '=='} {inf})", vector_of("bool", n)
        if name == "inverse":  # WGSL has none: a function of the target's own (builtins.HELPERS)
            if types[0] not in INVERSE_HELPERS:
                raise Untranslatable(f"inverse of a {types[0]}")
            return f"{INVERSE_HELPERS[types[0]]}({texts[0]})", types[0]
        if name == "dFdy":  # GL's window y runs up, WebGPU's framebuffer y down
            return f"(-dpdy({texts[0]}))", types[0]
        if name in TEXTURE_CALLS:
            if args[0][1] != "sampler2D":
                raise Untranslatable(f"{name} of a {args[0][1]}")
            tex = texts[0]
            if name == "textureSize":
                return f"vec2i(textureDimensions({tex}, {texts[1]}))", "ivec2"
            if name == "texelFetch":
                return f"textureLoad({tex}, {texts[1]}, {texts[2]})", "vec4"
            if name == "textureLod":
                lod = self.convert(texts[2], types[2], "float")
                return f"textureSampleLevel({tex}, {tex}_sampler, {texts[1]}, {lod})", "vec4"
            rest = ", ".join(texts[1:])
            return f"{TEXTURE_CALLS[name]}({tex}, {tex}_sampler, {rest})", "vec4"
        if name in COMPONENTWISE:
            t = self.common(types)
            if name == "mix" and scalar_of(types[2]) == "bool":
                return f"select({texts[0]}, {texts[1]}, {texts[2]})", t
            texts = [self.convert(text, tt, t) for text, tt in args]
            wgsl = RENAMED.get((name, len(args)), RENAMED.get(name, name))
            return f"{wgsl}({', '.join(texts)})", t
        if name in BUILTIN_RETURN:
            ret = BUILTIN_RETURN[name](types)
            wgsl = RENAMED.get((name, len(args)), RENAMED.get(name, name))
            if name in ("float", "int", "uint"):
                wgsl = wgsl_type(name)
            return f"{wgsl}({', '.join(texts)})", ret
        raise Untranslatable(f"built-in '{name}' has no WGSL translation")

    # statements
    def statements(self, body: list) -> None:
        for s in body:
            self.statement(s)

    def braced(self, opener: str, s) -> None:
        self.line(opener + " {")
        self.depth += 1
        self.scopes.append({})
        self.statements(s[1] if s[0] == "block" else [s])
        self.scopes.pop()
        self.depth -= 1

    def branch(self, opener: str, body) -> None:
        """A GLSL branch without braces stays one line: `if (c) { x = 1.0; }`."""
        saved, self.lines = self.lines, []
        self.braced(opener, body)
        inner, self.lines = self.lines[1:], saved
        if body[0] != "block" and len(inner) == 1 and "//" not in inner[0]:
            self.line(f"{opener} {{ {inner[0].strip()} }}")
        else:
            self.line(opener + " {")
            self.lines.extend(inner)
            self.line("}")

    def statement(self, s) -> None:
        self.one_statement(s)
        for line in self.writebacks:
            self.line(line)
        self.writebacks = []

    def one_statement(self, s) -> None:
        kind = s[0]
        if kind == "comment":
            self.comment(s[1])
        elif kind == "block":
            self.braced("", s)
            self.line("}")
        elif kind == "decl":
            self.declare(s)
        elif kind == "expr":
            self.line(self.expression_statement(s[1]) + ";")
        elif kind == "if":
            branches, other = [], s
            while other is not None and other[0] == "if":
                cond, _ = self.expr(other[1])
                branches.append((f"{'if' if not branches else 'else if'} ({strip_parens(cond)})", other[2]))
                other = other[3]
            if other is not None:
                branches.append(("else", other))
            for opener, body in branches:
                self.branch(opener, body)
        elif kind == "for":
            self.scopes.append({})
            init = self.declaration_text(s[1]) if s[1] and s[1][0] == "decl" else (
                self.expression_statement(s[1][1]) if s[1] else "")
            cond = self.expr(s[2])[0] if s[2] else ""
            step = self.expression_statement(s[3]) if s[3] else ""
            self.braced(f"for ({init}; {cond}; {step})", s[4])
            self.line("}")
            self.scopes.pop()
        elif kind == "while":
            cond, _ = self.expr(s[1])
            self.braced(f"while ({strip_parens(cond)})", s[2])
            self.line("}")
        elif kind == "return":
            if s[1] is None:
                self.line("return;")
            else:
                text, t = self.expr(s[1])
                if self.writebacks:  # the copies back happen before the function returns
                    self.line(f"let returned = {self.convert(text, t, self.ret)};")
                    for line in self.writebacks:
                        self.line(line)
                    self.writebacks = []
                    self.line("return returned;")
                else:
                    self.line(f"return {self.convert(text, t, self.ret)};")
        else:
            self.line(f"{kind};")

    def declaration_text(self, s) -> str:
        _, const, t, decls = s
        if len(decls) != 1:
            raise Untranslatable("several declarations in a for loop")
        return self.one_declaration(const, t, *decls[0])

    def one_declaration(self, const: bool, t: str, name: str, size, init) -> str:
        if size is not None:  # a variable even when const: indexed at run time, as a value it would be copied
            n, _ = self.expr(size)
            self.scopes[-1][name] = self.lib.canon(t) + "[]"
            declared = f"var {safe_name(name)}: array<{wgsl_type(t)}, {n}>"
            return declared if init is None else f"{declared} = {self.expr(init)[0]}"
        t = self.scopes[-1][name] = self.lib.canon(t)
        if init is None:
            return f"var {safe_name(name)}: {wgsl_type(t)}"
        text, it = self.expr(init)
        keyword = "let" if const else "var"
        return f"{keyword} {safe_name(name)}: {wgsl_type(t)} = {self.convert(text, it, t)}"

    def declare(self, s) -> None:
        _, const, t, decls = s
        for name, size, init in decls:
            self.line(self.one_declaration(const, t, name, size, init) + ";")

    def expression_statement(self, e: Expr) -> str:
        if e.kind == "assign" and e.value == "=" and e.args[1].kind == "assign":  # a = b = x: b first
            self.line(self.expression_statement(e.args[1]) + ";")
            e = Expr("assign", "=", [e.args[0], e.args[1].args[0]])
        if e.kind == "assign":
            target, tt = self.expr(e.args[0])
            if e.args[0].kind == "member" and len(e.args[0].value) > 1 and \
                    self.expr(e.args[0].args[0])[1] not in self.lib.structs:
                raise Untranslatable("a write to several components of a vector")
            value, vt = self.expr(e.args[1])
            expected = tt if e.value == "=" or size_of(vt) == size_of(tt) or tt.startswith("mat") else scalar_of(tt)
            if e.value in ("*=", "/=") and (vt.startswith("mat") or size_of(vt) == 1):
                expected = vt if vt.startswith("mat") else vector_of(scalar_of(tt), 1)
            return f"{strip_parens(target)} {e.value} {self.convert(value, vt, expected)}"
        if e.kind == "postfix":
            target, _ = self.expr(e.args[0])
            return f"{target}{e.value}"
        if e.kind == "call":
            text, t = self.expr(e)
            return text if t == "void" else f"_ = {text}"
        raise Untranslatable("an expression statement without effect")


def add_comment(lines: list[str], comment: str, indent: str) -> None:
    """A comment token as WGSL: at the end of the last line when it followed code there (and that
    line is code), else on a line of its own."""
    trailing = comment.startswith(TRAILING)
    text = "//" + comment[len(TRAILING) if trailing else 2:]
    if trailing and lines and lines[-1].strip():
        lines[-1] += "  " + text
    else:
        lines.append(indent + text)


def strip_parens(text: str) -> str:
    """`(*p)` as an assignment target reads better as `*p`; a whole parenthesised condition loses its
    parentheses (the `if ( )` has them)."""
    if text.startswith("(") and text.endswith(")"):
        depth = 0
        for i, c in enumerate(text):
            depth += c == "("
            depth -= c == ")"
            if depth == 0 and i < len(text) - 1:
                return text
        return text[1:-1]
    return text


# GLSL's fragment built-in variables: WGSL passes them to the entry point, which copies them into
# private variables of these names (target.py) so library code reads them anywhere.
FRAGMENT_BUILTINS = {"gl_FrontFacing": ("front_facing", "bool")}


def safe_name(name: str) -> str:
    if name in FRAGMENT_BUILTINS:
        return FRAGMENT_BUILTINS[name][0]
    return f"{name}_" if name in WGSL_RESERVED else name


class Translator:
    """Translates library files in dependency order; remembers what each declared so later files
    (and the generator's calls) resolve overloads and pointer parameters."""

    def __init__(self, prelude: dict[str, str], uniforms: dict[str, str] | None = None):
        """`prelude`: GLSL declarations every file may use (the closure and light structs);
        `uniforms`: name -> GLSL type of the uniforms library functions read directly."""
        self.lib = Library()
        self.lib.globals.update(uniforms or {})
        self.done: dict[tuple[str, str], str] = {}
        self.defined = {"GL_ES"}
        self.defined_before: dict[str, set[str]] = {}  # file -> the macros defined when it was first met
        self.prelude = {name: self._file(text, self.defined) for name, text in prelude.items()}

    def structs(self, used: set[str]) -> list[str]:
        return [text.strip() for name, text in self.prelude.items() if name in used]

    def file(self, key: str, text: str) -> str:
        """A file translated once per text: shaders resolve its feature sections differently."""
        if (key, text) not in self.done:
            # a file met again sees the macros of its first time, not its own #define guards
            defined = set(self.defined_before.setdefault(key, set(self.defined)))
            self.done[key, text] = self._file(text, defined)
            self.defined |= defined
        return self.done[key, text]

    def _file(self, text: str, defined: set[str]) -> str:
        items = Parser(tokenize(preprocess(text, defined)), set(self.lib.structs)).top_level()
        names = [it[2] for it in items if it[0] == "function"]
        out: list[str] = []
        for it in items:
            if it[0] == "comment":
                add_comment(out, it[1], "")
            elif it[0] == "define":
                value = FunctionEmitter(self.lib, [], "void").expr(Parser(tokenize(it[2]), set()).expression())
                self.lib.globals[it[1]] = value[1]
                out.append(f"const {it[1]}: {wgsl_type(value[1])} = {value[0]};")
            elif it[0] == "alias":
                self.lib.aliases[it[1]] = it[2]
                out.append(f"alias {it[1]} = {wgsl_type(it[2])};")
            elif it[0] == "struct":
                self.lib.structs[it[1]] = [(self.lib.canon(t), n) for t, n in it[2]]
                members = ", ".join(f"{safe_name(n)}: {wgsl_type(t)}" for t, n in it[2])
                out.append(f"struct {it[1]} {{ {members} }}")
            elif it[0] == "global":
                _, const, t, decls = it[1]
                emitter = FunctionEmitter(self.lib, [], "void")
                for name, size, init in decls:
                    if init is None:
                        raise Untranslatable("a module-scope variable")
                    value, vt = emitter.expr(init)
                    if size is not None:  # a constant array: its type is its constructor's
                        # A `const` array indexed at run time is a value: naga copies all of it into a
                        # local at every index (SPIR-V cannot index a value), which makes drivers
                        # compile for minutes (lavapipe: a 932-line surface, over five minutes against
                        # four seconds); a private variable is indexed in place.
                        self.lib.globals[name] = vt
                        array_type = value.split("(", 1)[0]
                        out.append(f"var<private> {safe_name(name)}: {array_type} = {value};")
                        continue
                    self.lib.globals[name] = t
                    out.append(f"const {safe_name(name)}: {wgsl_type(t)} = {emitter.convert(value, vt, t)};")
            else:
                out.extend(self.function(it, names.count(it[2]) > 1))
                out.append("")
        return "\n".join(out).strip("\n") + "\n"

    def function(self, item, overloaded: bool) -> list[str]:
        _, ret, name, params, body = item
        suffix = "_".join(re.sub(r"\[(\w+)\]", r"_\1", t) for _, t, _ in params)  # vec3[3] -> vec3_3
        wgsl_name = f"{name}_{suffix}" if overloaded else name
        declared = {n: t for _, t, n in params}  # array parameters keep their size here
        params = [(q, self.lib.canon(t), n) for q, t, n in params]
        ret = self.lib.canon(ret)
        # a file translated again (its feature sections resolved otherwise) declares the same function
        family = self.lib.functions.setdefault(name, [])
        family[:] = [s for s in family if s.name != wgsl_name] + [Signature(wgsl_name, ret, params)]
        emitter = FunctionEmitter(self.lib, params, ret)
        assigned = assigned_names(body)
        copies = []
        texts = []
        for q, t, n in params:
            if q == "in":
                if n in assigned:  # WGSL parameters are immutable: work on a copy
                    # `__`: no uniform has it in its name (targets/names.py), so none is read here
                    texts.append(f"{n}__in: {param_type(declared[n])}")
                    copies.append(f"    var {safe_name(n)}: {param_type(declared[n])} = {n}__in;")
                else:
                    texts.append(f"{safe_name(n)}: {param_type(declared[n])}")
            else:
                texts.append(f"{safe_name(n)}: ptr<function, {param_type(declared[n])}>")
            if t == "sampler2D":  # a GLSL sampler is a WGSL texture and its sampler
                texts[-1] = f"{safe_name(n)}: texture_2d<f32>, {n}_sampler: sampler"
        emitter.statements(body)
        arrow = "" if ret == "void" else f" -> {wgsl_type(ret)}"
        return [f"fn {wgsl_name}({', '.join(texts)}){arrow} {{", *copies, *emitter.lines, "}"]

    def signature(self, name: str) -> Signature | None:
        family = self.lib.functions.get(name, [])
        return family[0] if len(family) == 1 else None

    def expression(self, text: str, types: dict[str, str]) -> tuple[str, str]:
        """An inline expression whose placeholders are already names of the given GLSL types."""
        emitter = FunctionEmitter(self.lib, [("in", t, n) for n, t in types.items()], "void")
        return emitter.expr(Parser(tokenize(text), set(self.lib.structs)).expression())


def assigned_names(body) -> set[str]:
    names: set[str] = set()

    def target(e: Expr):
        while e.kind in ("member", "index", "paren"):
            e = e.args[0]
        if e.kind == "id":
            names.add(e.value)

    def walk(node):
        if isinstance(node, Expr):
            if node.kind in ("assign", "postfix"):
                target(node.args[0])
            for a in node.args:
                walk(a)
        elif isinstance(node, (list, tuple)):
            for n in node:
                walk(n)
    walk(body)
    return names
