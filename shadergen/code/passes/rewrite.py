"""Rebuilding IR trees: new nodes only along the paths that change (ir.py: nodes are shared
between items and requests, never mutated), so an unchanged item stays the same object and keeps
its memoised facts."""
from .. import ir


def rebuild_list(nodes: list, statement=None, expression=None) -> list:
    """A list of items or statements with `statement(stmt)` and `expression(expr)` applied at every
    depth (`nodes` itself when nothing changed).

    `statement(stmt)`: None keeps the statement (its insides rebuilt), a list of statements takes
    its place (those rebuilt in turn); `expression(expr)`: called on each expression after its
    insides, returns it or its replacement. An if, loop or block whose insides changed is tidied:
    an emptied `else` goes, an emptied brace-less body gets braces, and an if left with nothing to
    do and no call in its condition goes."""
    return _many(nodes, statement, expression)


def _rebuilt(node, statement, expression):
    changes = {}
    for name in node.CHILDREN:
        value = getattr(node, name)
        if isinstance(value, ir.Node):
            new = _one(value, statement, expression)
        elif isinstance(value, (list, tuple)) and value and isinstance(value[0], ir.Node):
            new = _many(value, statement, expression)
        else:
            continue
        if new is not value:
            changes[name] = new
    if changes:
        node = ir.replace(node, **changes)
    if isinstance(node, ir.Expr) and expression is not None:
        node = expression(node)
    return node


def _many(values, statement, expression):
    out, changed = [], False
    for value in values:
        if isinstance(value, ir.Node):
            new = _spliced(value, statement, expression)
            changed = changed or len(new) != 1 or new[0] is not value
            out.extend(new)
        else:
            out.append(value)
    if not changed:
        return values
    return tuple(out) if isinstance(values, tuple) else out


def _one(value, statement, expression):
    new = _spliced(value, statement, expression)
    if len(new) == 1:
        return new[0]
    return ir.Block(new, False) if new else None  # several statements in one place: grouped


def _spliced(node, statement, expression) -> list:
    if statement is not None and isinstance(node, ir.Stmt):
        replaced = statement(node)
        if replaced is not None:
            return [s for r in replaced for s in _spliced(r, statement, expression)]
    new = _rebuilt(node, statement, expression)
    return _tidied(new) if new is not node else [new]


def _tidied(stmt) -> list:
    if isinstance(stmt, ir.If):
        other = stmt.other
        while isinstance(other, ir.Block) and not other.scoped and len(other.body) == 1 \
                and isinstance(other.body[0], ir.Block):
            other = other.body[0]  # the `else { ... }` or `else if` the sections held
        if isinstance(other, ir.Block) and not other.scoped and not other.body:
            other = None  # the sections that held the `else` gave none
        then = _braced(stmt.then)
        if not then.body and other is None and not any(isinstance(n, ir.Call) for n in ir.walk(stmt.condition)):
            return []
        if then is not stmt.then or other is not stmt.other:
            stmt = ir.replace(stmt, then=then, other=other)
    elif isinstance(stmt, (ir.For, ir.While)):
        body = _braced(stmt.body)
        if body is not stmt.body:
            stmt = ir.replace(stmt, body=body)
    return [stmt]


def _braced(block):
    """An emptied brace-less body gets braces (`if (c) {}`), which every printer can write."""
    if block is None:
        return ir.Block([], True)
    return ir.replace(block, scoped=True) if not block.scoped and not block.body else block


def items_in(unit) -> list:
    """The items of a top-level unit: itself, or those of a Section's sides (nested ones too)."""
    if not isinstance(unit, ir.Section):
        return [unit]
    return [i for part in (unit.body, unit.other or ()) for u in part for i in items_in(u)]
