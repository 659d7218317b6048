"""The shader generator: from a prepared ShaderGraph to a hardware Shader (seed 2.4, emit steps).

Steps, in order, for a graph: declare the public uniforms the passes chose, let every
implementation create its variables, emit function definitions (each once, by a stable key), emit
the node calls in topological order (nodes scoped to a conditional branch inside that branch),
assign the shader outputs, then assemble each stage's text: header, type definitions, variable
blocks, functions, main. The graph arrives finished (passes/): emission only walks it.
"""
import re

from .errors import ShaderGenError
from .graph import BRANCH_INPUTS, Function, Graph, Input, Node, Output, Socket
from .library import Scope
from .nodes.base import expand_includes
from .shader import PIXEL, VERTEX, Stage, Variable, Writer
from .targets.deadcode import identifiers, used_functions
from .targets.glsl import STRUCTS, Syntax

CLOSURES = ("BSDF", "EDF", "VDF")
CONDITIONS = {"ifgreater": ">", "ifgreatereq": ">=", "ifequal": "=="}


class Namer:
    """One namer per shader: valid identifiers, no reserved words or gl_ prefix, no clashes."""

    def __init__(self, reserved: set[str]):
        self.reserved = reserved
        self.used: set[str] = set()

    def __call__(self, wanted: str) -> str:
        name = re.sub(r"\W", "_", wanted) or "v"
        if name[0].isdigit() or name.startswith("gl_") or name.startswith("__"):
            name = "v_" + name
        base, n = name, 1
        while name in self.used or name in self.reserved:
            name = f"{base}{n}"
            n += 1
        self.used.add(name)
        return name


