"""Typing the code the generator writes (main, nodegraph functions, the light dispatch) against
the library's: the same checker as the library's sources (check.py), with three differences. An
expression the generator made typed is taken as it is (values, typed templates); the generator
names its stage variables itself (a uniform, a stage input or output, vertex data, the target's
position output) and gives them their IR type, which the checker keeps; and those variables may
be assigned. The library's symbol table is shared by every request and never
changed: the generated functions join a copy of it.
"""
from . import ir
from .check import Checker, Symbols

GENERATED_KINDS = frozenset({"uniform", "input", "output", "vertexdata", "builtin"})


class GeneratedChecker(Checker):
    def expr(self, e: ir.Expr) -> ir.Expr:
        """What the generator made typed (its values, an inline template instantiated with its
        inputs' types: code/library.py's `expression`) is typed already, all the way down; a
        constructor has its type from the start, and is checked for its arguments' unless it is a
        value's (exact)."""
        if e.type is None or (e.__class__ is ir.Construct and not e.exact):
            return super().expr(e)
        return e

    def expr_Name(self, e):
        if e.kind in GENERATED_KINDS and e.type is not None and not any(e.name in s for s in self.scopes):
            e.type = self.resolve_type(e.type, e)
            return e
        return super().expr_Name(e)

    def is_lvalue(self, e: ir.Expr) -> bool:
        root = e
        while isinstance(root, (ir.Field, ir.Index)):
            root = root.base
        return super().is_lvalue(e) or (isinstance(root, ir.Name) and root.kind in ("output", "vertexdata", "builtin"))


def check_generated(library, functions: list[ir.Function], blocks: list[ir.Block], externals: dict[str, str]) -> None:
    """Types generated `functions` and root `blocks` in place; `externals`: the stage's variables
    (name -> IR type), which the library's own names take precedence over."""
    base = library.symbols
    symbols = Symbols(base.structs, base.aliases, dict(base.functions), base.values)
    checker = GeneratedChecker("generated code", symbols, externals)
    for fn in functions:
        fn.returns = checker.resolve_type(fn.returns, fn)
        for p in fn.params:
            p.type = checker.resolve_type(p.type, p)
        fn.key = fn.name + "(" + ",".join(p.type for p in fn.params) + ")"
        symbols.functions[fn.name] = dict(symbols.functions.get(fn.name, {}), **{fn.key: fn})
    for fn in functions:
        checker.function(fn)
    for block in blocks:
        checker.scopes = [{}]
        checker.returns = "void"
        checker.block(block)
        checker.scopes = []
