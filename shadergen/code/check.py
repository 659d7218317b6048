"""Types the untyped IR of a set of library modules (code/parse.py) in place.

After `check_modules`: every expression has its IR type (`Expr.type`); every Name its `kind`
("local", "param", "global" for a library constant or global, "uniform" for an external,
"builtin" for a target's variable such as gl_FrontFacing); every Call its `callee` (the
ir.Function it resolves to, overloads by GLSL's rules: an exact match, else the one candidate
needing fewest implicit conversions) or `builtin` True (code/builtins.py); a Call of a struct or
type alias is a Construct; every swizzle is marked (`Field.swizzle`) and written with xyzw letters;
type aliases (`#define EDF vec3`) are resolved wherever a type is named and dropped from their
module; array sizes named by constants (`T[MAX_LIGHT_SOURCES]`) are numbers; Function.key is
recomputed from the resolved parameter types.

Implicit conversions are written out as `ir.Convert(type, operand, implicit=True)`, exactly here:
  - int (or uint) to float, and int to uint, of the same shape, where GLSL converts implicitly:
    a function's or built-in's `in` argument, an initialiser, an assigned value, a returned
    value, a constant's value, a struct or array constructor's argument, the operand of the
    other kind in a binary operator (`x * 2`, `i < 0.5`), a branch of `?:`;
  - a scalar spread over a vector in built-in arguments GLSL takes as scalars
    (`clamp(v, 0.0, 1.0)`, `mix(a, b, 0.5)`, `max(v, 0.0)`, `step(0.5, v)`: builtins.py's "t");
  - a component of a vector or matrix constructor whose scalar differs from the constructed
    one (`vec2(i, 1.0)`, `vec3(1)`): the constructor converts it; except a constructor's single
    vector or matrix argument (`vec3(ivec3)`), which is the explicit conversion itself.
None is written where an operator takes mixed shapes itself: `vec3 * float`, `mat3 * vec3`,
`float + vec2` (component-wise with the scalar), `v *= 2.0`. Explicit conversions
(`float(i)`) stay Constructs.

Errors are ShaderGenError("invalid_source", "<file>:<line>:<col>: <what>", <file>).
"""
from ..errors import source_error
from . import ir
from .builtins import BUILTIN_VARIABLES, BUILTINS
from .types import (GLSL_TYPES, array_element, array_of, array_size, column_of, is_array, is_matrix, is_numeric,
                    is_scalar, is_vector, scalar_of, size_of, vector_of)

__all__ = ["check_modules", "check_expression", "Symbols", "library_symbols"]

SWIZZLE_SETS = ("xyzw", "rgba", "stpq")


class Symbols:
    """What code of one module sees: types (structs and aliases of the whole set), functions by
    name (name -> key -> Function, in the order met), values (name -> (type, kind)); `items`,
    filled for the whole library only (code/library.py): structs, constants and globals by name."""
    __slots__ = ("structs", "aliases", "functions", "values", "items")

    def __init__(self, structs, aliases, functions=None, values=None):
        self.structs: dict[str, list[tuple[str, str]]] = structs
        self.aliases: dict[str, str] = aliases
        self.functions: dict[str, dict[str, ir.Function]] = functions if functions is not None else {}
        self.values: dict[str, tuple[str, str]] = values if values is not None else {}
        self.items: dict[str, ir.Item] = {}

    def merged(self, other: "Symbols") -> None:
        for name, family in other.functions.items():
            mine = self.functions.setdefault(name, {})
            for key, fn in family.items():
                mine.setdefault(key, fn)
        for name, value in other.values.items():
            self.values.setdefault(name, value)


def where_of(node, fallback) -> tuple:
    return node.where if node is not None and node.where is not None else fallback


