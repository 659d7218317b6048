"""Main's statements, typed, read and printed once per library for each shape they are built in.

A node's call (`mx_noise3d_float(n3_out, ...)`), its output's declaration, a shading context's
scope recur across the materials of a library and across the requests of one material: a
statement built alike from alike parts is typed alike (the library decides its calls), has the
same facts and prints the same. So each statement of main the generator builds is looked up by its
`key`, its structure (the structure slots of every node, as ir.shape reads them), where a
statement typed in an earlier request (`Shared.remember`) takes its place: the checker only
declares what it declares (code/generated.py), its facts are read once (code/facts.py), and a
printer keeps its lines per target and depth. A statement that misses is looked for statement by
statement inside it (a scope of which one lobe changed keeps the others).

A statement whose typing could depend on anything but its structure and the library has no key:
one that reads a name the generator left untyped (the checker types it by the scope). A call of a
function the request wrote itself (a nodegraph's body, the light dispatch) is keyed by that
function's structure, and the statements of its body are looked up as main's are. Shared
statements are never changed: the checker skips them and the passes never edit main or the
generated functions.

Most of main is a node's call, or its output's declaration with the node's inline expression,
built from names and values. Those the generator looks up before it builds them
(EmitContext.add_alike): what a statement is built from (`alike_key`: its text, names and values)
leads to the number its statement had (`Memo.alike`), and an earlier request's typed statement
of that number is taken as it is, neither built nor keyed again.
"""
import itertools

from . import ir
from .facts import collect

MAX_MEMO = 32768  # statements kept per library (then no more are: as its other memos)
MAX_KEYS = 65536  # statement structures numbered per library


class Entry:
    """A statement typed in an earlier request, with its facts (read when first shared) and its
    lines, per (printer key, depth)."""
    __slots__ = ("statement", "facts", "lines")

    def __init__(self, statement):
        self.statement = statement
        self.facts = None
        self.lines: dict = {}


class Memo:
    """One per library (CodeLibrary.statements): `numbers`, each statement structure seen (its
    key) -> its number, and `entries`, number -> Entry. A statement's key holds the numbers of the
    statements inside it, not their keys: a key is hashed once, not again with each block around it."""

    def __init__(self):
        self.numbers: dict[tuple, int] = {}
        self.entries: dict[int, Entry] = {}
        self.counter = itertools.count()  # (next() and setdefault: two threads never share a number)
        # what a statement of main is built from (EmitContext.add_alike: `alike_key`) -> its number,
        # so that the generator takes a typed one instead of building it again
        self.alike: dict[tuple, int] = {}

    def built_alike(self, key: tuple) -> tuple | None:
        """(statement, number) of the statement an earlier request built from `key`'s parts and
        typed; None if none was."""
        number = self.alike.get(key)
        entry = self.entries.get(number) if number is not None else None
        return (entry.statement, number) if entry is not None else None

    def share(self, main: ir.Block, generated_functions, found=None, fresh=()) -> tuple[ir.Block, "Shared"]:
        """`main` with the entries of alike statements in its place, outermost first (main
        itself, when a request built one alike before; its lists are this request's own to
        change); the others are this request's fresh statements, remembered once typed
        (`Shared.remember`). `found`: id -> number of the statements the generator took from
        the memo (`built_alike`); `fresh`: (what it was built from, statement) of those it built."""
        generated: dict[str, list] = {}
        for f in generated_functions:
            generated.setdefault(f.name, []).append(f)
        keys = Keys(generated, self)
        if found:
            keys.found.update(found)
        keys.statement(main)
        alike = self.alike
        for key, s in fresh:
            number = keys.found.get(id(s))
            if number is not None and len(alike) < MAX_KEYS:
                alike[key] = number
        shared = Shared(self)
        body = [main]
        shared.place(body, keys.found)
        for f in generated_functions:  # what main calls of them (the light dispatch, a nodegraph's body)
            if id(f.body) in keys.found:
                shared.place(f.body.body, keys.found)
        number = keys.found.get(id(main))
        if number is not None:  # main has a structure: so has the code the passes keep of it
            try:
                shared.key = number, tuple([keys.function(name) for name in generated])
            except Unkeyed:
                pass
        return body[0], shared


class Shared:
    """What one request shares: `hits` (id(statement) -> Entry) for the checker, the facts and
    the printers; `fresh`, the (key, statement) pairs of its own, remembered once typed; `key`,
    the structure of main and of the functions the request wrote (main's by its number), or None
    where one has none."""
    __slots__ = ("memo", "hits", "fresh", "key")

    def __init__(self, memo: Memo):
        self.memo = memo
        self.hits: dict[int, Entry] = {}
        self.fresh: list = []
        self.key = None

    def place(self, body: list, found: dict) -> None:
        entries = self.memo.entries
        for i, s in enumerate(body):
            key = found.get(id(s))
            entry = entries.get(key) if key is not None else None
            if entry is not None:
                body[i] = entry.statement
                self.hits[id(entry.statement)] = entry
                continue
            if key is not None:
                self.fresh.append((key, s))
            for inner in inner_bodies(s):
                self.place(inner, found)

    def remember(self) -> None:
        """The fresh statements, typed now, become entries (and this request's lines are kept)."""
        entries = self.memo.entries
        for key, s in self.fresh:
            if len(entries) >= MAX_MEMO:
                break
            entry = entries.get(key)
            if entry is None:
                entry = entries[key] = Entry(s)
            self.hits.setdefault(id(entry.statement), entry)
        self.fresh = []

    def facts_of(self, statement):
        """The facts of a shared statement (code/facts.py collect)."""
        entry = self.hits[id(statement)]
        if entry.facts is None:
            entry.facts = collect([statement])
        return entry.facts


