"""What the passes need to know of an item of shader code, read once per item from its IR.

Library items are parsed and checked once per library and recur in every request (the sections
pass hands back the same resolved copy for the same decisions), so `facts(item)` is memoised on
the item (ir.Item.facts: read once per process, or once per library where the library's cache is
written after reading them; a rebuilt item is a new node with facts of its own). Generated
code (main, nodegraph functions) is read with `collect`, unmemoised: it is new in every request.

The facts are exact on the typed IR: a call names the Function the checker resolved, a member is
(struct, member) by the type of the value it is read from, a name is a global, constant or uniform
by the kind the checker gave it. An expression the checker did not type (type None) counts for
every struct with that member name, and a Name without a kind for any item of that name: either
only keeps more.
"""
from collections import Counter, namedtuple
from functools import lru_cache

from . import ir

SCALARS = ("bool", "int", "uint", "float")
BUILTIN_TYPES = frozenset(SCALARS + ("void", "sampler2D")
                          + tuple(f"{p}vec{n}" for p in ("", "i", "u", "b") for n in (2, 3, 4))
                          + tuple(f"mat{n}" for n in (2, 3, 4)))
# Built-ins that take screen-space derivatives: explicitly, or for the level of detail of a lookup
# that does not give one (texture, textureOffset, textureProj... choose theirs from derivatives).
DERIVATIVE_BUILTINS = frozenset({
    "dFdx", "dFdy", "fwidth", "dFdxFine", "dFdyFine", "dFdxCoarse", "dFdyCoarse", "fwidthFine", "fwidthCoarse",
    "texture", "textureOffset", "textureProj", "textureProjOffset", "textureQueryLod"})
# Built-ins that write through an out parameter besides returning a value.
WRITING_BUILTINS = frozenset({"modf", "frexp", "uaddCarry", "usubBorrow", "umulExtended", "imulExtended"})
LOCAL_KINDS = frozenset({"local", "param"})
INTERFACE_KINDS = frozenset({"uniform", "input", "output", "vertexdata"})  # variables a client or a stage binds

# Store: an assignment to a member (`lobe.frame = ...;`, `lobe.Vt.z = ...;`, `a[i].m += ...;`):
# `members` the (struct, member) pairs its target writes into (every member on the target's path),
# `occurrences` every member of the statement (target and value, a Counter), `removable` whether
# the statement does nothing else (no call that writes through a parameter or outside the function).
Store = namedtuple("Store", "statement members occurrences removable")


class Facts:
    """What one item (or a set of root nodes) uses and does.

    callees: the Functions it calls, first call first; calls: their keys; builtins: the built-in
    functions it calls; names: the names it reads that are not its locals or parameters (globals,
    constants, uniforms, stage inputs; and identifiers in array sizes of its types); uniforms: those
    of kind "uniform"; types: the non-built-in type names it mentions (structs, aliases);
    members: every (struct, member) read or stored (a Counter of occurrences); stores: its member
    stores (Store); whole: structs whose every member it observes (built by their constructor,
    compared whole, the type of a uniform or stage variable it reads: a layout); writes_params: a
    function with an out or inout parameter; writes_outside: it assigns to a name that is not its
    own (a global, a stage output); derivatives: it calls a
    derivative built-in itself; forwards: (target Function, arguments) when the item is a function
    whose whole body is `return target(...)`, each parameter passed once in its order with the
    qualifier and type of the target's parameter it becomes, the others literals, and the return
    types equal; else None; macros: the macros its sections test.
    """
    __slots__ = ("callees", "calls", "builtins", "names", "uniforms", "types", "members", "stores", "whole",
                 "writes_params", "writes_outside", "derivatives", "forwards", "macros")

    # Pickled with the library's items (code/library.py), whose cache must be the same bytes however
    # the library was read: a set's order depends on how it was filled, so sets go as sorted tuples.
    SETS = frozenset({"builtins", "uniforms", "whole", "macros"})

    def __getstate__(self):
        state = {name: getattr(self, name) for name in self.__slots__}
        for name in self.SETS:
            state[name] = _sorted(state[name])
        state["stores"] = tuple(s._replace(members=_sorted(s.members)) for s in self.stores)
        return state

    def __setstate__(self, state):
        for name, value in state.items():
            setattr(self, name, frozenset(value) if name in self.SETS else value)
        self.stores = tuple(s._replace(members=frozenset(s.members)) for s in self.stores)


def _sorted(values) -> tuple:
    return tuple(sorted(values, key=repr))  # repr: a member's struct may be None


