"""Ordering passes: topological order (a cycle is an error naming its nodes) and conditional
scopes (seed 2.4 step 5)."""
from ..errors import ShaderGenError
from ..graph import BRANCH_INPUTS, Node, Output


def topological_order(outputs: dict[str, Output]) -> list[Node]:
    """Depth-first post-order from the outputs: every node after the nodes it reads."""
    order: list[Node] = []
    state: dict[int, int] = {}  # 1 visiting, 2 done
    for out in outputs.values():
        if state.get(id(out.node)) == 2:
            continue
        stack = [(out.node, iter(out.node.upstream()))]
        state[id(out.node)] = 1
        while stack:
            node, it = stack[-1]
            nxt = next(it, None)
            if nxt is None:
                stack.pop()
                state[id(node)] = 2
                order.append(node)
                continue
            s = state.get(id(nxt))
            if s == 1:
                names = [n.path for n, _ in stack[[n for n, _ in stack].index(nxt):]] + [nxt.path]
                raise ShaderGenError("cycle", "cycle in the graph: " + " -> ".join(names), nxt.path)
            if s is None:
                state[id(nxt)] = 1
                stack.append((nxt, iter(nxt.upstream())))
    return order


def assign_scopes(nodes: list[Node], uniform_flow=lambda node: False) -> int:
    """A node read only through one branch input of a conditional (directly or through nodes of
    that branch) gets that branch as its scope; anything else is global. `uniform_flow(node)` says
    a node must stay global (it takes screen-space derivatives). Returns how many nodes are scoped."""
    if not any(node.category in BRANCH_INPUTS for node in nodes):  # no branch: every node is global
        for node in nodes:
            node.scope = ()
        return 0
    consumers: dict[int, list[tuple[Node, str]]] = {}
    for node in nodes:
        for inp in node.inputs.values():
            if inp.connection is not None:
                consumers.setdefault(id(inp.connection.node), []).append((node, inp.name))
    for node in reversed(nodes):  # consumers before producers
        uses = consumers.get(id(node))
        if not uses:
            node.scope = ()
            continue
        scopes = set()
        for consumer, input_name in uses:
            if input_name in BRANCH_INPUTS.get(consumer.category, ()):
                scopes.add(consumer.scope + ((consumer, input_name),))
            else:
                scopes.add(consumer.scope)
        scope = scopes.pop() if len(scopes) == 1 else _common_prefix(scopes)
        node.scope = () if scope and uniform_flow(node) else scope  # (asked only where it decides)
    return sum(1 for n in nodes if n.scope)


def _common_prefix(scopes: set[tuple]) -> tuple:
    items = list(scopes)
    prefix = items[0]
    for s in items[1:]:
        n = 0
        while n < min(len(prefix), len(s)) and prefix[n] == s[n]:
            n += 1
        prefix = prefix[:n]
    return prefix
