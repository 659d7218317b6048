"""Inline templates (an implementation's `{{input}}` expression, parsed once) made into the
expression of one node: each placeholder replaced by its input's value."""
from . import ir


def placeholders(template: ir.Expr) -> list[str]:
    return [n.name for n in ir.walk(template) if isinstance(n, ir.Placeholder)]


def substitute(template: ir.Expr, values: dict[str, ir.Expr]) -> ir.Expr:
    """A new expression: the template's nodes down to each placeholder copied, the values put
    in (shared, never copied: a value is an expression the generator made for this shader)."""
    if isinstance(template, ir.Placeholder):
        return values[template.name]
    changes = {}
    for field in template.FIELDS:
        value = getattr(template, field)
        if isinstance(value, ir.Expr):
            changes[field] = substitute(value, values)
        elif isinstance(value, list):
            changes[field] = [substitute(v, values) if isinstance(v, ir.Expr) else v for v in value]
    return ir.replace(template, **changes) if changes else template