class EmitContext:
    """Shared state of one generation; node implementations write through it."""

    def __init__(self, syntax: Syntax, scope: Scope, target: str):
        self.syntax = syntax
        self.scope = scope
        self.target = target
        self.stages = {VERTEX: Stage(VERTEX), PIXEL: Stage(PIXEL)}
        self.namer = Namer(syntax.reserved)
        self.closure = None  # shading context for BSDF nodes (see nodes/base.py)
        self.vars: dict[int, str] = {}  # id(Output | Input | Socket) -> expression naming its value
        self.used_types: set[str] = set()
        self.body: Writer = self.pixel.main
        self.vertex_main: list[str] = []
        self.function_names: dict[int, str] = {}  # id(Function) -> its name in the shader
        self.memo: dict = {}  # per-shader facts implementations compute once (e.g. which lights exist)

    @property
    def pixel(self) -> Stage:
        return self.stages[PIXEL]

    @property
    def vertex(self) -> Stage:
        return self.stages[VERTEX]

    # -- values ----------------------------------------------------------------------------
    def value(self, inp: Input) -> str:
        if inp.connection is not None:
            return self.vars[id(inp.connection)]
        if inp.socket is not None:
            return self.vars[id(inp.socket)]
        if inp.public:
            return self.vars[id(inp)]
        return self.syntax.literal(inp.type, inp.value, inp.meta)

    def publish(self, port: Input | Socket) -> str:
        """A public input (or the socket several inputs of an expanded body share) as a uniform."""
        listing_type, value = port.type, port.value
        if port.type == "string":
            if port.meta.get("enum"):
                listing_type, value = "integer", self.syntax.enum_index(port.value, port.meta)
            elif value == "":
                value = None
        name = self.vars[id(port)] = self.namer(f"{port.owner.name}_{port.name}")
        self.add_variable(PIXEL, "PublicUniforms", Variable(
            name, listing_type, value, port.path, unit=port.meta.get("unit"), colorspace=port.meta.get("colorspace"),
            ui=port.meta.get("ui")))
        return name

    def output_name(self, out: Output) -> str:
        if id(out) not in self.vars:
            self.vars[id(out)] = self.namer(f"{out.node.name}_{out.name}")
            self.used_types.add(out.type)
        return self.vars[id(out)]

    def assign(self, out: Output, expression: str) -> None:
        self.body.line(f"{self.syntax.type_name(out.type)} {self.output_name(out)} = {expression};")

    def declare(self, out: Output) -> str:
        name = self.output_name(out)
        if out.type in CLOSURES:  # closure functions accumulate into their result: start from zero
            self.body.line(f"{self.syntax.type_name(out.type)} {name} = {self.syntax.literal(out.type, None)};")
        else:
            self.body.line(f"{self.syntax.type_name(out.type)} {name};")
        return name

    def call(self, function: str, node: Node) -> None:
        outs = [self.declare(o) for o in node.outputs.values()]
        args = [self.value(i) for i in node.inputs.values()] + outs
        if is_closure_node(node):
            args.insert(0, "closureData")
        self.body.line(f"{function}({', '.join(args)});")

    # -- variables ---------------------------------------------------------------------------
    def add_variable(self, stage: str, block: str, var: Variable) -> Variable:
        self.used_types.add(var.type)
        return self.stages[stage].blocks[block].add(var)

    def private_uniform(self, name: str, type_name: str, stages=(PIXEL,)) -> str:
        for s in stages:
            self.add_variable(s, "PrivateUniforms", Variable(name, type_name))
        return name

    def app_data(self, name: str, type_name: str) -> str:
        self.add_variable(VERTEX, "AppData", Variable(name, type_name))
        return name

    def vertex_data(self, name: str, type_name: str, vertex_expression: str) -> str:
        """A value computed per vertex and interpolated: declared in both stages, assigned once in
        the vertex stage's main. Returns how the pixel stage reads it."""
        for s in (VERTEX, PIXEL):
            self.add_variable(s, "VertexData", Variable(name, type_name))
        if name not in self.vertex.calculated:
            self.vertex.calculated.add(name)
            self.vertex_main.append(f"{self.syntax.vertex_data_member(name)} = {vertex_expression};")
        return self.syntax.vertex_data_member(name)

    # -- functions -------------------------------------------------------------------------------
    def emit_source_file(self, path: str) -> None:
        for dep_path, text in expand_includes(path, set()):
            if self.pixel.once(("file", dep_path)):
                self.pixel.functions.extend(text)
                self.pixel.functions.line()

    def emit_graph_function(self, function: Function) -> None:
        """A nodegraph body shared by several calls, written once."""
        if id(function) in self.function_names:
            return
        self.function_names[id(function)] = fname = self.namer(function.name)
        saved_body, saved_vars = self.body, self.vars
        self.body, self.vars = Writer(), dict(saved_vars)
        params = []
        for s in function.params:
            self.vars[id(s)] = pname = self.namer(f"{fname}_{s.name}")
            params.append(f"{self.syntax.type_name(s.type)} {pname}")
            self.used_types.add(s.type)
        out_params = [(self.namer(f"{fname}_{out.name}"), out) for out in function.outputs]
        params += [f"out {self.syntax.type_name(out.type)} {p}" for p, out in out_params]
        try:
            self.define_functions(function.graph)
            with self.body.block(f"void {fname}({', '.join(params)})"):
                self.emit_nodes(function.graph, ())
                for p, out in out_params:
                    self.body.line(f"{p} = {self.vars[id(out)]};")
            self.pixel.functions.extend(self.body.text())
            self.pixel.functions.line()
        finally:
            self.body, self.vars = saved_body, saved_vars

    def define_functions(self, graph: Graph) -> None:
        for node in graph.nodes:
            node.impl.create_variables(node, self)
        for node in graph.nodes:
            node.impl.emit_function_definition(node, self)

    # -- calls -------------------------------------------------------------------------------
    def emit_nodes(self, graph: Graph, scope: tuple) -> None:
        branching = {id(cond) for n in graph.nodes for cond, _ in n.scope}  # conditionals with nodes of their own
        for node in graph.nodes:
            if is_closure_node(node) and self.closure is None:
                continue  # closures are evaluated per shading context by the surface that reads them
            if node.scope == scope:
                if id(node) in branching:
                    self.emit_branches(graph, node)
                else:
                    node.impl.emit_function_call(node, self)

    def emit_closures(self, inp: Input, context: str) -> str:
        """Evaluate the closure nodes upstream of `inp` in one shading context (seed's
        SgNodeContext): the caller has declared `closureData` for that context. Data nodes feeding
        the closures were computed once, before. Returns the expression of the result."""
        nodes: list[Node] = []
        seen: set[int] = set()

        def visit(out: Output | None):
            if out is None or id(out.node) in seen or not is_closure_node(out.node):
                return
            seen.add(id(out.node))
            for i in out.node.inputs.values():
                visit(i.connection)
            nodes.append(out.node)

        visit(inp.connection)
        saved = self.closure
        self.closure = context
        try:
            for node in nodes:
                node.impl.emit_function_call(node, self)
        finally:
            self.closure = saved
        return self.value(inp)

    def emit_branches(self, graph: Graph, node: Node) -> None:
        """A conditional whose branches have nodes of their own: if/else, each branch computing
        only what it needs (seed 2.4 step 5)."""
        out = next(iter(node.outputs.values()))
        result = self.declare(out)
        for i, (branch, condition) in enumerate(self.branch_conditions(node)):
            opener = ("if" if i == 0 else "else if") + f" ({condition})" if condition else "else"
            with self.body.block(opener):
                if branch is None:  # no input selected: the type's zero, as the inline form gives
                    self.body.line(f"{result} = {self.syntax.literal(out.type, None)};")
                    continue
                self.emit_nodes(graph, node.scope + ((node, branch),))
                self.body.line(f"{result} = {self.value(node.inputs[branch])};")

    def branch_conditions(self, node: Node) -> list[tuple[str | None, str | None]]:
        """(branch input, condition) in order; a None condition is the final else."""
        if node.category in CONDITIONS:
            op = CONDITIONS[node.category]
            v1, v2 = self.value(node.inputs["value1"]), self.value(node.inputs["value2"])
            return [("in1", f"{v1} {op} {v2}"), ("in2", None)]
        which = node.inputs["which"]
        w = self.value(which)
        bound = (lambda k: str(k)) if which.type == "integer" else (lambda k: f"{k}.0")
        names = [n for n in BRANCH_INPUTS["switch"] if n in node.inputs]
        # `which` below k selects input k; from the number of inputs on, none is selected
        return [(n, f"{w} < {bound(k)}") for k, n in enumerate(names, start=1)] + [(None, None)]


