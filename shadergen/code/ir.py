"""The typed intermediate representation of shader code: library functions and generated code alike.

Every library source file is parsed into these nodes once per library (code/parse.py), typed once
(code/check.py), and kept on disk with the library cache (pickled: plain classes with __slots__).
The generator builds the same nodes for what it writes itself (main, nodegraph functions, the
light dispatch); passes (code/passes/) read and rebuild them; each target prints them
(targets/<name>/printer.py). No node holds text of any target: a type is an IR type name, an
operator is the IR's operator, a literal is a value.

IR types are names: the scalars `bool`, `int`, `uint`, `float`; vectors `vec2..4`, `ivec2..4`,
`uvec2..4`, `bvec2..4`; matrices `mat2..4` (square, column-major); `sampler2D` (a texture with its
sampler); `void`; a struct's own name; an array `T[N]` (`T[]` before its size is known). They are
spelled as GLSL spells them because the libraries are written that way; a printer maps each one.

Operators: unary `-`, `!`, `~`; binary `+ - * / %`, `== != < > <= >=`, `&& ||`, `& | ^ << >>`;
assignment `=`, `+=`, `-=`, `*=`, `/=`, `%=`, `&=`, `|=`, `^=`, `<<=`, `>>=`, and `++`/`--` (value
None). `*` between a matrix and a vector (either order) or two matrices is the linear-algebra
product; everywhere else operators are component-wise.

Nodes compare by identity; passes never mutate a node another item may share: they build new ones
(`replace`). Every expression has `type` (None until checked); every node has `where`, the
(file, line, column) it was parsed from, or None for generated code.
"""

__all__ = [
    "Expr", "Literal", "Name", "Placeholder", "Call", "Construct", "Field", "Index", "Unary", "Binary",
    "Select", "Convert",
    "Stmt", "Declare", "Assign", "ExprStatement", "If", "For", "While", "Return", "Break", "Continue",
    "Discard", "Block", "Comment", "Section",
    "Item", "Struct", "Constant", "Global", "Param", "Function", "Module",
    "replace", "copy_tree", "children", "walk", "shape",
]


def initializer(fields: tuple[str, ...], keywords: tuple, initial: tuple):
    """An __init__ taking `fields` positionally and `keywords` ((slot, default) pairs) by name,
    and setting `initial` slots to their values: each assigned directly, since requests make
    nodes by the thousand and a loop over a class's fields costs several times as much."""
    params = ", ".join(("self", *fields, *(["*"] if keywords else []), *(f"{k}={d!r}" for k, d in keywords)))
    body = [f"self.{f} = {f}" for f in fields] + [f"self.{k} = {k}" for k, _ in keywords]
    body += [f"self.{k} = {v!r}" for k, v in initial] or ["pass"]
    namespace: dict = {}
    exec(f"def __init__({params}):\n    " + "\n    ".join(body), namespace)  # noqa: S102 (our own text)
    return namespace["__init__"]


def _first_init(cls):
    """An __init__ that makes the class's own (initializer) when its first node is made, and puts it
    in its place: compiling one costs a tenth of a millisecond, and a process that reads its library
    from the cache makes nodes of about half of the classes (the parser's, such as Section, For or
    Placeholder, are made only where a library is parsed)."""
    def __init__(self, *args, **kwargs):
        made = cls.__init__ = initializer(cls.FIELDS, cls.KEYWORDS, cls.INITIAL)
        made(self, *args, **kwargs)
    return __init__


# Fields that hold a name, a type, an operator, a flag or lines of text, never a node: walks skip them
# (a walk over generated code runs per request, and most of a node's fields are these)
VALUE_FIELDS = frozenset({"name", "kind", "type", "op", "text", "const", "scoped", "macro", "defined", "lines",
                          "qualifier", "returns", "block", "members"})


class Node:
    __slots__ = ("where",)
    FIELDS: tuple[str, ...] = ()  # the child-bearing and value fields, in order (replace, children)
    CHILDREN: tuple[str, ...] = ()  # the FIELDS that may hold nodes (or lists of them), in order
    KEYWORDS: tuple = (("where", None),)  # slots given by keyword, with their defaults
    INITIAL: tuple = ()  # slots every new node starts with, and their values

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "__init__" not in cls.__dict__:
            cls.__init__ = _first_init(cls)
        leaves = VALUE_FIELDS | ({"value"} if cls.__name__ == "Literal" else set())
        cls.CHILDREN = tuple(f for f in cls.FIELDS if f not in leaves)

    def __getstate__(self):
        # (None, slots): pickle and copy set the slots themselves, without a Python call per
        # node (a fifth of the library cache's load time); an item's `pending` is the cache's own
        return None, {name: getattr(self, name) for cls in type(self).__mro__ for name in getattr(cls, "__slots__", ())
                      if name != "pending"}

    def __repr__(self):
        inner = ", ".join(f"{n}={getattr(self, n)!r}" for n in self.FIELDS)
        return f"{type(self).__name__}({inner})"


