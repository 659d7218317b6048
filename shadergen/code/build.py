"""Building generated code in the IR: expressions by small constructors, statements through a
Builder whose blocks are context managers (an exception can never leave a block open).

Generated code is built untyped where a node's type is obvious from its parts and typed by the
checker with the library (code/check.py) before the passes run: the generator names what it
means (a call of `normalize`, a uniform, a local) and never how a target writes it.
"""
from contextlib import contextmanager

from . import ir


def name(text: str, kind: str = "local", type: str | None = None) -> ir.Name:
    return ir.Name(text, kind, type=type)


def call(function: str, *args: ir.Expr) -> ir.Call:
    return ir.Call(function, list(args))


def construct(type: str, *args: ir.Expr) -> ir.Construct:
    return ir.Construct(type, list(args))


def field(base: ir.Expr, member: str) -> ir.Field:
    return ir.Field(base, member)


def binary(op: str, left: ir.Expr, right: ir.Expr) -> ir.Binary:
    return ir.Binary(op, left, right)


def unary(op: str, operand: ir.Expr) -> ir.Unary:
    return ir.Unary(op, operand)


def select(condition: ir.Expr, if_true: ir.Expr, if_false: ir.Expr) -> ir.Select:
    return ir.Select(condition, if_true, if_false)


def convert(type: str, operand: ir.Expr) -> ir.Convert:
    return ir.Convert(type, operand)


def index(base: ir.Expr, at: ir.Expr) -> ir.Index:
    return ir.Index(base, at)


def number(value: float) -> ir.Literal:
    return ir.Literal(float(value), None, type="float")


def integer(value: int) -> ir.Literal:
    return ir.Literal(int(value), None, type="int")


def boolean(value: bool) -> ir.Literal:
    return ir.Literal(bool(value), None, type="bool")


def all_of(conditions: list[ir.Expr]) -> ir.Expr:
    out = conditions[0]
    for c in conditions[1:]:
        out = binary("&&", out, c)
    return out


def any_of(conditions: list[ir.Expr]) -> ir.Expr:
    out = conditions[0]
    for c in conditions[1:]:
        out = binary("||", out, c)
    return out


class Builder:
    """Statements in order, into the innermost open block."""

    def __init__(self):
        self.root: list[ir.Stmt] = []
        self._open = [self.root]

    @property
    def statements(self) -> list[ir.Stmt]:
        return self._open[-1]

    def add(self, statement: ir.Stmt) -> None:
        self._open[-1].append(statement)

    def declare(self, type: str, variable: str, init: ir.Expr | None = None) -> ir.Name:
        self.add(ir.Declare(type, variable, init, False))
        return name(variable, "local", type)

    def assign(self, target: ir.Expr, value: ir.Expr, op: str = "=") -> None:
        self.add(ir.Assign(op, target, value))

    def call(self, function: str, *args: ir.Expr) -> None:
        self.add(ir.ExprStatement(call(function, *args)))

    def comment(self, text: str) -> None:
        self.add(ir.Comment([text]))

    def ret(self, value: ir.Expr | None = None) -> None:
        self.add(ir.Return(value))

    @contextmanager
    def _into(self, body: list[ir.Stmt]):
        self._open.append(body)
        try:
            yield
        finally:
            self._open.pop()

    @contextmanager
    def scope(self, comment: str | None = None):
        """A bare `{ }` block: what is declared inside stays local to it."""
        if comment:
            self.comment(comment)
        body: list[ir.Stmt] = []
        self.add(ir.Block(body, True))
        with self._into(body):
            yield

    @contextmanager
    def chain(self):
        """An if/else chain: `with b.chain() as c:` then `with c.clause(condition):` per clause,
        the last one's condition None for a final else."""
        yield Chain(self)

    @contextmanager
    def count_loop(self, variable: str, bound: ir.Expr):
        """`for` an int from 0 up to `bound`."""
        body: list[ir.Stmt] = []
        i = name(variable, "local", "int")
        self.add(ir.For(ir.Declare("int", variable, integer(0), False), binary("<", i, bound),
                        ir.Assign("++", i, None), ir.Block(body, True)))
        with self._into(body):
            yield

    def block(self) -> ir.Block:
        return ir.Block(self.root, True)


class Chain:
    def __init__(self, builder: Builder):
        self.builder = builder
        self.last: ir.If | None = None  # the chain's last `if`, which the next clause continues

    @contextmanager
    def clause(self, condition: ir.Expr | None):
        body: list[ir.Stmt] = []
        block = ir.Block(body, True)
        if self.last is None:
            if condition is None:
                raise ValueError("an else needs an if before it")
            self.last = ir.If(condition, block, None)
            self.builder.add(self.last)
        elif condition is None:
            self.last.other = block
        else:
            following = ir.If(condition, block, None)
            self.last.other = ir.Block([following], False)
            self.last = following
        with self.builder._into(body):
            yield


def function(returns: str, function_name: str, params: list[tuple[str, str, str]], body: ir.Block,
             comment: list[str] | None = None) -> ir.Function:
    """A generated function; params (qualifier, type, name)."""
    return ir.Function(returns, function_name, [ir.Param(q, t, n, False) for q, t, n in params], body,
                       comment=comment)