def is_closure_node(node: Node) -> bool:
    return any(o.type in CLOSURES for o in node.outputs.values())


def assign_outputs(ctx: EmitContext, graph: Graph) -> None:
    for name, out in graph.outputs.items():
        if out.type in ("filename", "string"):
            raise ShaderGenError("unsupported_output", f"a {out.type} output cannot be drawn", name)
        var = ctx.namer(name)
        ctx.add_variable(PIXEL, "Outputs", Variable(var, "color4"))
        ctx.body.line(f"{var} = {display_value(out.type, ctx.vars[id(out)])};")


def display_value(type_name: str, v: str) -> str:
    """Every pixel output is a vec4 colour."""
    if type_name in ("float", "integer", "boolean"):
        s = v if type_name == "float" else f"float({v})"
        return f"vec4({s}, {s}, {s}, 1.0)"
    if type_name == "vector2":
        return f"vec4({v}, 0.0, 1.0)"
    if type_name in ("vector3", "color3"):
        return f"vec4({v}, 1.0)"
    if type_name in ("vector4", "color4"):
        return v
    if type_name in ("surfaceshader", "material", "volumeshader"):
        return f"vec4({v}.color, 1.0)"
    return "vec4(0.0, 0.0, 0.0, 1.0)"


def emit_shader(ctx: EmitContext, graph: Graph) -> dict[str, str]:
    ctx.private_uniform("u_worldMatrix", "matrix44", (VERTEX,))
    ctx.private_uniform("u_viewProjectionMatrix", "matrix44", (VERTEX,))
    ctx.app_data("i_position", "vector3")
    for port in graph.interface:
        ctx.publish(port)
    ctx.define_functions(graph)
    ctx.emit_nodes(graph, ())
    assign_outputs(ctx, graph)
    drop_unused(ctx, graph.interface_mode == "specialized")
    return {VERTEX: assemble_vertex(ctx), PIXEL: assemble_pixel(ctx)}


FIXED_VERTEX = {"i_position", "u_worldMatrix", "u_viewProjectionMatrix"}  # the position transform always runs


