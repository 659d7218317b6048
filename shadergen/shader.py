"""Shader, stages and variable blocks (seed 2.6-2.7): what generation produces, before it is text.

A Stage owns its variable blocks, its code in the IR (the library items and generated functions it
needs, and main) and, once the code passes ran, what they kept (`code`). The Writer is the stage
assemblers': lines with explicit, exception-safe indentation.
"""
from contextlib import contextmanager

from .code.build import Builder
from .types import value_to_json

VERTEX, PIXEL = "vertex", "pixel"


class Variable:
    """A variable of a block, as the listing gives it. (Plain classes here, not dataclasses: see
    graph.py.)"""

    def __init__(self, name: str, type: str, value: object = None, path: str | None = None, unit: str | None = None,
                 colorspace: str | None = None, ui: dict | None = None, initializer: object = None,
                 fallback: object = None):
        self.name = name
        self.type = type  # MaterialX type name
        self.value = value
        self.path = path
        self.semantic: str | None = None
        self.unit = unit
        self.colorspace = colorspace
        self.ui = ui
        self.initializer = initializer  # what the source initialises the uniform to (the listing carries `value`)
        self.fallback = fallback  # a filename's: what its image node gives for a missing or unreadable file

    def to_json(self) -> dict:
        d = {"name": self.name, "type": self.type, "value": value_to_json(self.value), "path": self.path,
             "semantic": self.semantic, "unit": self.unit, "colorspace": self.colorspace}
        if self.ui:
            d["ui"] = dict(self.ui)  # its own: the ui a nodedef input gives is shared by every node of it
        if self.fallback is not None:
            d["fallback"] = value_to_json(self.fallback)
        return d


class VariableBlock:
    def __init__(self, name: str, instance: str = ""):
        self.name = name
        self.instance = instance  # e.g. "vd" for VertexData: members are written vd.member
        self.variables: dict[str, Variable] = {}

    def add(self, var: Variable) -> Variable:
        return self.variables.setdefault(var.name, var)

    def __contains__(self, name: str) -> bool:
        return name in self.variables

    def __iter__(self):
        return iter(self.variables.values())

    def __len__(self) -> int:
        return len(self.variables)


class Writer:
    """Lines of code with explicit, exception-safe indentation."""

    def __init__(self, indent: str = "    "):
        self.lines: list[str] = []
        self.depth = 0
        self.unit = indent

    def line(self, text: str = "") -> None:
        self.lines.append(self.unit * self.depth + text if text else "")

    def extend(self, lines) -> None:
        """Lines already indented for the top level, indented to this depth."""
        if not self.depth:  # library items, at the top level: as they are
            self.lines.extend(lines)
            return
        indent = self.unit * self.depth
        self.lines.extend(indent + ln if ln else "" for ln in lines)

    @contextmanager
    def scope(self, comment: str | None = None):
        """A bare `{ }` block: the variables declared inside stay local to it."""
        if comment:
            self.line(f"// {comment}")
        self.line("{")
        self.depth += 1
        try:
            yield
        finally:
            self.depth -= 1
            self.line("}")

    @contextmanager
    def block(self, opener: str):
        """`opener { ... }`: a function body, a loop, a branch."""
        self.line(opener)
        with self.scope():
            yield

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"


BLOCKS = {
    VERTEX: ("PublicUniforms", "PrivateUniforms", "AppData", "VertexData"),
    PIXEL: ("PublicUniforms", "PrivateUniforms", "VertexData", "LightData", "Outputs"),
}


class Stage:
    """One stage of a shader: its variable blocks, its code and main."""

    def __init__(self, name: str):
        self.name = name
        self.blocks = {b: VariableBlock(b, "vd" if b == "VertexData" else "") for b in BLOCKS[name]}
        self.items: list = []  # the library's IR items it asked for, in that order
        self.generated: list = []  # the functions the generator wrote (typed with main), in order
        self.main = Builder()  # body of main()
        # main's statements served from an earlier request's, by what they are built from (id ->
        # number), and those built here with what they were built from (code/statements.py)
        self.alike_found: dict[int, int] = {}
        self.alike_fresh: list = []
        self.code = None  # what the code passes kept (code/stage.py), once they ran
        self.emitted: set = set()  # keys of library files and generated functions already added

    def once(self, key) -> bool:
        """True the first time `key` is seen: each function definition is emitted once per stage."""
        if key in self.emitted:
            return False
        self.emitted.add(key)
        return True

    def listing(self) -> dict:
        return {name: [v.to_json() for v in block] for name, block in self.blocks.items()}
