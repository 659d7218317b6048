"""Typing the code the generator writes (main, nodegraph functions, the light dispatch) against
the library's: the same checker as the library's sources (check.py), with three differences. An
expression the generator made typed is taken as it is (values, typed templates); the generator
names its stage variables itself (a uniform, a stage input or output, vertex data, the target's
position output) and gives them their IR type, which the checker keeps; and those variables may
be assigned. The library's symbol table is shared by every request and never
changed: the generated functions join a copy of it.

What depends only on the library is worked out once per library (`CodeLibrary.generated`): a
type as written to its IR type, and the overload a call of a library function resolves to for
its arguments' types; a request then pays for what it adds.
"""
from . import ir
from .check import Checker, Symbols

GENERATED_KINDS = frozenset({"uniform", "input", "output", "vertexdata", "builtin"})


class GeneratedChecker(Checker):
    def __init__(self, path: str, symbols: Symbols, externals: dict[str, str], library_functions: dict,
                 memo: tuple[dict, dict], shared=frozenset()):
        super().__init__(path, symbols, externals)
        self.shared = shared  # ids of statements typed in an earlier request (code/statements.py)
        self.typed: set[int] = set()  # ids of statements typed in this one
        self.library_functions = library_functions  # the library's own families (name -> key -> Function)
        # the library's: type -> IR type; (name, argument types) -> (Function, out positions, converts)
        self.types, self.overloads = memo

    def resolve_type(self, t: str, node) -> str:
        found = self.types.get(t)
        if found is None:
            found = self.types[t] = super().resolve_type(t, node)  # an unknown type raises, and is not kept
        return found

    def overload(self, e: ir.Call, family: list[ir.Function]) -> tuple[ir.Function, list[ir.Expr]]:
        """The library's overload for these argument types, resolved once per library (with whether
        an argument converts and which are out or inout: most calls pass every argument as it is);
        a family a generated function joined (its name is the library's too) is resolved each time."""
        if self.symbols.functions.get(e.name) is not self.library_functions.get(e.name):
            return super().overload(e, family)
        args = e.args
        key = (e.name, tuple([a.type for a in args]))
        found = self.overloads.get(key)
        if found is None:
            best, converted = super().overload(e, family)  # no overload, or an ambiguous call, raises
            writes = tuple(i for i, p in enumerate(best.params) if p.qualifier != "in")
            self.overloads[key] = best, writes, any(c is not a for c, a in zip(converted, args))
            return best, converted
        best, writes, converts = found
        for i in writes:
            if not self.is_lvalue(args[i]):
                p = best.params[i]
                raise self.error(args[i], f"the {p.qualifier} argument '{p.name}' of '{e.name}' is not a variable")
        if not converts:
            return best, args
        return best, [self.convert(a, p.type) for p, a in zip(best.params, args)]

    def expr(self, e: ir.Expr) -> ir.Expr:
        """What the generator made typed (its values, an inline template instantiated with its
        inputs' types: code/library.py's `expression`) is typed already, all the way down; a
        constructor has its type from the start, and is checked for its arguments' unless it is a
        value's (exact)."""
        if e.type is None or (e.__class__ is ir.Construct and not e.exact):
            return Checker.expr(self, e)
        return e

    def statement(self, s) -> None:
        """A declaration of a variable of its typed value's type (most of main: a node's output),
        the type one the library has resolved to itself, only enters its scope: what the
        library's rules would do to it changes nothing. Anything else is checked by them."""
        if id(s) in self.shared or id(s) in self.typed:  # typed before: it only declares what it declares
            if s.__class__ is ir.Declare:
                self.scopes[-1][s.name] = (s.type, "local")
            return
        self.typed.add(id(s))  # (main may hold a statement twice: a closure's call in each context)
        init = s.init if s.__class__ is ir.Declare else None
        if init is not None and init.type == s.type and (init.__class__ is not ir.Construct or init.exact) \
                and self.types.get(s.type) == s.type:
            self.scopes[-1][s.name] = (s.type, "local")
            return
        super().statement(s)

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


def check_generated(library, functions: list[ir.Function], blocks: list[ir.Block], externals: dict[str, str],
                    shared=frozenset()) -> None:
    """Types generated `functions` and root `blocks` in place; `externals`: the stage's variables
    (name -> IR type), which the library's own names take precedence over; `shared`: ids of the
    blocks' statements typed before, which are not typed again."""
    base = library.symbols
    # the generated functions join a copy of the library's table (none: the table itself, unchanged)
    symbols = Symbols(base.structs, base.aliases, dict(base.functions) if functions else base.functions, base.values)
    checker = GeneratedChecker("generated code", symbols, externals, base.functions, library.generated, shared)
    for fn in functions:
        fn.returns = checker.resolve_type(fn.returns, fn)
        for p in fn.params:
            p.type = checker.resolve_type(p.type, p)
        fn.key = fn.name + "(" + ",".join(p.type for p in fn.params) + ")"
        symbols.functions[fn.name] = dict(symbols.functions.get(fn.name, {}), **{fn.key: fn})
    for fn in functions:
        checker.function(fn)
    for block in blocks:
        if id(block) in shared:
            continue
        checker.scopes = [{}]
        checker.returns = "void"
        checker.block(block)
        checker.scopes = []