# -- expressions -----------------------------------------------------------------------------------
class Expr(Node):
    __slots__ = ("type",)
    KEYWORDS = (("type", None), ("where", None))


class Literal(Expr):
    """A constant: `value` a bool, int or float (`type` says which IR scalar). `text`, when parsed
    from a library, is how the source spelled it (`1e-20`, `0.5`), which printers may keep."""
    __slots__ = ("value", "text")
    FIELDS = ("value", "text")


class Name(Expr):
    """A variable, parameter, global, uniform or constant, by name. `kind` (set by the checker or
    by the generator): "local", "param", "global" (a library constant or global), "uniform",
    "vertexdata", "input" (a stage input), "output" (a stage output), "builtin" (a target's own
    variable, e.g. the position output)."""
    __slots__ = ("name", "kind")
    FIELDS = ("name", "kind")


class Placeholder(Expr):
    """`{{name}}` of an inline implementation: the node input `name`, substituted when instantiated."""
    __slots__ = ("name",)
    FIELDS = ("name",)


class Call(Expr):
    """A call of a function: a library or generated function (`callee` the Function after checking)
    or a built-in (`callee` None, `builtin` True). `args` are expressions; an `out`/`inout`
    parameter's argument is an lvalue expression."""
    __slots__ = ("name", "args", "callee", "builtin")
    FIELDS = ("name", "args")
    KEYWORDS = Expr.KEYWORDS + (("callee", None), ("builtin", False))


class Construct(Expr):
    """A value of `type` built from `args`: a vector or matrix constructor (with GLSL's rules:
    one scalar fills every component; components taken in order from the arguments), a struct in
    member order, or an array (`type` `T[N]`). `exact`: every argument is already of the type
    its place takes (a value's constructor, code/values.py), so checking would change nothing."""
    __slots__ = ("args", "exact")
    FIELDS = ("args",)
    KEYWORDS = Expr.KEYWORDS + (("exact", False),)

    def __init__(self, type, args, where=None, exact=False):
        self.args = args
        self.type = type
        self.where = where
        self.exact = exact


class Field(Expr):
    """`base.name`: a struct member, or (`swizzle` True after checking) vector components such as
    `xyz` or `rg` (always written with xyzw letters once checked)."""
    __slots__ = ("base", "name", "swizzle")
    FIELDS = ("base", "name")
    KEYWORDS = Expr.KEYWORDS + (("swizzle", False),)


class Index(Expr):
    __slots__ = ("base", "index")
    FIELDS = ("base", "index")


class Unary(Expr):
    __slots__ = ("op", "operand")
    FIELDS = ("op", "operand")


class Binary(Expr):
    __slots__ = ("op", "left", "right")
    FIELDS = ("op", "left", "right")


class Select(Expr):
    """`condition ? if_true : if_false`."""
    __slots__ = ("condition", "if_true", "if_false")
    FIELDS = ("condition", "if_true", "if_false")


class Convert(Expr):
    """`operand` as `type`: a conversion (int to float), or a scalar spread over a vector's
    components. `implicit`: the checker inserted it where the source relied on an implicit
    conversion; a target that converts implicitly (GLSL) need not write it, one that does not
    (WGSL) must."""
    __slots__ = ("operand", "implicit")
    FIELDS = ("operand",)

    def __init__(self, type, operand, implicit=False, where=None):
        self.operand = operand
        self.type = type
        self.implicit = implicit
        self.where = where


# -- statements ------------------------------------------------------------------------------------
class Stmt(Node):
    """A statement. `comment`: a comment after it on its line, kept by printers."""
    __slots__ = ("comment",)
    KEYWORDS = (("where", None), ("comment", None))


class Declare(Stmt):
    """`type name = init;` (init None: declared only). `const`: never assigned again."""
    __slots__ = ("type", "name", "init", "const")
    FIELDS = ("type", "name", "init", "const")


