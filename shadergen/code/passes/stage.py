"""The passes of one stage's library code, in their order, with their counts for the record.

Sections first (what the request's features and environment decide), then reach from the roots;
fields and forward can leave a function nothing calls (a store that went was its last caller, a
forwarding function was called straight), so reach runs again after them, until neither changes
anything. Each pass is memoised per its inputs, so a topology seen before costs lookups.
"""
from ..facts import collect
from . import fields, forward, reach, sections


def run(items: list, features: frozenset | None, macros: frozenset, roots=(), names=(), library=None,
        shared=None) -> tuple:
    """(reach.Reached of what the stage keeps, {"sections", "reach", "fields", "forward": count}:
    sections resolved, items left unreached, dead members and stores, calls made straight)
    for `items` (the library items the stage's files bring, in library order), `roots` (main's
    statements, the generated functions) and `names` (items the generator names without IR);
    `library`: the CodeLibrary the items come from (sections.run); `shared`: the roots' statements
    typed in an earlier request, whose facts were read then (code/statements.py)."""
    resolved, counts = sections.run(items, features, macros, library)
    root_facts = collect(roots, shared)
    reached, unreached = reach.run(resolved, root_facts, names)
    total = {"sections": counts, "reach": unreached, "fields": 0, "forward": 0}
    while True:
        kept, n = fields.run(reached.items, root_facts)
        kept, m = forward.run(kept, root_facts)
        total["fields"] += n
        total["forward"] += m
        if not n + m:
            break
        reached, unreached = reach.run(kept, root_facts, names)
        total["reach"] += unreached
    return reached, total