def facts(item: ir.Item) -> Facts:
    """The facts of a top-level item (Function, Struct, Constant, Global), memoised on it
    (ir.Item.facts; a library cache written before the slot existed reads as unread)."""
    found = getattr(item, "facts", None)
    if found is None:
        found = item.facts = _read([item], item if isinstance(item, ir.Function) else None)
    return found


def collect(nodes, shared=None) -> Facts:
    """The facts of generated code (root statements, generated functions), read each time but
    for the statements `shared` holds (code/statements.py Shared: typed in an earlier request, their
    facts read once). Its `stores` are left empty: the passes edit library items only, never the
    roots (finding whether a store does anything else walks it again, for every member store of main)."""
    return _read(list(nodes), None, False, shared)


def _read(nodes, function: ir.Function | None, read_stores: bool = True, shared=None) -> Facts:
    """One pass over the nodes (the walk is inlined: facts of a library's functions are read on a
    cold process's first request, where a generic walk costs several times as much); a shared
    statement's facts join as they were read once."""
    callees: dict[int, ir.Function] = {}
    builtins, names, uniforms, mentioned = set(), {}, set(), {}
    members: Counter = Counter()
    stores, whole, macros = [], set(), set()
    writes_outside = False
    stack = list(nodes)
    pop, push, extend = stack.pop, stack.append, stack.extend
    Name, Literal, Construct, Node = ir.Name, ir.Literal, ir.Construct, ir.Node
    hits = shared.hits if shared is not None else {}
    parts = []  # facts of shared statements
    while stack:
        n = pop()
        cls = n.__class__
        if cls is Name:  # most nodes are names and literals, which hold no node: handled first
            type_name = n.type
            if type_name is not None:
                mentioned[type_name] = None
            kind = n.kind
            if kind not in LOCAL_KINDS:
                names.setdefault(n.name)
                if kind == "uniform":
                    uniforms.add(n.name)
                if kind in INTERFACE_KINDS and type_name:
                    whole.add(type_name.partition("[")[0])  # a uniform's or a stage variable's layout stays
            continue
        if cls is Literal:
            type_name = n.type
            if type_name is not None:
                mentioned[type_name] = None
            continue
        if cls is Construct and n.exact and n.type in BUILTIN_TYPES:
            continue  # a value's vector or matrix (code/values.py): numbers of built-in types, no fact
        if hits and id(n) in hits:
            parts.append(shared.facts_of(n))
            continue
        for field in cls.CHILDREN:
            value = getattr(n, field)
            if value.__class__ is list:
                extend(value)  # (a list field holds nodes only: statements, arguments, parameters)
            elif value is not None:
                push(value)
        type_name = getattr(n, "type", None)
        if type_name is not None:
            mentioned[type_name] = None
        if cls is ir.Call:
            if n.builtin or n.callee is None:
                builtins.add(n.name)
            else:
                callees.setdefault(id(n.callee), n.callee)
        elif cls is ir.Field:
            if not n.swizzle:
                members[(struct_of(n.base), n.name)] += 1
        elif cls is ir.Construct:
            whole.add(n.type.partition("[")[0])
        elif cls is ir.Binary:
            if n.op in ("==", "!=") and n.left.type not in BUILTIN_TYPES:
                whole.add(n.left.type)  # a struct compared whole: every member is observed
        elif cls is ir.Assign:
            root = _target_root(n.target)
            if isinstance(root, ir.Name) and root.kind not in LOCAL_KINDS:
                writes_outside = True
            stored = stored_members(n.target) if read_stores else None
            if stored:
                stores.append(Store(n, stored, _occurrences(n), not _has_effects(n)))
        elif cls is ir.Section:
            macros.add(n.macro)
        elif cls is ir.Function:
            mentioned[n.returns] = None
        elif cls is ir.Struct:
            mentioned.update((t, None) for t, _ in n.members)
    types: dict[str, None] = {}
    for type_name in mentioned:
        _note_type(type_name, types, names)
    for part in parts:
        callees.update((id(f), f) for f in part.callees)
        builtins |= part.builtins
        names.update(dict.fromkeys(part.names))
        uniforms |= part.uniforms
        types.update(dict.fromkeys(part.types))
        members.update(part.members)
        whole |= part.whole
        writes_outside = writes_outside or part.writes_outside
        macros |= part.macros
    out = Facts()
    out.callees = tuple(callees.values())
    out.calls = tuple(f.key for f in out.callees)
    out.builtins = frozenset(builtins)
    out.names = tuple(names)
    out.uniforms = frozenset(uniforms)
    out.types = tuple(types)
    out.members = members
    out.stores = tuple(stores)
    out.whole = frozenset(whole - BUILTIN_TYPES - {None})
    out.writes_params = function is not None and any(p.qualifier in ("out", "inout") for p in function.params)
    out.writes_outside = writes_outside
    out.derivatives = not DERIVATIVE_BUILTINS.isdisjoint(builtins)
    out.forwards = _forwards(function) if function is not None else None
    out.macros = frozenset(macros)
    return out