class Checker:
    """Types one module's items (or one expression) against `symbols`."""

    def __init__(self, path: str, symbols: Symbols, externals: dict[str, str]):
        self.path = path
        self.symbols = symbols
        self.externals = externals
        self.scopes: list[dict[str, tuple[str, str]]] = []
        self.returns = "void"
        self.placeholders: dict[str, str] = {}
        self.constant_values: dict[str, int] = {}  # integer constants by name (array sizes)

    def error(self, node, what: str):
        where = where_of(node, (self.path, 0, 0))
        return source_error(where[0], where[1], where[2], what)

    # -- types -------------------------------------------------------------------------------------
    def resolve_type(self, t: str, node) -> str:
        """An IR type as written in the source -> the IR type: aliases resolved, array sizes numbers."""
        if is_array(t):
            element = self.resolve_type(array_element(t), node)
            size = t[t.rindex("[") + 1:-1]
            if size and not size.isdigit():
                value = self.constant_int(size, node)
                size = str(value)
            return f"{element}[{size}]"
        t = self.symbols.aliases.get(t, t)
        if t in GLSL_TYPES or t in self.symbols.structs:
            return t
        raise self.error(node, f"unknown type '{t}'")

    def constant_int(self, name: str, node) -> int:
        if name not in self.constant_values:
            raise self.error(node, f"array size '{name}' is not an integer constant")
        return self.constant_values[name]

    def convert(self, e: ir.Expr, to: str, node=None) -> ir.Expr:
        """`e` where a `to` is expected: itself, or implicitly converted (int -> float, int -> uint)."""
        t = e.type
        if t == to:
            return e
        if implicitly_converts(t, to):
            return ir.Convert(to, e, implicit=True, where=e.where)
        raise self.error(e if e.where else node, f"a {t} where a {to} is expected")

    # -- expressions -------------------------------------------------------------------------------
    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        cls.EXPR_RULES = expr_rules(cls)

    def expr(self, e: ir.Expr) -> ir.Expr:
        rule = self.EXPR_RULES.get(e.__class__)
        if rule is None:
            return getattr(self, "expr_" + type(e).__name__)(e)  # (not an expression: raises)
        return rule(self, e)

    def expr_Literal(self, e):
        if isinstance(e.value, bool):
            e.type = "bool"
        elif isinstance(e.value, float):
            e.type = "float"
        else:
            e.type = "uint" if (e.text or "").lower().endswith("u") else "int"
        return e

    def expr_Placeholder(self, e):
        if e.name not in self.placeholders:
            raise self.error(e, f"inline expression names unknown input '{e.name}'")
        e.type = self.placeholders[e.name]
        return e

    def expr_Name(self, e):
        for scope in reversed(self.scopes):
            if e.name in scope:
                e.type, e.kind = scope[e.name]
                return e
        if e.name in self.symbols.values:
            e.type, e.kind = self.symbols.values[e.name]
            return e
        if e.name in self.externals:
            e.type, e.kind = self.resolve_type(self.externals[e.name], e), "uniform"
            return e
        if e.name in BUILTIN_VARIABLES:
            e.type, e.kind = BUILTIN_VARIABLES[e.name], "builtin"
            return e
        raise self.error(e, f"unknown name '{e.name}'")

    def expr_Field(self, e):
        e.base = self.expr(e.base)
        t = e.base.type
        if t in self.symbols.structs:
            for member_type, member in self.symbols.structs[t]:
                if member == e.name:
                    e.type = member_type
                    return e
            raise self.error(e, f"struct {t} has no member '{e.name}'")
        if is_vector(t) or is_scalar(t):
            letters = next((s for s in SWIZZLE_SETS if all(c in s for c in e.name)), None)
            if letters is None or len(e.name) > 4 or any(letters.index(c) >= size_of(t) for c in e.name):
                raise self.error(e, f"'{e.name}' is not a swizzle of a {t}")
            e.name = "".join("xyzw"[letters.index(c)] for c in e.name)
            e.swizzle = True
            e.type = vector_of(scalar_of(t), len(e.name))
            return e
        raise self.error(e, f"a {t} has no member '{e.name}'")

    def expr_Index(self, e):
        e.base = self.expr(e.base)
        e.index = self.expr(e.index)
        if e.index.type not in ("int", "uint"):
            raise self.error(e.index, f"an index must be an int, not a {e.index.type}")
        t = e.base.type
        if is_array(t):
            e.type = array_element(t)
        elif is_matrix(t):
            e.type = column_of(t)
        elif is_vector(t):
            e.type = scalar_of(t)
        else:
            raise self.error(e, f"a {t} cannot be indexed")
        return e

    def expr_Unary(self, e):
        e.operand = self.expr(e.operand)
        t = e.operand.type
        if e.op == "!" and t != "bool":
            raise self.error(e, f"'!' of a {t}")
        if e.op == "-" and (not is_numeric(t) or scalar_of(t) == "bool"):
            raise self.error(e, f"'-' of a {t}")
        if e.op == "~" and scalar_of(t) not in ("int", "uint"):
            raise self.error(e, f"'~' of a {t}")
        e.type = t
        return e

    def expr_Binary(self, e):
        e.left = self.expr(e.left)
        e.right = self.expr(e.right)
        e.left, e.right, e.type = self.binary(e.op, e.left, e.right, e)
        return e

    def binary(self, op: str, left: ir.Expr, right: ir.Expr, node) -> tuple[ir.Expr, ir.Expr, str]:
        """The operands (converted where GLSL converts them) and the result type of `left op right`."""
        a, b = left.type, right.type
        if op in ("&&", "||"):
            if a != "bool" or b != "bool":
                raise self.error(node, f"'{op}' of {a} and {b}")
            return left, right, "bool"
        if not (is_numeric(a) and is_numeric(b)):
            if op in ("==", "!=") and a == b and a in self.symbols.structs:
                return left, right, "bool"
            raise self.error(node, f"'{op}' of {a} and {b}")
        sa, sb = scalar_of(a), scalar_of(b)
        if sa != sb:  # GLSL converts int to uint and both to float
            wider = "float" if "float" in (sa, sb) else "uint"
            if "bool" in (sa, sb) or op in ("<<", ">>"):
                if op not in ("<<", ">>"):
                    raise self.error(node, f"'{op}' of {a} and {b}")
            elif sa != wider:
                left = self.convert(left, vector_of(wider, size_of(a)) if not is_matrix(a) else a, node)
                a = left.type
            else:
                right = self.convert(right, vector_of(wider, size_of(b)) if not is_matrix(b) else b, node)
                b = right.type
        if op in ("==", "!="):
            if a != b:
                raise self.error(node, f"'{op}' of {a} and {b}")
            return left, right, "bool"
        if op in ("<", ">", "<=", ">="):
            if a != b or not is_scalar(a) or a == "bool":
                raise self.error(node, f"'{op}' of {a} and {b}")
            return left, right, "bool"
        if scalar_of(a) == "bool" or scalar_of(b) == "bool":
            raise self.error(node, f"'{op}' of {a} and {b}")
        if op in ("%", "&", "|", "^", "<<", ">>"):
            if scalar_of(a) not in ("int", "uint") or scalar_of(b) not in ("int", "uint"):
                raise self.error(node, f"'{op}' of {a} and {b}")
            if op in ("<<", ">>"):
                return left, right, a
        if a == b:
            return left, right, a
        if is_scalar(a):
            return left, right, b
        if is_scalar(b):
            return left, right, a
        if op == "*" and is_matrix(a) and is_vector(b) and size_of(b) ** 2 == size_of(a):
            return left, right, b
        if op == "*" and is_vector(a) and is_matrix(b) and size_of(a) ** 2 == size_of(b):
            return left, right, a
        raise self.error(node, f"'{op}' of {a} and {b}")

    def expr_Select(self, e):
        e.condition = self.expr(e.condition)
        if e.condition.type != "bool":
            raise self.error(e.condition, f"a {e.condition.type} as a condition")
        e.if_true = self.expr(e.if_true)
        e.if_false = self.expr(e.if_false)
        a, b = e.if_true.type, e.if_false.type
        if a != b:
            if implicitly_converts(a, b):
                e.if_true = self.convert(e.if_true, b)
            elif implicitly_converts(b, a):
                e.if_false = self.convert(e.if_false, a)
            else:
                raise self.error(e, f"'?:' between a {a} and a {b}")
        e.type = e.if_true.type
        return e

    def expr_Convert(self, e):
        e.operand = self.expr(e.operand)
        return e

    def expr_Construct(self, e):
        t = self.resolve_type(e.type, e)
        e.args = [self.expr(a) for a in e.args]
        if is_array(t):
            element, size = array_element(t), array_size(t)
            if size is None:
                size = len(e.args)
                t = array_of(element, size)
            if len(e.args) != size:
                raise self.error(e, f"{len(e.args)} values for an array of {size}")
            e.args = [self.convert(a, element) for a in e.args]
        elif t in self.symbols.structs:
            members = self.symbols.structs[t]
            if len(e.args) != len(members):
                raise self.error(e, f"{len(e.args)} values for struct {t} of {len(members)} members")
            e.args = [self.convert(a, mt) for a, (mt, _) in zip(e.args, members)]
        elif is_scalar(t):
            if len(e.args) != 1 or not is_numeric(e.args[0].type):
                raise self.error(e, f"{t}() takes one number")
        elif is_vector(t) or is_matrix(t):
            self.construct_numeric(e, t)
        else:
            raise self.error(e, f"no constructor of a {t}")
        e.type = t
        return e

    def construct_numeric(self, e: ir.Construct, t: str) -> None:
        if not e.args or any(not is_numeric(a.type) for a in e.args):
            raise self.error(e, f"{t}() takes numbers")
        scalar = scalar_of(t)
        if len(e.args) == 1:
            only = e.args[0]
            if is_scalar(only.type) and only.type != scalar:
                e.args = [ir.Convert(scalar, only, implicit=True, where=only.where)]
            return  # a vector or matrix argument: the constructor converts or resizes it
        given = sum(size_of(a.type) for a in e.args)
        wanted = size_of(t)
        if given < wanted or given - size_of(e.args[-1].type) >= wanted:
            raise self.error(e, f"{given} components for a {t}")
        e.args = [a if scalar_of(a.type) == scalar else
                  ir.Convert(a.type if is_matrix(a.type) else vector_of(scalar, size_of(a.type)), a, implicit=True,
                             where=a.where)
                  for a in e.args]

    def expr_Call(self, e):
        resolved = self.symbols.aliases.get(e.name, e.name)
        if resolved in self.symbols.structs or resolved in GLSL_TYPES:
            return self.expr(ir.Construct(resolved, e.args, where=e.where))
        e.args = [self.expr(a) for a in e.args]
        family = self.symbols.functions.get(e.name)
        if family:
            fn, args = self.overload(e, list(family.values()))
            e.args, e.callee, e.builtin, e.type = args, fn, False, fn.returns
            return e
        sigs = BUILTINS.get(e.name)
        if sigs is None:
            raise self.error(e, f"unknown function '{e.name}'")
        for sig in sigs:
            found = self.builtin(sig, e.args)
            if found is not None:
                e.args, e.type = found
                e.builtin, e.callee = True, None
                return e
        raise self.error(e, f"no built-in {e.name}({', '.join(a.type for a in e.args)})")

    def overload(self, e: ir.Call, family: list[ir.Function]) -> tuple[ir.Function, list[ir.Expr]]:
        best, best_cost, tie = None, None, False
        for fn in family:
            if len(fn.params) != len(e.args):
                continue
            cost = 0
            for p, a in zip(fn.params, e.args):
                if p.type == a.type:
                    continue
                if p.qualifier == "in" and implicitly_converts(a.type, p.type):
                    cost += 1
                    continue
                cost = None
                break
            if cost is None:
                continue
            if best_cost is None or cost < best_cost:
                best, best_cost, tie = fn, cost, False
            elif cost == best_cost:
                tie = True
        types = ", ".join(a.type for a in e.args)
        if best is None:
            raise self.error(e, f"no overload of '{e.name}' takes ({types})")
        if tie:
            raise self.error(e, f"the call {e.name}({types}) is ambiguous")
        for p, a in zip(best.params, e.args):
            if p.qualifier != "in" and not self.is_lvalue(a):
                raise self.error(a, f"the {p.qualifier} argument '{p.name}' of '{e.name}' is not a variable")
        return best, [self.convert(a, p.type) for p, a in zip(best.params, e.args)]

    def builtin(self, sig, args: list[ir.Expr]):
        """(converted args, return type) of a call matching the built-in signature, or None."""
        if len(sig.params) != len(args):
            return None
        generic = None
        shaped = [a.type for p, a in zip(sig.params, args) if p == "T"]
        if shaped:
            generic = common_type(shaped, sig.families)
            if generic is None:
                return None
        out = []
        for p, a in zip(sig.params, args):
            if p == "T":
                want = generic
            elif p == "t":
                want = generic
                if is_scalar(a.type) and not is_scalar(generic):
                    s = scalar_of(generic)
                    if a.type != s and not implicitly_converts(a.type, s):
                        return None
                    a = a if a.type == s else ir.Convert(s, a, implicit=True, where=a.where)
                    out.append(ir.Convert(generic, a, implicit=True, where=a.where))
                    continue
            elif p == "S":
                want = scalar_of(generic)
            elif p in ("bT", "iT", "uT", "fT"):
                want = vector_of({"b": "bool", "i": "int", "u": "uint", "f": "float"}[p[0]], size_of(generic))
            else:
                want = p
            if a.type != want and not implicitly_converts(a.type, want):
                return None
            out.append(a if a.type == want else ir.Convert(want, a, implicit=True, where=a.where))
        r = sig.returns
        if r == "T":
            ret = generic
        elif r == "S":
            ret = scalar_of(generic)
        elif r in ("bT", "iT", "uT", "fT"):
            ret = vector_of({"b": "bool", "i": "int", "u": "uint", "f": "float"}[r[0]], size_of(generic))
        else:
            ret = r
        return out, ret

    def is_lvalue(self, e: ir.Expr) -> bool:
        while isinstance(e, (ir.Field, ir.Index)):
            e = e.base
        return isinstance(e, ir.Name) and e.kind in ("local", "param", "global")

    # -- statements --------------------------------------------------------------------------------
    def declare(self, name: str, t: str, kind: str) -> None:
        self.scopes[-1][name] = (t, kind)

    def block(self, block: ir.Block) -> None:
        self.scopes.append({})
        self.statements(block.body)
        self.scopes.pop()

    def statements(self, body: list) -> None:
        for s in body:
            self.statement(s)

    def statement(self, s) -> None:
        kind = type(s)
        if kind is ir.Declare:
            s.type = self.resolve_type(s.type, s)
            if s.init is not None:
                s.init = self.expr(s.init)
                if is_array(s.type) and array_size(s.type) is None and is_array(s.init.type):
                    s.type = s.init.type
                s.init = self.convert(s.init, s.type, s)
            self.declare(s.name, s.type, "local")
        elif kind is ir.Assign:
            self.assign(s)
        elif kind is ir.ExprStatement:
            s.expr = self.expr(s.expr)
        elif kind is ir.If:
            s.condition = self.condition(s.condition)
            self.block(s.then)
            if s.other is not None:
                self.block(s.other)
        elif kind is ir.For:
            self.scopes.append({})
            if s.init is not None:
                self.statement(s.init)
            if s.condition is not None:
                s.condition = self.condition(s.condition)
            if s.update is not None:
                self.statement(s.update)
            self.block(s.body)
            self.scopes.pop()
        elif kind is ir.While:
            s.condition = self.condition(s.condition)
            self.block(s.body)
        elif kind is ir.Return:
            if s.value is None:
                if self.returns != "void":
                    raise self.error(s, f"a return without a value from a function returning {self.returns}")
            else:
                if self.returns == "void":
                    raise self.error(s, "a return with a value from a void function")
                s.value = self.convert(self.expr(s.value), self.returns, s)
        elif kind is ir.Block:
            if s.scoped:
                self.block(s)
            else:
                self.statements(s.body)
        elif kind is ir.Section:  # both sides, in the enclosing scope (a section does not scope)
            self.statements(s.body)
            self.statements(s.other)
        elif kind in (ir.Break, ir.Continue, ir.Discard, ir.Comment):
            pass
        else:
            raise self.error(s, f"unexpected {kind.__name__} among statements")

    def condition(self, e: ir.Expr) -> ir.Expr:
        e = self.expr(e)
        if e.type != "bool":
            raise self.error(e, f"a {e.type} as a condition")
        return e

    def assign(self, s: ir.Assign) -> None:
        s.target = self.expr(s.target)
        if not self.is_lvalue(s.target):
            raise self.error(s, "an assignment to something other than a variable")
        t = s.target.type
        if s.value is None:  # ++ / --
            if scalar_of(t) not in ("int", "uint", "float"):
                raise self.error(s, f"'{s.op}' of a {t}")
            return
        s.value = self.expr(s.value)
        if s.op == "=":
            s.value = self.convert(s.value, t, s)
            return
        op = s.op[:-1]
        value = s.value
        if scalar_of(value.type) != scalar_of(t) and implicitly_converts(scalar_of(value.type) or "", scalar_of(t) or ""):
            value = self.convert(value, vector_of(scalar_of(t), size_of(value.type)) if not is_matrix(value.type)
                                 else value.type, s)
        _, _, result = self.binary(op, s.target, value, s)
        if result != t:
            raise self.error(s, f"'{s.op}' of a {t} by a {s.value.type}")
        s.value = value

    # -- items -------------------------------------------------------------------------------------
    def function(self, fn: ir.Function) -> None:
        self.returns = fn.returns
        self.scopes = [{p.name: (p.type, "param") for p in fn.params}]
        self.statements(fn.body.body)
        self.scopes = []


