"""The implementation interface (seed's SgImplementation) and the data-driven kinds.

Every implementation answers three questions for a node: which shader variables it needs
(`create_variables`), which function definitions it needs (`emit_function_definition`, written
once per stage by a stable key), and what code computes its outputs (`emit_function_call`). Calls
receive the EmitContext: it knows the stages, the syntax, and how to spell an input's value.
`ctx.closure` carries the shading context (reflection, transmission, indirect, emission) for BSDF
nodes that are called once per context; it is None for ordinary data nodes.
"""
import os
import re
from functools import lru_cache

from ..element import Element
from ..errors import ShaderGenError
from ..features import node_features
from ..library import Library, read_source
from ..targets.glsl import starts_word
from ..targets.glsl_target import PLACEHOLDER

REGISTRY: dict[str, type["NodeImpl"]] = {}
# No leading \b: it would stop the regex engine from scanning for the names' first letters, which
# makes the search some 30 times slower over a library source (takes_derivatives checks the boundary).
DERIVATIVES = re.compile(r"(?:dFdx|dFdy|fwidth|texture)\s*\(")
INCLUDE = re.compile(r'^\s*#include\s+"([^"]+)"\s*$', re.M)
TARGET_SUFFIX = re.compile(r"_gen\w+$")


def register(*names: str):
    """Register a dynamic implementation class under one or more implementation names."""
    def deco(cls):
        for n in names:
            REGISTRY[n] = cls
        return cls
    return deco


class NodeImpl:
    element: Element | None = None  # the <implementation> it was made from
    # Takes screen-space derivatives (explicitly or through implicit-lod texture lookups), so it
    # must run in uniform control flow, never inside a per-pixel branch.
    uses_derivatives = False
    # Inputs that are settings of the implementation rather than values (never published).
    fixed_inputs: frozenset[str] = frozenset()

    def is_editable(self, input_name: str) -> bool:
        return input_name not in self.fixed_inputs

    def features(self, node) -> set[str]:
        """The library features (shadergen/features.py) this node's calls need."""
        return set()

    def create_variables(self, node, ctx) -> None:
        pass

    def emit_function_definition(self, node, ctx) -> None:
        pass

    def emit_function_call(self, node, ctx) -> None:
        raise NotImplementedError


class InlineImpl(NodeImpl):
    def __init__(self, expression: str):
        self.expression = expression.strip()

    @classmethod
    def from_file(cls, elem: Element) -> "InlineImpl":
        return cls(read_source(_source_path(elem, elem.get("file"))))

    def emit_function_call(self, node, ctx) -> None:
        for name in PLACEHOLDER.findall(self.expression):
            if name not in node.inputs:
                raise ShaderGenError("invalid_implementation", f"inline expression names unknown input '{name}'",
                                     node.path)
        inputs = {name: (ctx.value(i), i.type) for name, i in node.inputs.items()}
        ctx.assign(next(iter(node.outputs.values())), ctx.target.inline(self.expression, inputs))


class SourceFunctionImpl(NodeImpl):
    """A function in a library source file. Its files are read and expanded when it is made:
    made once per library (nodes.implementation_for), they are read once per library, and files
    several sources include (the closures' common code) once for all of them."""

    def __init__(self, elem: Element, library: Library | None = None):
        self.path = _source_path(elem, elem.get("file"))
        self.function = elem.get("function") or os.path.splitext(os.path.basename(self.path))[0]
        # (path, text) of it and its includes, dependencies first
        self.files = tuple(expand_includes(self.path, set(), library))
        self.source = self.files[-1][1]  # the text of its own file, without its #include lines
        self.uses_derivatives = any(takes_derivatives(text) for _, text in self.files)

    def features(self, node) -> set[str]:
        return node_features(node, self.source)

    def emit_function_definition(self, node, ctx) -> None:
        ctx.emit_source_files(self.files)

    def emit_function_call(self, node, ctx) -> None:
        ctx.call(self.function, node)


@lru_cache(maxsize=1024)
def takes_derivatives(source: str) -> bool:
    """Whether the source calls dFdx, dFdy, fwidth or texture (as whole names). Memoised: the
    closures' shared files are included by every lobe's source, and scanned once."""
    return any(starts_word(source, m.start()) for m in DERIVATIVES.finditer(source))


def _source_path(elem: Element, file: str) -> str:
    """Source files are named relative to the .mtlx file that declares the implementation."""
    base = os.path.dirname(elem.source) if elem.source else ""
    path = os.path.normpath(os.path.join(base, file))
    if not os.path.exists(path):
        raise ShaderGenError("missing_source", f"implementation source '{file}' not found", elem.name)
    return path


def expand_includes(path: str, seen: set[str], library: Library | None = None) -> list[tuple[str, str]]:
    """A source file and the files it #includes, dependencies first, each once (by path). With a
    `library`, each file is read once for the library's life (its files are part of its key)."""
    if path in seen:
        return []
    seen.add(path)
    includes, text = library.fact(("source", path), lambda: read_included(path)) if library is not None \
        else read_included(path)
    out = []
    for inc_path in includes:
        out.extend(expand_includes(inc_path, seen, library))
    out.append((path, text))
    return out


def read_included(path: str) -> tuple[tuple[str, ...], str]:
    """The files a source #includes (paths, in order) and its text without its #include lines."""
    text = read_source(path)
    includes = []
    for inc in INCLUDE.findall(text):
        inc_path = os.path.normpath(os.path.join(os.path.dirname(path), inc))
        if not os.path.exists(inc_path):
            raise ShaderGenError("missing_source", f"'{path}' includes missing '{inc}'", path)
        includes.append(inc_path)
    return tuple(includes), INCLUDE.sub("", text).strip("\n")


class GraphFunctionImpl(NodeImpl):
    """A call of a nodegraph body written once as a function (passes/functions.py)."""

    def __init__(self, function, uses_derivatives: bool):
        self.function = function
        self.uses_derivatives = uses_derivatives

    def emit_function_definition(self, node, ctx) -> None:
        ctx.emit_graph_function(self.function)

    def emit_function_call(self, node, ctx) -> None:
        ctx.call(ctx.function_names[id(self.function)], node)


def implementation_for(elem: Element, library: Library | None = None) -> NodeImpl:
    """The NodeImpl of an implementation element. The kinds that read files are made once per
    `library` for its own elements (their files read and expanded once); the others are cheap to
    make, and dynamic ones may keep state for the shader they write, so they are made each time."""
    file = elem.get("file")
    if file and elem.get("sourcecode") is None and library is not None and library.owns(elem):
        return library.fact(("implementation", id(elem)), lambda: _from_file(elem, file, library))
    return _make(elem)


def _make(elem: Element) -> NodeImpl:
    if elem.get("sourcecode") is not None:
        return InlineImpl(elem.get("sourcecode"))
    file = elem.get("file")
    if file:
        return _from_file(elem, file)
    # dynamic classes are registered target-neutrally: IM_position_vector3 serves IM_position_vector3_genglsl
    cls = REGISTRY.get(elem.name) or REGISTRY.get(TARGET_SUFFIX.sub("", elem.name))
    if cls is None:
        raise ShaderGenError("unknown_implementation",
                             f"implementation '{elem.name}' has no source and no registered class", elem.name)
    impl = cls()
    impl.element = elem  # where its library files are (dynamic implementations may include some)
    return impl


def _from_file(elem: Element, file: str, library: Library | None = None) -> NodeImpl:
    return InlineImpl.from_file(elem) if file.endswith(".inline") else SourceFunctionImpl(elem, library)