def _note_type(type_name: str, types: dict, names: dict) -> None:
    base, _, size = type_name.partition("[")
    if base not in BUILTIN_TYPES:
        types.setdefault(base)
    size = size.rstrip("]")
    if size and not size.isdigit():
        names.setdefault(size)  # `float x[MAX_LIGHT_SOURCES]`: the constant sizes the array


def struct_of(expr: ir.Expr) -> str | None:
    """The struct a member is read from (None where unchecked: any struct)."""
    return expr.type.partition("[")[0] if expr.type else None


def _target_root(target: ir.Expr) -> ir.Expr:
    while isinstance(target, (ir.Field, ir.Index)):
        target = target.base
    return target


def stored_members(target: ir.Expr) -> frozenset:
    """The (struct, member) pairs an assignment's target writes into: every member on its path
    (`a.b.c = x;` writes into a.b and into its c); empty when it stores no member."""
    found = []
    while isinstance(target, (ir.Field, ir.Index)):
        if isinstance(target, ir.Field) and not target.swizzle:
            found.append((struct_of(target.base), target.name))
        target = target.base
    return frozenset(found)


def _occurrences(statement) -> Counter:
    return Counter((struct_of(n.base), n.name) for n in ir.walk(statement)
                   if isinstance(n, ir.Field) and not n.swizzle)


def _has_effects(node) -> bool:
    """Whether evaluating `node` may change anything but what it assigns: a call of a function
    that writes through a parameter or outside itself, or of a built-in with an out parameter."""
    for n in ir.walk(node):
        if isinstance(n, ir.Call):
            if n.builtin or n.callee is None:
                if n.name in WRITING_BUILTINS:
                    return True
            elif has_effects(n.callee):
                return True
    return False


@lru_cache(maxsize=16384)
def has_effects(function: ir.Function) -> bool:
    """Whether a call of `function` may change anything but its value: it writes through an out or
    inout parameter of its own, or assigns outside itself, itself or through what it calls (a
    callee's out parameters are the caller's own variables)."""
    return facts(function).writes_params or any(facts(f).writes_outside for f in _reached([function]))


def _reached(functions) -> list:
    """`functions` and every function they call, transitively, each once (a walk with its own
    seen set: a recursion the checker let through cannot loop)."""
    seen, order, stack = set(), [], list(functions)
    while stack:
        f = stack.pop()
        if id(f) in seen:
            continue
        seen.add(id(f))
        order.append(f)
        stack.extend(facts(f).callees)
    return order


@lru_cache(maxsize=16384)
def uses_derivatives(function: ir.Function) -> bool:
    """Whether `function` takes screen-space derivatives, itself or in anything it calls (code that
    does must run in uniform control flow)."""
    return any(facts(f).derivatives for f in _reached([function]))


@lru_cache(maxsize=16384)
def reads_constant(function: ir.Function, name: str) -> bool:
    """Whether `function`, or anything it calls, reads the constant `name` (a lobe reading
    CLOSURE_TYPE_TRANSMISSION answers the transmission context)."""
    return any(name in facts(f).names for f in _reached([function]))


# -- forwarding ------------------------------------------------------------------------------------
def _forwards(function: ir.Function):
    body = [s for s in function.body.body if not isinstance(s, ir.Comment)] if function.body else []
    if len(body) != 1 or not isinstance(body[0], ir.Return) or not isinstance(body[0].value, ir.Call):
        return None
    call = body[0].value
    target = call.callee
    if call.builtin or target is None or target.returns != function.returns or len(call.args) != len(target.params):
        return None
    own = {p.name: p for p in function.params}
    passed = []
    for argument, taken in zip(call.args, target.params):
        if isinstance(argument, ir.Name) and argument.kind in ("param", None) and argument.name in own:
            mine = own[argument.name]
            if (mine.qualifier, mine.type) != (taken.qualifier, taken.type):
                return None
            passed.append(argument.name)
        elif not is_literal(argument):
            return None
    if passed != [p.name for p in function.params]:
        return None
    return target, tuple(call.args)