def expr_rules(cls) -> dict:
    """A checker class's `expr_<Class>` method per expression class: `expr` looks its rule up by
    the node's class instead of by a name built per node (generated code is typed per request)."""
    return {node: getattr(cls, "expr_" + node.__name__) for node in vars(ir).values()
            if isinstance(node, type) and issubclass(node, ir.Expr) and hasattr(cls, "expr_" + node.__name__)}


Checker.EXPR_RULES = expr_rules(Checker)


def implicitly_converts(a: str | None, b: str | None) -> bool:
    """Whether GLSL converts a value of type `a` to `b` implicitly (int -> uint -> float, same shape)."""
    if a is None or b is None or a == b:
        return a == b
    sa, sb = scalar_of(a), scalar_of(b)
    if sa is None or sb is None or is_matrix(a) or is_matrix(b) or size_of(a) != size_of(b):
        return False
    return (sa, sb) in (("int", "float"), ("uint", "float"), ("int", "uint"))


def common_type(types: list[str], families: tuple[str, ...]) -> str | None:
    """T for a built-in's T arguments: their one type, with int ones taken as float (or uint)
    where GLSL would convert them; None if none of `families` fits."""
    first = types[0]
    if all(t == first for t in types) and first in families:
        return first
    shapes = {size_of(t) for t in types}
    if len(shapes) != 1 or any(is_matrix(t) for t in types):
        return first if all(t == first for t in types) and first in families else None
    n = shapes.pop()
    for scalar in ("uint", "float"):
        t = vector_of(scalar, n)
        if t in families and all(x == t or implicitly_converts(x, t) for x in types):
            return t
    return None