class Assign(Stmt):
    """`target op value;`: target an lvalue (Name, Field, Index); `++`/`--` have value None."""
    __slots__ = ("op", "target", "value")
    FIELDS = ("op", "target", "value")


class ExprStatement(Stmt):
    """An expression evaluated for its effect: a call."""
    __slots__ = ("expr",)
    FIELDS = ("expr",)


class Block(Stmt):
    """Statements in order. `scoped`: a `{ }` of its own (a bare block in the source, a body);
    unscoped blocks only group (a section's statements)."""
    __slots__ = ("body", "scoped")
    FIELDS = ("body", "scoped")


class If(Stmt):
    """`if (condition) then else other`: then and other are Blocks (other None)."""
    __slots__ = ("condition", "then", "other")
    FIELDS = ("condition", "then", "other")


class For(Stmt):
    """`for (init; condition; update) body`: init a Declare or Assign (or None), update an
    Assign (or None), body a Block."""
    __slots__ = ("init", "condition", "update", "body")
    FIELDS = ("init", "condition", "update", "body")


class While(Stmt):
    __slots__ = ("condition", "body")
    FIELDS = ("condition", "body")


class Return(Stmt):
    __slots__ = ("value",)
    FIELDS = ("value",)


class Break(Stmt):
    __slots__ = ()


class Continue(Stmt):
    __slots__ = ()


class Discard(Stmt):
    __slots__ = ()


class Comment(Stmt):
    """A comment on lines of its own (one entry of `lines` per line, without `//`)."""
    __slots__ = ("lines",)
    FIELDS = ("lines",)


class Section(Stmt):
    """Code present only where `macro` is defined (`defined` True: `#ifdef`) or not (`#ifndef`),
    with `other` (an `#else`) in its place otherwise. `body` and `other` are lists of statements,
    or of items at the top level. A feature macro (`MX_FEATURE_*`) and a decided compiler macro are
    resolved by code/passes/sections.py; any other is written out by targets with a preprocessor
    and given its default (undefined) by those without. `else_branch`: the section holds the
    `else` of the `if` before it (`if (...) {...} #ifdef X else {...} #endif`), which the parser
    attaches to that `if` as its `other`, a Block holding this section."""
    __slots__ = ("macro", "defined", "body", "other", "else_branch")
    FIELDS = ("macro", "defined", "body", "other")

    KEYWORDS = Stmt.KEYWORDS + (("else_branch", False),)


# -- top-level items -------------------------------------------------------------------------------
class Item(Node):
    """A top-level definition. `comment`: the comment lines above it in the source (kept).
    `facts`: what code/facts.py read of the item, memoised on it (None until read; pickled with
    the library when read before, so a cold process need not walk the library's functions; a
    copy `replace` makes starts without: its fields may differ). Added by code/facts.py's author.
    `pending`: on an item read from the library's cache, the fields still in the file
    (code/cachefile.py: a function's facts and body, a constant's value), each read when first
    asked for; unset on any other item."""
    __slots__ = ("comment", "facts", "pending")
    KEYWORDS = (("where", None), ("comment", None))
    INITIAL = (("facts", None),)

    def __getattr__(self, name):
        # reached only where a slot is unset: a field the cache's file still holds, or a mistake
        try:
            pending = object.__getattribute__(self, "pending")
        except AttributeError:
            raise AttributeError(name) from None
        pending.restore(self, name)
        return object.__getattribute__(self, name)


class Struct(Item):
    """`members`: (type, name) each, in order."""
    __slots__ = ("name", "members")
    FIELDS = ("name", "members")


class Constant(Item):
    """A named constant: `#define NAME value` or `const T NAME = value;` (`value` an Expr, typed)."""
    __slots__ = ("type", "name", "value")
    FIELDS = ("type", "name", "value")


class Global(Item):
    """A variable every function may read: a library's global, or one the generator declares
    (uniforms, stage inputs and outputs are Globals with `kind` "uniform", "input", "output",
    "vertexdata"; `block` the variable block it belongs to, `init` a uniform's initializer)."""
    __slots__ = ("type", "name", "kind", "block", "init")
    FIELDS = ("type", "name", "kind", "block", "init")

    def __init__(self, type, name, kind="global", block=None, init=None, where=None, comment=None):
        self.type, self.name, self.kind, self.block, self.init = type, name, kind, block, init
        self.where, self.comment, self.facts = where, comment, None


