"""Forwarding functions called straight (GLSL, ESSL).

A library function whose whole body is `return target(arguments);`, each argument one of its own
parameters, in the order it takes them, or a literal, is a name for a call: the way of lighting
or the features a shader was generated for often reduce a dispatcher to one (the environment a lobe
reflects, without a thin film, is the samples without the film). Its callers call the target
instead, with their own arguments put where the parameters were, and the forwarding function
leaves the stage when nothing else calls it. The same computation: every parameter is passed once,
in order, with the same type and qualifier (`in`, `out`, `inout`) as the target's parameter it
becomes, the return types are equal, and the target has one definition, so no conversion or
overload resolution differs. Calls from the roots (main) stay, since the roots are not edited,
and so do calls that span a comment.
"""
import re
from collections import namedtuple
from functools import lru_cache

from .deadfields import code_text

SIGNATURE = re.compile(r"^\s*(\w+)\s+(\w+)\s*\(([^()]*)\)\s*$", re.S)
FORWARD = re.compile(r"^\{\s*return\s+(\w+)\s*\((.*)\)\s*;\s*\}$", re.S)
LITERAL = re.compile(r"^(?:-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?[uf]?|true|false)$")
PARAMETER = re.compile(r"^(?:(in|out|inout)\s+)?(?:const\s+)?(\w+)\s+(\w+)$")
PARENTHESIS = re.compile(r"[()]")


# a named tuple, not a dataclass: a cold process would import dataclasses for it alone (see graph.py);
# `parameters`: (qualifier, type, name) each; `forwards`: (target, arguments) of a forwarding body, or None
Function = namedtuple("Function", "name returns parameters forwards")


def without_forwarding(items: list[tuple[str, ...]], root_words: set[str]) -> dict[int, tuple[str, ...]]:
    """Item index -> the item with its calls of forwarding functions made to their targets, for
    each item that changes."""
    functions = [_function(item) for item in items]
    definitions: dict[str, list[Function]] = {}
    for f in functions:
        if f is not None:
            definitions.setdefault(f.name, []).append(f)
    wrappers = {f.name: f for f in functions
                if f is not None and f.forwards and f.name not in root_words and len(definitions[f.name]) == 1
                and _passes_through(f, definitions.get(f.forwards[0], []))}
    if not wrappers:
        return {}
    pattern = re.compile(rf"\b({'|'.join(sorted(wrappers))})\s*\(")
    edited = {}
    for k, item in enumerate(items):
        if functions[k] is not None and functions[k].name in wrappers:
            continue
        text = "\n".join(item)
        if not any(name in text for name in wrappers):  # most items call none: a substring test says so
            continue
        new = _calls_replaced(text, pattern, wrappers)
        if new != text:
            edited[k] = tuple(new.split("\n"))
    return edited


def _passes_through(wrapper: Function, targets: list[Function]) -> bool:
    """Whether the wrapper passes each parameter once, in order, as the target takes it."""
    if len(targets) != 1 or targets[0].returns != wrapper.returns:
        return False
    target = targets[0]
    _, arguments = wrapper.forwards
    if len(arguments) != len(target.parameters):
        return False
    own = {name: (qualifier, type_name) for qualifier, type_name, name in wrapper.parameters}
    passed = []
    for argument, (qualifier, type_name, _) in zip(arguments, target.parameters):
        if argument in own:
            if own[argument] != (qualifier, type_name):
                return False
            passed.append(argument)
        elif not LITERAL.match(argument):
            return False
    return passed == [name for _, _, name in wrapper.parameters]


def _calls_replaced(text: str, pattern: re.Pattern, wrappers: dict[str, Function]) -> str:
    out, pos = [], 0
    for m in pattern.finditer(text):
        if m.start() < pos:
            continue  # inside a call already replaced
        end = _closing(text, m.end())
        span = text[m.end():end]
        if end < 0 or "//" in span:
            continue
        wrapper = wrappers[m.group(1)]
        given = dict(zip((name for _, _, name in wrapper.parameters), _split(span)))
        target, arguments = wrapper.forwards
        call = f"{target}({', '.join(given.get(a, a) for a in arguments)})"
        out.append(text[pos:m.start()] + call)
        pos = end + 1
    return "".join(out) + text[pos:]


def _closing(text: str, start: int) -> int:
    """Index of the `)` closing the call whose arguments start at `start`, -1 if none."""
    depth = 1
    for m in PARENTHESIS.finditer(text, start):
        depth += 1 if m.group() == "(" else -1
        if depth == 0:
            return m.start()
    return -1


def _split(arguments: str) -> list[str]:
    """Arguments split at the commas outside parentheses and brackets, stripped."""
    parts, held, depth = [], [], 0  # held: the pieces since the last comma outside
    for piece in arguments.split(","):
        held.append(piece)
        depth += piece.count("(") + piece.count("[") - piece.count(")") - piece.count("]")
        if depth == 0:
            parts.append(" ".join(",".join(held).split()))
            held = []
    return [p for p in parts if p] if arguments.strip() else []


@lru_cache(maxsize=8192)
def _function(item: tuple[str, ...]) -> Function | None:
    """The item as a function: its signature, and its body when that only forwards."""
    code = code_text(item).strip()
    brace = code.find("{")
    if brace < 0 or code.startswith(("struct", "#", "const")):
        return None
    signature = SIGNATURE.match(code[:brace])
    if signature is None:
        return None
    returns, name, parameter_text = signature.groups()
    parameters = []
    for text in _split(parameter_text):
        m = PARAMETER.match(text)
        if m is None:
            return None  # arrays, precision qualifiers: left alone
        parameters.append((m.group(1) or "in", m.group(2), m.group(3)))
    body = FORWARD.match(code[brace:])
    if body and _closing(body.group(2) + ")", 0) != len(body.group(2)):
        body = None  # `return f(a) + g(b);`: not one call
    forwards = (body.group(1), tuple(_split(body.group(2)))) if body else None
    return Function(name, returns, tuple(parameters), forwards)
