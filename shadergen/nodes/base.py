"""The implementation interface (seed's SgImplementation) and the data-driven kinds.

Every implementation answers three questions for a node: which shader variables it needs
(`create_variables`), which function definitions it needs (`emit_function_definition`, written
once per stage by a stable key), and what code computes its outputs (`emit_function_call`). Calls
receive the EmitContext: it knows the stages, the syntax, and how to spell an input's value.
`ctx.closure` carries the shading context (reflection, transmission, indirect, emission) for BSDF
nodes that are called once per context; it is None for ordinary data nodes.
"""
import itertools
import os
import re

from ..element import Element
from ..errors import ShaderGenError
from ..features import node_features
from ..library import Library, read_source

REGISTRY: dict[str, type["NodeImpl"]] = {}
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
    """An expression of the node's inputs (`{{input}}` placeholders), parsed into the IR once per
    library (code/library.py templates) and typed once per set of input types; each call puts the
    inputs' values in its placeholders."""

    def __init__(self, expression: str, where: str | None = None):
        self.expression = expression.strip()
        self.where = where  # the implementation, named in a parse error

    @classmethod
    def from_file(cls, elem: Element) -> "InlineImpl":
        return cls(read_source(_source_path(elem, elem.get("file"))), elem.name)

    def emit_function_call(self, node, ctx) -> None:
        inputs = {name: ctx.value(i) for name, i in node.inputs.items()}

        def make():
            try:
                return ctx.code.instance(self.expression, inputs, self.where)
            except ShaderGenError as e:  # a placeholder naming no input of the node, among others
                raise ShaderGenError("invalid_implementation", e.message, node.path) from None
        # the expression is decided by its text and its inputs (their types choose the template's typing)
        ctx.assign_made(next(iter(node.outputs.values())), (self.expression, *itertools.chain(*inputs.items())), make)


class SourceFunctionImpl(NodeImpl):
    """A function in a library source file, in the IR: made once per library
    (nodes.implementation_for), it reads what the code passes and the closure passes need from the
    function's IR, once: the files it needs (its own and their includes, dependencies first), the
    features it declares, and what calling it means to the passes (code/library.py Calls: whether
    it takes derivatives, and for a lobe whether it is empty at zero weight, whether it answers the
    transmission context and the state its `_prepare` writes), read with the library's cache."""

    def __init__(self, elem: Element, library: Library):
        self.path = _source_path(elem, elem.get("file"))
        self.function = elem.get("function") or os.path.splitext(os.path.basename(self.path))[0]
        code = library.code()
        self.files = code.files_for(self.path)  # paths, dependencies first
        self.declarations = code.module(self.files[-1]).features  # its own, by the path the library keys it by
        calls = code.calls_of(self.function)
        self.uses_derivatives = calls.uses_derivatives
        self.empty_at_zero_weight = calls.empty_at_zero_weight
        self.handles_transmission = calls.handles_transmission
        self.prepared_state = calls.prepared_state

    def features(self, node) -> set[str]:
        return node_features(node, self.declarations)

    def emit_function_definition(self, node, ctx) -> None:
        ctx.emit_modules(self.files)

    def emit_function_call(self, node, ctx) -> None:
        ctx.call(self.function, node)


def _source_path(elem: Element, file: str) -> str:
    """Source files are named relative to the .mtlx file that declares the implementation."""
    base = os.path.dirname(elem.source) if elem.source else ""
    path = os.path.normpath(os.path.join(base, file))
    if not os.path.exists(path):
        raise ShaderGenError("missing_source", f"implementation source '{file}' not found", elem.name)
    return path


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
    return _make(elem, library)


def _make(elem: Element, library: Library | None) -> NodeImpl:
    if elem.get("sourcecode") is not None:
        return InlineImpl(elem.get("sourcecode"), elem.name)
    file = elem.get("file")
    if file:
        return _from_file(elem, file, library)
    # dynamic classes are registered target-neutrally: IM_position_vector3 serves IM_position_vector3_genglsl
    cls = REGISTRY.get(elem.name) or REGISTRY.get(TARGET_SUFFIX.sub("", elem.name))
    if cls is None:
        raise ShaderGenError("unknown_implementation",
                             f"implementation '{elem.name}' has no source and no registered class", elem.name)
    impl = cls()
    impl.element = elem  # where its library files are (dynamic implementations may include some)
    return impl


def _from_file(elem: Element, file: str, library: Library | None) -> NodeImpl:
    return InlineImpl.from_file(elem) if file.endswith(".inline") else SourceFunctionImpl(elem, library)