class Param(Node):
    """`qualifier` "in", "out" or "inout"; `const` an in parameter declared const."""
    __slots__ = ("qualifier", "type", "name", "const")
    FIELDS = ("qualifier", "type", "name", "const")


class Function(Item):
    """`returns name(params) body`. `key` identifies an overload across the library
    (name and parameter types), which targets without overloading spell into the name."""
    __slots__ = ("returns", "name", "params", "body", "key")
    FIELDS = ("returns", "name", "params", "body")

    def __init__(self, returns, name, params, body, where=None, comment=None):
        self.returns, self.name, self.params, self.body = returns, name, params, body
        self.where, self.comment, self.facts = where, comment, None
        self.key = name + "(" + ",".join(p.type for p in params) + ")"


class Module:
    """One library source file: its items in order (Sections among them), the files it includes
    (paths, in order), and its `#pragma shadergen feature` declarations as (feature, input,
    comparison, value) tuples (features.py reads them)."""
    __slots__ = ("path", "items", "includes", "features")

    def __init__(self, path, items, includes=(), features=()):
        self.path = path
        self.items = items
        self.includes = tuple(includes)
        self.features = tuple(features)

    def __getstate__(self):
        return (self.path, self.items, self.includes, self.features)

    def __setstate__(self, state):
        self.path, self.items, self.includes, self.features = state


# -- traversal -------------------------------------------------------------------------------------
def children(node) -> list:
    """The nodes directly inside `node`, in source order (lists flattened, values skipped)."""
    out = []
    for name in node.CHILDREN:
        value = getattr(node, name)
        if isinstance(value, Node):
            out.append(value)
        elif isinstance(value, (list, tuple)):
            out.extend(v for v in value if isinstance(v, Node))
    return out


def walk(node):
    """`node` and every node inside it, depth first, in source order."""
    stack = [node]
    while stack:
        n = stack.pop()
        yield n
        stack.extend(reversed(children(n)))


_SLOTS: dict[type, tuple[str, ...]] = {}


def slots_of(cls: type) -> tuple[str, ...]:
    """Every slot of a node class, its bases' included (an item's `facts` left out: a copy's are
    read again, Item's doc; and its `pending`, the cache's)."""
    found = _SLOTS.get(cls)
    if found is None:
        found = _SLOTS[cls] = tuple(name for c in cls.__mro__ for name in getattr(c, "__slots__", ())
                                    if name not in ("facts", "pending"))
    return found


_STRUCTURE: dict[type, tuple[str, ...]] = {}


def structure_slots(cls: type) -> tuple[str, ...]:
    """The slots that make a node what it is (`shape`, code/statements.py keys): every slot but
    its `where` (where a node was written does not change what it does) and a call's `callee`
    (which its name and its arguments' types decide)."""
    found = _STRUCTURE.get(cls)
    if found is None:
        found = _STRUCTURE[cls] = tuple(name for name in slots_of(cls) if name not in ("where", "callee"))
    return found


def copy_tree(node):
    """A copy of a tree in which every node is new (the checker types a template's copy in place);
    names, numbers and a call's callee are shared. (copy.deepcopy would do, but a cold process
    imports nothing else of copy, nor of the weakref it brings: up to 4 ms under -X importtime.)"""
    new = replace(node)
    for name in type(node).CHILDREN:
        value = getattr(new, name)
        if isinstance(value, Node):
            setattr(new, name, copy_tree(value))
        elif isinstance(value, list):
            setattr(new, name, [copy_tree(v) if isinstance(v, Node) else v for v in value])
    return new


def replace(node, **changes):
    """A copy of `node` with some fields changed (passes build new nodes; shared ones stay)."""
    cls = type(node)
    new = object.__new__(cls)
    for name in slots_of(cls):
        setattr(new, name, changes[name] if name in changes else getattr(node, name))
    if isinstance(new, Item):
        new.facts = changes.get("facts")
    return new


def shape(value):
    """A hashable value equal for two trees exactly when they are built alike: every structure
    slot of every node (structure_slots). Numbers keep their Python type, since 1 == 1.0 == True."""
    if isinstance(value, Node):
        return (type(value),) + tuple(shape(getattr(value, name)) for name in structure_slots(type(value)))
    if isinstance(value, (list, tuple)):
        return tuple(shape(v) for v in value)
    if isinstance(value, (bool, int, float)):
        return type(value), value
    return value
