"""Inline templates (an implementation's `{{input}}` expression, parsed and typed once per set of
input types) made into the expression of one node: each placeholder replaced by its input's value.

A template is compiled once into a maker: a function of the values that copies the nodes above a
placeholder and shares every other node of the template (nothing changes a typed template's
nodes: passes build new ones). A node per call is made only where a value goes in.
"""
from . import ir


def placeholders(template: ir.Expr) -> frozenset[str]:
    return frozenset(n.name for n in ir.walk(template) if isinstance(n, ir.Placeholder))


def maker(template: ir.Expr):
    """values (name -> Expr) -> the template's expression with them in place."""
    if isinstance(template, ir.Placeholder):
        name = template.name
        return lambda values: values[name]
    parts = []  # (field, maker of its value), for the fields a placeholder is under
    for field in template.FIELDS:
        value = getattr(template, field)
        if isinstance(value, ir.Expr) and placeholders(value):
            parts.append((field, maker(value)))
        elif isinstance(value, list) and any(isinstance(v, ir.Expr) and placeholders(v) for v in value):
            makers = [maker(v) if isinstance(v, ir.Expr) and placeholders(v) else _shared(v) for v in value]
            parts.append((field, lambda values, makers=makers: [m(values) for m in makers]))
    if not parts:
        return _shared(template)
    slots = ir.slots_of(type(template))

    def make(values):
        node = object.__new__(type(template))
        for slot in slots:
            setattr(node, slot, getattr(template, slot))
        for field, part in parts:
            setattr(node, field, part(values))
        return node
    return make


def _shared(node):
    return lambda values: node