def is_literal(expr: ir.Expr) -> bool:
    """A literal, negated or converted (`-1.0`, an int literal the checker made a float)."""
    if isinstance(expr, ir.Convert):
        expr = expr.operand
    if isinstance(expr, ir.Unary) and expr.op == "-":
        expr = expr.operand
    return isinstance(expr, ir.Literal)


# -- closures --------------------------------------------------------------------------------------
def early_exit_at_zero_weight(function: ir.Function) -> bool:
    """Whether a lobe returns before it writes its throughput, under a condition that reads its
    `weight` parameter or a `.weight` member of a parameter: such a lobe leaves the closure's zero
    at zero weight (no response, everything let through), so removing it is exact. A lobe that
    marks itself opaque first (diffuse, conductor) is not the closure's zero. Statements are read
    in source order; a throughput written on any path before that return (or through a call that
    takes the closure as out/inout) answers False, as does a return reached unconditionally first."""
    params = {p.name: p for p in function.params}
    for stmt, conditions in _in_order(function.body.body, ()):
        if _writes_throughput(stmt, params):
            return False
        if isinstance(stmt, ir.Return):
            if any(_reads_weight(c, params) for c in conditions):
                return True
            if not conditions:
                return False  # the function ends here on every path
    return False


def _in_order(stmts, conditions):
    """(statement, conditions of the ifs and loops around it) for every statement, in source order;
    both sides of a section (code for any macros) are read."""
    for s in stmts:
        yield s, conditions
        if isinstance(s, ir.If):
            inner = conditions + (s.condition,)
            yield from _in_order(s.then.body, inner)
            if s.other is not None:
                yield from _in_order(s.other.body, inner)
        elif isinstance(s, (ir.For, ir.While)):
            yield from _in_order(s.body.body, conditions + (s.condition,))
        elif isinstance(s, ir.Block):
            yield from _in_order(s.body, conditions)
        elif isinstance(s, ir.Section):
            yield from _in_order(s.body, conditions + (None,))
            yield from _in_order(s.other or (), conditions + (None,))


def _own_expressions(stmt) -> list:
    """The expressions a statement evaluates itself (not those of the statements inside it)."""
    if isinstance(stmt, (ir.Block, ir.Section, ir.Comment)):
        return []
    if isinstance(stmt, (ir.If, ir.While)):
        return [stmt.condition]
    if isinstance(stmt, ir.For):
        return [n for s in (stmt.init, stmt.update) if s is not None for n in _own_expressions(s)] \
            + ([stmt.condition] if stmt.condition is not None else [])
    return [n for n in ir.children(stmt) if isinstance(n, ir.Expr)]


def _writes_throughput(stmt, params) -> bool:
    assigns = [s for s in ((stmt.init, stmt.update) if isinstance(stmt, ir.For) else (stmt,)) if isinstance(s, ir.Assign)]
    if any(_is_closure_store(a.target, params) for a in assigns):
        return True
    for expr in _own_expressions(stmt):
        for n in ir.walk(expr):
            if isinstance(n, ir.Call) and not n.builtin and n.callee is not None:
                if any(p.qualifier != "in" and _is_closure_store(a, params) for a, p in zip(n.args, n.callee.params)):
                    return True
    return False


def _is_closure_store(target, params) -> bool:
    """A store into a closure's throughput: `bsdf.throughput...`, or a struct the lobe writes out whole."""
    if isinstance(target, ir.Name):
        param = params.get(target.name)
        return param is not None and param.qualifier != "in" and param.type not in BUILTIN_TYPES \
            and target.kind in ("param", None)
    return any(member == "throughput" for _, member in stored_members(target))


def _reads_weight(condition, params) -> bool:
    if condition is None:
        return False
    for n in ir.walk(condition):
        if isinstance(n, ir.Name) and n.name == "weight" and n.name in params and n.kind in ("param", None):
            return True
        if isinstance(n, ir.Field) and n.name == "weight" and not n.swizzle and isinstance(n.base, ir.Name) \
                and n.base.name in params and n.base.kind in ("param", None):
            return True
    return False


def prepared_state(function: ir.Function, library) -> str | None:
    """The type of the state `<lobe>_prepare` writes (its last parameter, `out`), where the library
    prepares the lobe once per shading point; None where it does not (the first definition of that
    name decides, as a C-like compiler would see it first). `library.functions(name)`: its
    definitions, in library order."""
    for prepare in library.functions(function.name + "_prepare"):
        last = prepare.params[-1] if prepare.params else None
        return last.type if last is not None and last.qualifier == "out" else None
    return None