def leaf_key(n) -> object | None:
    """The key of a node that holds no other node's structure: a typed name by its name, kind and
    type; a literal by its value and text; a value by its identity (code/values.py makes one node
    for an equal value). None for an untyped name (the checker types it by the scope) and for any
    other node."""
    cls = n.__class__
    if cls is ir.Name:
        return (cls, n.name, n.kind, n.type) if n.type is not None else None
    if cls is ir.Literal:
        value = n.value
        return cls, value.__class__, value, n.type, n.text  # 1 == 1.0 == True, printed apart
    if cls is ir.Construct and n.exact:
        return n
    return None


def alike_key(parts: tuple) -> tuple | None:
    """What a statement is built from as a key (EmitContext.add_alike): its text and the
    expressions it reads, each by its `leaf_key`; None when one has none (built from other
    expressions: keyed once built)."""
    out = []
    for p in parts:
        if p.__class__ is str or p is None:
            out.append(p)
            continue
        key = leaf_key(p)
        if key is None:
            return None
        out.append(key)
    return tuple(out)


CONTAINERS = frozenset({ir.If, ir.For, ir.While})  # statements with blocks of their own


def inner_blocks(s) -> list:
    """A container's blocks."""
    if s.__class__ is ir.If:
        return [s.then] if s.other is None else [s.then, s.other]
    return [s.body]


def inner_bodies(s) -> list:
    """The statement lists inside a statement, whose statements are looked up one by one."""
    if s.__class__ is ir.Block:
        return [s.body]
    return [b.body for b in inner_blocks(s)] if s.__class__ in CONTAINERS else []


UNKEYED = ()  # the key of a statement whose typing may depend on more than its structure and the library


class Unkeyed(Exception):
    """Raised inside a statement's key: it has none."""


class Keys:
    """The numbers of a tree's statements (`found`: id -> number, for every statement that has
    one), each key computed once from its parts'."""

    def __init__(self, generated: dict, memo: Memo):
        self.numbers, self.counter = memo.numbers, memo.counter
        self.found: dict[int, int] = {}
        self.node, self.function = structure(generated, self)

    def statements(self, body: list):
        keys = [self.statement(s) for s in body]  # every one: an inner statement may be shared alone
        return UNKEYED if UNKEYED in keys else tuple(keys)

    def statement(self, s):
        number = self.found.get(id(s))
        if number is not None:  # a statement main holds twice (a closure's call in each context)
            return number
        cls = s.__class__
        if cls is ir.Block:
            inner = self.statements(s.body)
            key = UNKEYED if inner is UNKEYED else (cls, inner, s.scoped, s.comment)
        elif cls in CONTAINERS and UNKEYED in [self.statement(b) for b in inner_blocks(s)]:
            key = UNKEYED  # (its blocks keyed as statements first: theirs are looked up too)
        else:
            try:
                key = self.node(s)
            except Unkeyed:
                key = UNKEYED
        if key is UNKEYED:
            return UNKEYED
        number = self.numbers.get(key)
        if number is None:
            if len(self.numbers) >= MAX_KEYS:
                return UNKEYED
            number = self.numbers.setdefault(key, next(self.counter))
        self.found[id(s)] = number
        return number


def structure(generated: dict, keys: "Keys"):
    """(node -> its structure, name -> the structure of the request's functions of that name):
    a node's is a tuple of its class and its fields' (a statement's block by its key, keyed
    first); both raise Unkeyed. `generated`: name -> the functions the request wrote, keyed by
    their structure when a statement calls them. (Closures over their names: `node` runs for
    every node of main in every request.)"""
    Name, Literal, Construct, Call, Block, Node = ir.Name, ir.Literal, ir.Construct, ir.Call, ir.Block, ir.Node
    slots, found, functions = ir.structure_slots, keys.found, {}

    def function(name: str):
        if name not in functions:
            functions[name] = UNKEYED  # (a call inside itself: a recursion the checker refuses)
            key = tuple((fn.returns, fn.name, tuple([node(p) for p in fn.params]), keys.statement(fn.body))
                        for fn in generated[name])
            if any(body is UNKEYED for *_, body in key):
                raise Unkeyed
            functions[name] = key
        if functions[name] is UNKEYED:
            raise Unkeyed
        return functions[name]

    def node(n):
        cls = n.__class__
        if cls is Name or cls is Literal or (cls is Construct and n.exact):
            key = leaf_key(n)
            if key is None:
                raise Unkeyed  # an untyped name
            return key
        if cls is Call and n.name in generated:
            # the request's own function, by its structure: a call is typed by what it calls
            return cls, function(n.name), tuple([node(x) for x in n.args])
        out = [cls]
        for name in slots(cls):
            v = getattr(n, name)
            c = v.__class__
            if c is list:  # nodes (arguments, statements) or text (a comment's lines)
                v = tuple([node(x) if isinstance(x, Node) else x for x in v])
            elif c is Block:
                v = found[id(v)]  # a statement's block, numbered first (Keys.statement)
            elif isinstance(v, Node):
                v = node(v)
            out.append(v)
        return tuple(out)
    return node, function