# -- module sets ---------------------------------------------------------------------------------
def flat_items(items: list) -> list:
    """Items with the Sections' both sides spread in, in source order."""
    out = []
    for item in items:
        if isinstance(item, ir.Section):
            out.extend(flat_items(item.body))
            out.extend(flat_items(item.other))
        else:
            out.append(item)
    return out


def alias_target(item, structs: dict) -> str | None:
    """The type a `#define NAME TYPE` names, or None for a constant."""
    if isinstance(item, ir.Constant) and item.type is None and isinstance(item.value, ir.Name):
        if item.value.name in GLSL_TYPES or item.value.name in structs:
            return item.value.name
    return None


def dependency_order(modules: dict[str, ir.Module], first: tuple[str, ...]) -> list[str]:
    """Module paths, each after the files it includes (`first` before all), else sorted."""
    order: list[str] = []
    state: dict[str, int] = {}

    def visit(path: str, by: ir.Module | None) -> None:
        if state.get(path) == 2:
            return
        if state.get(path) == 1:
            raise source_error(path, 1, 1, "it includes itself")
        if path not in modules:
            where = by.path if by is not None else path
            raise source_error(where, 1, 1, f"includes missing '{path}'")
        state[path] = 1
        for inc in modules[path].includes:
            visit(inc, modules[path])
        state[path] = 2
        order.append(path)
    for path in first:
        visit(path, None)
    for path in sorted(modules):
        visit(path, None)
    return order


