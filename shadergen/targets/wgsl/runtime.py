"""Constant operations of generated code made run-time operations, for WGSL.

WGSL evaluates an expression of constants when it creates the module and refuses the module when
that overflows or divides by zero (`1.0e30 * 1.0e30`, `1 / 0`); GLSL leaves such an expression to
run time, where it is inf (or undefined, as the specification says). The fold pass leaves exactly
those operations unfolded (evaluate.py refuses what 32 bits cannot hold), and inline expressions
of constant inputs make more. So in the code the generator wrote, every operation whose operands
are all constants takes its first constant operand through an identity function
(`mx_runtime_f32(1.0e30) * 1.0e30`): no longer a constant expression, computed as GLSL would.
Library code is left as written: it is validated as it is.
"""
from ...code import ir
from ...code.types import is_matrix, is_vector
from .printer import wgsl_type

OPERATIONS = (ir.Binary, ir.Unary, ir.Select)
FIRST_OPERAND = {ir.Binary: ("left", None), ir.Unary: ("operand", None), ir.Select: ("condition", None),
                 ir.Call: ("args", 0)}  # the field of an operation's first operand (a list's index)


def constant(e) -> bool:
    """Nothing in it is read at run time (literals, their constructors and conversions)."""
    cls = e.__class__
    if cls is ir.Literal:
        return True
    if cls is ir.Construct:
        return all(constant(a) for a in e.args)
    if cls is ir.Convert:
        return constant(e.operand)
    if cls in OPERATIONS:
        return all(constant(c) for c in ir.children(e))
    if cls is ir.Call:
        return e.builtin and all(constant(a) for a in e.args)
    return False


def operation(e) -> bool:
    return e.__class__ in OPERATIONS or (e.__class__ is ir.Call and e.builtin)


class Runtime:
    """The identity functions a stage's rewritten code calls, one per type, made on first use."""

    def __init__(self):
        self.functions: dict[str, ir.Function] = {}

    def identity(self, e: ir.Expr) -> ir.Call:
        t = e.type
        if t not in self.functions:
            value = ir.Name("value", "param", type=t)
            self.functions[t] = ir.Function(t, f"mx_runtime_{wgsl_type(t)}", [ir.Param("in", t, "value", False)],
                                            ir.Block([ir.Return(value)], True))
        function = self.functions[t]
        return ir.Call(function.name, [e], type=t, callee=function)

    def expression(self, e):
        """`e` with each outermost constant operation's first constant operand made run-time."""
        if not isinstance(e, ir.Expr):
            return e
        if operation(e) and constant(e):
            return self._first_operand_runtime(e)
        changes = {}
        for name in e.FIELDS:
            value = getattr(e, name)
            if isinstance(value, ir.Expr):
                new = self.expression(value)
                if new is not value:
                    changes[name] = new
            elif isinstance(value, list) and any(isinstance(v, ir.Expr) for v in value):
                new_list = [self.expression(v) for v in value]
                if any(a is not b for a, b in zip(new_list, value)):
                    changes[name] = new_list
        return ir.replace(e, **changes) if changes else e

    def _first_operand_runtime(self, e):
        """The operation with its first operand run-time (an operand that is an operation itself
        made run-time the same way: every operation above a run-time value is one), and each of
        its other operands that is a constant operation too, which WGSL would still evaluate."""
        field, index = FIRST_OPERAND[e.__class__]
        changes = {}
        for name in e.FIELDS:
            value = getattr(e, name)
            if isinstance(value, list):
                new = [self._runtime(v, first=name == field and k == index) for k, v in enumerate(value)]
                if any(a is not b for a, b in zip(new, value)):
                    changes[name] = new
            elif isinstance(value, ir.Expr):
                new = self._runtime(value, first=name == field and index is None)
                if new is not value:
                    changes[name] = new
        return ir.replace(e, **changes) if changes else e

    def _runtime(self, operand, first: bool):
        if operation(operand) and constant(operand):
            return self._first_operand_runtime(operand)
        if first and _runtime_type(operand):
            return self.identity(operand)
        return operand

    def statement(self, s):
        """A statement (and the statements inside it) with its expressions rewritten."""
        changes = {}
        for name in s.FIELDS:
            value = getattr(s, name)
            if isinstance(value, ir.Expr):
                new = self.expression(value)
            elif isinstance(value, ir.Stmt):
                new = self.statement(value)
            elif isinstance(value, list) and value and isinstance(value[0], ir.Node):
                new = [self.statement(v) if isinstance(v, ir.Stmt) else self.expression(v) for v in value]
                if all(a is b for a, b in zip(new, value)):
                    new = value
            else:
                continue
            if new is not value:
                changes[name] = new
        return ir.replace(s, **changes) if changes else s


def _runtime_type(e) -> bool:
    """An operand an identity function can take: a scalar, vector or matrix of a type WGSL names
    (abstract literals get the type the checker gave them)."""
    t = e.type
    return t in ("float", "int", "uint", "bool") or is_vector(t) or is_matrix(t)