def drop_unused(ctx: EmitContext, variables: bool) -> None:
    """Only the functions main reaches are written, and only the structs they use. With
    `variables` (specialized), uniforms nothing reads and vertex data the pixel stage does not read
    are dropped too, from the code and from the listings."""
    main = "\n".join(ctx.pixel.main.lines)
    ctx.pixel.functions.lines = used_functions(ctx.pixel.functions.lines, main)
    used = identifiers(main + "\n".join(ctx.pixel.functions.lines))
    if variables:
        blocks = ctx.pixel.blocks
        for block in ("PrivateUniforms", "PublicUniforms"):
            blocks[block].variables = {n: v for n, v in blocks[block].variables.items() if n in used}
        if "u_lightData" not in blocks["PrivateUniforms"]:
            blocks["LightData"].variables = {}
        read = {n for n in blocks["VertexData"].variables
                if identifiers(ctx.syntax.vertex_data_member(n)) <= used}
        for stage in ctx.stages.values():
            stage.blocks["VertexData"].variables = {n: v for n, v in stage.blocks["VertexData"].variables.items()
                                                    if n in read}
        ctx.vertex_main = [ln for ln in ctx.vertex_main
                           if any(ln.startswith(f"{ctx.syntax.vertex_data_member(n)} = ") for n in read)]
        vertex_used = identifiers("\n".join(ctx.vertex_main)) | FIXED_VERTEX
        for block in ("AppData", "PrivateUniforms"):
            vb = ctx.vertex.blocks[block]
            vb.variables = {n: v for n, v in vb.variables.items() if n in vertex_used}
    declared = {v.type for st in ctx.stages.values() for b in st.blocks.values() for v in b}
    ctx.used_types = {t for t in ctx.used_types if t not in STRUCTS or t in used or t in declared}


def _declarations(ctx: EmitContext, stage: Stage, w: Writer) -> None:
    syntax = ctx.syntax
    for block in ("PrivateUniforms", "PublicUniforms"):
        variables = list(stage.blocks[block])
        if variables:
            w.line(f"// Uniform block: {block}")
            for v in variables:
                meta = {"enum": ""}  # listing values of enums are already indices
                w.line(syntax.uniform_declaration(v.type, v.name, v.value, meta))
            w.line()


def _vertex_data(ctx: EmitContext, stage: Stage, w: Writer, direction: str) -> None:
    members = list(stage.blocks["VertexData"])
    if not members:
        return
    if ctx.syntax.vertex_data_block:
        w.line(f"{direction} VertexData")
        w.line("{")
        for v in members:
            w.line(f"    {ctx.syntax.type_name(v.type)} {v.name};")
        w.line("} vd;")
    else:
        for v in members:
            w.line(f"{direction} {ctx.syntax.type_name(v.type)} {ctx.syntax.vertex_data_member(v.name)};")
    w.line()


def assemble_pixel(ctx: EmitContext) -> str:
    w = Writer()
    for line in ctx.syntax.header():
        w.line(line)
    w.line()
    structs = ctx.syntax.struct_definitions({t for t in ctx.used_types if t in STRUCTS})
    if structs:
        for s in structs:
            w.line(s)
        w.line()
    _declarations(ctx, ctx.pixel, w)
    _vertex_data(ctx, ctx.pixel, w, "in")
    for v in ctx.pixel.blocks["Outputs"]:
        w.line(f"out vec4 {v.name};")
    w.line()
    if ctx.pixel.functions.lines:
        w.lines.extend(ctx.pixel.functions.lines)
    with w.block("void main()"):
        w.lines.extend("    " + ln if ln else "" for ln in ctx.pixel.main.lines)
    return w.text()


def assemble_vertex(ctx: EmitContext) -> str:
    w = Writer()
    for line in ctx.syntax.header():
        w.line(line)
    w.line()
    _declarations(ctx, ctx.vertex, w)
    for v in ctx.vertex.blocks["AppData"]:
        w.line(f"in {ctx.syntax.type_name(v.type)} {v.name};")
    w.line()
    _vertex_data(ctx, ctx.vertex, w, "out")
    with w.block("void main()"):
        w.line("vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);")
        w.line("gl_Position = u_viewProjectionMatrix * hPositionWorld;")
        for line in ctx.vertex_main:
            w.line(line)
    return w.text()