def check_modules(modules: dict[str, ir.Module], externals: dict[str, str],
                  prelude: tuple[str, ...] = ()) -> dict[str, Symbols]:
    """Types the modules (path -> Module) in place; `prelude`: paths of modules every other sees
    (the closure structs); `externals`: name -> IR type of the uniforms the generator declares.
    Returns each module's Symbols (what its code sees: itself, its includes, the prelude)."""
    order = dependency_order(modules, prelude)
    structs: dict[str, list[tuple[str, str]]] = {}
    aliases: dict[str, str] = {}
    constant_values: dict[str, int] = {}
    seen: dict[str, Symbols] = {}
    for path in order:
        module = modules[path]
        symbols = Symbols(structs, aliases)
        for dep in (*prelude, *module.includes):
            if dep in seen and dep != path:
                symbols.merged(seen[dep])
        checker = Checker(path, symbols, externals)
        checker.constant_values = constant_values
        items = flat_items(module.items)
        for item in items:  # types and values first, in order; then every signature; then bodies
            if isinstance(item, ir.Struct):
                item.members = [(checker.resolve_type(t, item), n) for t, n in item.members]
                structs[item.name] = item.members
            elif alias_target(item, structs) is not None:
                aliases[item.name] = checker.resolve_type(alias_target(item, structs), item)
            elif isinstance(item, ir.Constant):
                item.value = checker.expr(item.value)
                item.type = item.value.type if item.type is None else checker.resolve_type(item.type, item)
                if is_array(item.type) and array_size(item.type) is None:
                    item.type = item.value.type
                item.value = checker.convert(item.value, item.type, item)
                symbols.values[item.name] = (item.type, "global")
                if item.type == "int" and isinstance(item.value, ir.Literal):
                    constant_values[item.name] = item.value.value
            elif isinstance(item, ir.Global):
                item.type = checker.resolve_type(item.type, item)
                if item.init is not None:
                    item.init = checker.convert(checker.expr(item.init), item.type, item)
                symbols.values[item.name] = (item.type, "global")
        for item in items:
            if isinstance(item, ir.Function):
                item.returns = checker.resolve_type(item.returns, item)
                for p in item.params:
                    p.type = checker.resolve_type(p.type, p)
                item.key = item.name + "(" + ",".join(p.type for p in item.params) + ")"
                symbols.functions.setdefault(item.name, {}).setdefault(item.key, item)
        for item in items:
            if isinstance(item, ir.Function):
                checker.function(item)
        module.items = drop_aliases(module.items, structs)
        seen[path] = symbols
    return seen


def drop_aliases(items: list, structs: dict) -> list:
    out = []
    for item in items:
        if isinstance(item, ir.Section):
            item.body = drop_aliases(item.body, structs)
            item.other = drop_aliases(item.other, structs)
        elif isinstance(item, ir.Constant) and item.type is None:
            continue  # an alias (a constant has its type by now)
        out.append(item)
    return out


def library_symbols(per_module: dict[str, Symbols]) -> Symbols:
    """Everything of every module (what an inline expression sees)."""
    out = None
    for path in sorted(per_module):
        symbols = per_module[path]
        if out is None:
            out = Symbols(symbols.structs, symbols.aliases)
        out.merged(symbols)
    return out if out is not None else Symbols({}, {})


MAX_TYPED = 65536  # typed templates a library keeps (their keys come from requests)


def check_expression(expr: ir.Expr, placeholder_types: dict[str, str], library) -> ir.Expr:
    """A typed copy of an inline template (`expr` itself is left untyped), its placeholders of
    the given IR types, against `library` (a code/library.py CodeLibrary: its `symbols` and
    `externals`). Memoised in `library.typed` per (template, types): it runs per request, and the
    result is shared (build new nodes rather than change it)."""
    memo_key = (expr, tuple(sorted(placeholder_types.items())))
    found = library.typed.get(memo_key)
    if found is None:
        where = expr.where[0] if expr.where else "inline expression"
        checker = Checker(where, library.symbols, library.externals)
        checker.placeholders = placeholder_types
        found = checker.expr(ir.copy_tree(expr))
        if len(library.typed) < MAX_TYPED:
            library.typed[memo_key] = found
    return found
