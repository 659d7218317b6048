"""The shader generator: from a prepared ShaderGraph to a hardware Shader (seed 2.4, emit steps).

Steps, in order, for a graph: declare the public uniforms the passes chose, let every
implementation create its variables, emit function definitions (each once, by a stable key), emit
the node calls in topological order (nodes scoped to a conditional branch inside that branch),
assign the shader outputs, then assemble each stage's text: header, type definitions, variable
blocks, functions, main. The graph arrives finished (passes/): emission only walks it.
"""
from .code import build, ir
from .code import stage as code_passes
from .code.build import Builder
from .code.externals import environment_macros
from .code.facts import collect
from .code.statements import alike_key
from .code.types import ir_type
from .code.values import enum_index, value_expr
from .errors import ShaderGenError
from .features import LIGHTS_FEATURE, graph_features
from .graph import BRANCH_INPUTS, Function, Graph, Input, Node, Output, Socket
from .library import Scope
from .naming import SourceNames
from .nodes.lobes import closure_nodes, emit_lobes
from .shader import PIXEL, VERTEX, Stage, Variable
from .targets.names import identifier

CLOSURES = ("BSDF", "EDF", "VDF")
SHADERS = CLOSURES + ("surfaceshader", "volumeshader", "material", "lightshader")  # what a closure language outputs as it is
CONDITIONS = {"ifgreater": ">", "ifgreatereq": ">=", "ifequal": "=="}  # the IR's comparison


class Namer:
    """One namer per shader (naga's shape): every name the code declares is an identifier of every
    target (targets/names.py), no reserved word, no clash. Fresh names (`__call__`: uniforms,
    outputs, functions, locals, each a new variable) also keep off the prefixes the targets' own
    names use; claimed names (`claim`: the seed's uniforms, app data and vertex data, which several
    nodes ask for by one name) are the same variable for the same wanted name."""

    def __init__(self, reserved: frozenset[str], reserved_prefixes: tuple[str, ...],
                 reserved_suffixes: tuple[str, ...] = ()):
        self.reserved = reserved
        self.reserved_prefixes = reserved_prefixes
        self.reserved_suffixes = reserved_suffixes
        self.used: set[str] = set()
        self.claimed: dict[str, str] = {}  # wanted -> its name, for claimed names
        self.claimed_used: set[str] = set()

    def __call__(self, wanted: str, avoid: frozenset[str] = frozenset()) -> str:
        name = identifier(wanted)
        if name.startswith(self.reserved_prefixes):
            name = "v_" + name
        if name.endswith(self.reserved_suffixes):
            name += "_v"
        used = self.used
        if name not in used and name not in self.reserved and name not in avoid:  # (most names: free)
            used.add(name)
            return name
        return _unique(name, lambda n: n in used or n in self.reserved or n in avoid, used)

    def claim(self, wanted: str) -> str:
        # a claimed name is the seed's (`u_time`, RESERVED for fresh names) or prefixed by its kind
        # (`i_geomprop_<name>`, `texcoord_0`): no keyword, only other claimed names to avoid
        if wanted not in self.claimed:
            self.claimed[wanted] = _unique(identifier(wanted), self.claimed_used.__contains__, self.claimed_used)
        return self.claimed[wanted]


def _unique(name: str, taken, used: set[str]) -> str:
    base, n = name, 1
    while taken(name):
        name = f"{base}{n}"
        n += 1
    used.add(name)
    return name


class EmitContext:
    """Shared state of one generation; node implementations write through it, in the IR
    (code/ir.py): values are IR expressions, statements go to `body` (a code.build.Builder)."""

    def __init__(self, target, scope: Scope, values_in_source: bool = False, names: str = "structural"):
        self.values_in_source = values_in_source  # uniform initializers hold the document's values
        self.names = SourceNames(names)  # what the source calls what the document names (naming.py)
        self.target = target  # the Target: its names, closure convention and stage assembly
        self.scope = scope
        self.code = scope.library.code()  # the library's code in the IR (code/library.py)
        self.stages = {VERTEX: Stage(VERTEX), PIXEL: Stage(PIXEL)}
        self.namer = Namer(target.reserved, target.reserved_prefixes, target.reserved_suffixes)
        self.closure = None  # shading context for BSDF nodes (see nodes/base.py)
        self.vars: dict[int, ir.Expr] = {}  # id(Output | Input | Socket) -> the expression of its value
        self.used_types: set[str] = set()  # MaterialX types of the variables declared
        self.body: Builder = self.pixel.main
        self.vertex_main: dict[str, ir.Stmt] = {}  # vertex data member -> the statement assigning it
        self.function_names: dict[int, str] = {}  # id(Function) -> its name in the shader
        self.memo: dict = {}  # per-shader facts implementations compute once (e.g. which lights exist)
        self.lobe_weights: dict[int, ir.Expr] = {}  # id(lobe's weight Input) -> its weight at this point
        self.prepared_lobes: dict[int, ir.Expr] = {}  # id(lobe Node) -> its prepared state, in this surface
        self.features: frozenset[str] | None = None  # library features the nodes need (None: all)
        self.macros: frozenset[tuple[str, bool]] = frozenset()  # compiler macros decided at generation
        self.lights = True  # whether the shader is drawn with a light rig (Graph.lights)
        self.texture_width = None  # OSL's texture() filter width (Graph.texture_width)
        self.luts: dict[str, dict] = {}  # private texture uniform -> its texels (a colour transform's LUT)

    @property
    def pixel(self) -> Stage:
        return self.stages[PIXEL]

    @property
    def vertex(self) -> Stage:
        return self.stages[VERTEX]

    # -- values ----------------------------------------------------------------------------
    def value(self, inp: Input) -> ir.Expr:
        if id(inp) in self.lobe_weights:
            return self.lobe_weights[id(inp)]
        if inp.connection is not None:
            return self.vars[id(inp.connection)]
        if inp.socket is not None:
            return self.vars[id(inp.socket)]
        if inp.public:
            return self.vars[id(inp)]
        return value_expr(inp.type, inp.value, inp.meta)

    def publish(self, port: Input | Socket) -> ir.Name:
        """A public input (or the socket several inputs of an expanded body share) as a uniform."""
        listing_type = "integer" if port.type == "string" and port.meta.get("enum") else port.type
        value = listing_value(port, port.value)
        # Value-free source (complete, reduced): initialised to the nodedef's value, so materials that
        # differ only in values share one source; the values reach the program from the listing.
        initializer = value if self.values_in_source else listing_value(port, port.default)
        # a uniform is a global every library function could see: none of their names
        name = self.namer(self.names.uniform(port), self.code.identifiers)
        self.add_variable(PIXEL, "PublicUniforms", Variable(
            name, listing_type, value, port.path, unit=port.meta.get("unit"), colorspace=port.meta.get("colorspace"),
            ui=port.meta.get("ui"), initializer=initializer,
            fallback=image_fallback(port) if port.type == "filename" else None))
        self.vars[id(port)] = expr = build.name(name, "uniform", ir_type(listing_type))
        return expr

    def output_name(self, out: Output) -> str:
        if id(out) not in self.vars:
            self.vars[id(out)] = build.name(self.namer(f"{self.names.node(out.node)}_{out.name}"), "local",
                                            ir_type(out.type))
            self.used_types.add(out.type)
        return self.vars[id(out)].name

    def assign(self, out: Output, expression: ir.Expr) -> None:
        self.assign_made(out, (expression,), lambda: expression)

    def assign_made(self, out: Output, parts: tuple, make) -> None:
        """`out` declared with the value `make()` builds from `parts` (the expressions it reads,
        with whatever else decides it)."""
        type_name, name = ir_type(out.type), self.output_name(out)
        self.add_alike(("assign", type_name, name, *parts), lambda: ir.Declare(type_name, name, make(), False))

    def declare(self, out: Output) -> ir.Name:
        type_name, name = ir_type(out.type), self.output_name(out)
        # closure functions accumulate into their result: it starts from zero
        zero = value_expr(out.type, None) if out.type in CLOSURES else None
        self.add_alike(("declare", type_name, name, zero), lambda: ir.Declare(type_name, name, zero, False))
        return self.vars[id(out)]  # (output_name's)

    def call(self, function: str, node: Node) -> None:
        outs = [self.declare(o) for o in node.outputs.values()]
        prepared = self.prepared_lobes.get(id(node))
        if prepared is not None:  # its inputs were read once, by its preparation
            args = [prepared] + outs
        else:
            args = [self.value(i) for i in node.inputs.values()] + outs
        if is_closure_node(node):
            args = self.target.closures.arguments() + args
        self.call_statement(function, args)

    def call_statement(self, function: str, args: list[ir.Expr]) -> None:
        # a call of a function this request wrote is decided by that function too (its body)
        written = any(f.name == function for f in self.pixel.generated)
        self.add_alike(None if written else ("call", function, *args),
                       lambda: ir.ExprStatement(build.call(function, *args)))

    def local(self, type_name: str, name: str) -> ir.Name:
        """A variable of the body being written, declared without a value (a prepared lobe's state)."""
        self.add_alike(("declare", type_name, name, None), lambda: ir.Declare(type_name, name, None, False))
        return build.name(name, "local", type_name)

    def add_alike(self, parts: tuple | None, make) -> None:
        """Adds the statement `make()` builds from `parts` (what decides it: its kind, the names it
        declares, the expressions it reads) to main; or the one an earlier request built from
        alike parts and typed then, without building it (code/statements.py `Memo.alike`)."""
        stage = self.pixel
        if parts is None or self.body is not stage.main:  # (a generated function's body is typed whole)
            self.body.add(make())
            return
        key = alike_key(parts)
        found = self.code.statements.built_alike(key) if key is not None else None
        if found is not None:
            statement, stage.alike_found[id(statement)] = found
            self.body.add(statement)
            return
        statement = make()
        self.body.add(statement)
        if key is not None:
            stage.alike_fresh.append((key, statement))

    # -- variables ---------------------------------------------------------------------------
    def add_variable(self, stage: str, block: str, var: Variable) -> Variable:
        self.used_types.add(var.type)
        return self.stages[stage].blocks[block].add(var)

    def private_uniform(self, name: str, type_name: str, stages=(PIXEL,)) -> ir.Name:
        name = self.namer.claim(name)
        for s in stages:
            self.add_variable(s, "PrivateUniforms", Variable(name, type_name))
        return build.name(name, "uniform", ir_type(type_name))

    def app_data(self, name: str, type_name: str, value: object = None) -> ir.Name:
        """A vertex stream; `value`, in the listing, is what the stream holds where a mesh lacks it."""
        name = self.namer.claim(name)
        self.add_variable(VERTEX, "AppData", Variable(name, type_name, value))
        return build.name(name, "input", ir_type(type_name))

    def vertex_data(self, name: str, type_name: str, vertex_expression: ir.Expr) -> ir.Name:
        """A value computed per vertex and interpolated: declared in both stages, assigned once in
        the vertex stage's main. Returns how the pixel stage reads it."""
        name = self.namer.claim(name)
        for s in (VERTEX, PIXEL):
            self.add_variable(s, "VertexData", Variable(name, type_name))
        member = build.name(name, "vertexdata", ir_type(type_name))
        self.vertex_main.setdefault(name, ir.Assign("=", member, vertex_expression))
        return member

    # -- functions -------------------------------------------------------------------------------
    def emit_modules(self, paths: tuple[str, ...]) -> None:
        """Library source files (dependencies first), each once: their items join the stage's, for
        the passes to keep what main reaches (code/passes/)."""
        for path in paths:
            if self.pixel.once(("file", path)):
                self.pixel.items.extend(self.code.module(path).items)

    def add_function(self, function: ir.Function) -> None:
        """A function the generator wrote: printed after the library code, which it may call."""
        self.pixel.generated.append(function)

    def emit_graph_function(self, function: Function) -> None:
        """A nodegraph body shared by several calls, written once."""
        if id(function) in self.function_names:
            return
        self.function_names[id(function)] = fname = self.namer(self.names.function(function))
        saved_body, saved_vars = self.body, self.vars
        self.body, self.vars = Builder(), dict(saved_vars)
        params = []
        for s in function.params:
            pname = self.namer(f"{fname}_{s.name}")
            self.vars[id(s)] = build.name(pname, "param", ir_type(s.type))
            params.append(("in", ir_type(s.type), pname))
            self.used_types.add(s.type)
        out_params = [(self.namer(f"{fname}_{out.name}"), out) for out in function.outputs]
        try:
            self.define_functions(function.graph)
            self.emit_nodes(function.graph, ())
            for p, out in out_params:
                self.body.assign(build.name(p, "param", ir_type(out.type)), self.vars[id(out)])
            params += [("out", ir_type(o.type), p) for p, o in out_params]
            self.add_function(build.function("void", fname, params, self.body.block()))
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
        closures = self.target.closures
        for node in graph.nodes:
            if is_closure_node(node) and self.closure is None and not closures.values:
                continue  # closures are evaluated per shading context by the surface that reads them
            if node.scope == scope:
                if closures.claims(node):  # closures that are values of the language (OSL)
                    closures.emit_closure(self, node)
                elif id(node) in branching:
                    self.emit_branches(graph, node)
                else:
                    node.impl.emit_function_call(node, self)

    def emit_lobes(self, inp: Input, point_arguments) -> None:
        """Once per shading point, before its contexts: the lobes' weights at this point and their
        prepared states (nodes/lobes.py)."""
        emit_lobes(self, inp, point_arguments)

    def closure_nodes(self, inp: Input) -> list[Node]:
        """The closure nodes `inp` reads, readers first (nodes/lobes.py): walked once per shader,
        read by the shading point and by every context."""
        key = ("closure_nodes", id(inp))
        if key not in self.memo:
            self.memo[key] = closure_nodes(inp)
        return self.memo[key]

    def emit_closures(self, inp: Input, context: str) -> ir.Expr:
        """Evaluate the closure nodes upstream of `inp` in one shading context (seed's
        SgNodeContext): the caller has declared `closureData` for that context. Data nodes feeding
        the closures were computed once, before. Returns the expression of the result."""
        saved = self.closure
        self.closure = context
        # The calls are alike in every context (what a closure function does in each is decided
        # by the closure data it is passed): the first context's statements serve the others too,
        # the same objects, built, keyed and typed once (code/statements.py, code/generated.py).
        key = ("closure_statements", id(inp))
        try:
            emitted = self.memo.get(key)
            if emitted is not None:
                self.body.statements.extend(emitted)
            else:
                start = len(self.body.statements)
                for node in self.closure_nodes(inp)[::-1]:  # what a closure reads before it
                    node.impl.emit_function_call(node, self)
                self.memo[key] = self.body.statements[start:]
        finally:
            self.closure = saved
        return self.value(inp)

    def emit_branches(self, graph: Graph, node: Node) -> None:
        """A conditional whose branches have nodes of their own: if/else, each branch computing
        only what it needs (seed 2.4 step 5)."""
        out = next(iter(node.outputs.values()))
        result = self.declare(out)
        with self.body.chain() as chain:
            for branch, condition in self.branch_conditions(node):
                with chain.clause(condition):
                    if branch is None:  # no input selected: the type's zero, as the inline form gives
                        self.body.assign(result, value_expr(out.type, None))
                        continue
                    self.emit_nodes(graph, node.scope + ((node, branch),))
                    self.body.assign(result, self.value(node.inputs[branch]))

    def branch_conditions(self, node: Node) -> list[tuple[str | None, ir.Expr | None]]:
        """(branch input, condition) in order; a None condition is the final else."""
        if node.category in CONDITIONS:
            v1, v2 = self.value(node.inputs["value1"]), self.value(node.inputs["value2"])
            return [("in1", build.binary(CONDITIONS[node.category], v1, v2)), ("in2", None)]
        which = node.inputs["which"]
        w = self.value(which)
        names = [n for n in BRANCH_INPUTS["switch"] if n in node.inputs]
        # `which` below k selects input k; from the number of inputs on, none is selected
        bound = build.integer if which.type == "integer" else build.number
        return [(n, build.binary("<", w, bound(k))) for k, n in enumerate(names, start=1)] + [(None, None)]


def listing_value(port: Input | Socket, value):
    """A value as the uniform holds it: enum strings are their index, an empty string is none."""
    if port.type == "string":
        if port.meta.get("enum"):
            return enum_index(value, port.meta)
        if value == "":
            return None
    return value


def image_fallback(file: Input | Socket):
    """The value of the image node's `default` input beside a filename, when it is fixed (it may be
    folded into the code, so a renderer could not find it among the uniforms): what the node gives
    when its file is missing or unreadable. None when the node has no constant default."""
    default = file.owner.inputs.get("default")
    seen = set()
    # a body's input bound to its node's; a body kept as a function binds the node's own input to
    # its parameter, whose origin is that input again
    while default is not None and default.socket is not None and id(default) not in seen:
        seen.add(id(default))
        default = default.socket.origin
    if default is None or default.connection is not None:
        return None
    return default.value


def is_closure_node(node: Node) -> bool:
    for o in node.outputs.values():  # (a loop, not any(): asked of every node in every request)
        if o.type in CLOSURES:
            return True
    return False


def assign_outputs(ctx: EmitContext, graph: Graph) -> None:
    for name, out in graph.outputs.items():
        if out.type in ("filename", "string"):
            raise ShaderGenError("unsupported_output", f"a {out.type} output cannot be drawn", name)
        if out.type in CLOSURES:  # a lobe has no colour until a surface shader lights it
            raise ShaderGenError("unsupported_output", f"a {out.type} output cannot be drawn by itself: "
                                 "connect it to a surface shader", name)
        var = ctx.namer(ctx.names.output(name))
        if ctx.target.closures.values and out.type in SHADERS:  # the closure itself (OSL)
            ctx.add_variable(PIXEL, "Outputs", Variable(var, out.type))
            value = ctx.vars[id(out)]
            ctx.body.assign(build.name(var, "output", value.type), value)
            continue
        ctx.add_variable(PIXEL, "Outputs", Variable(var, "color4"))
        ctx.body.assign(build.name(var, "output", "vec4"), output_color(out.type, ctx.vars[id(out)]))


def output_color(type_name: str, v: ir.Expr) -> ir.Expr:
    """Every pixel output is an RGBA colour."""
    one = build.number(1.0)
    if type_name in ("float", "integer", "boolean"):
        s = v if type_name == "float" else build.convert("float", v)
        return build.construct("vec4", s, s, s, one)
    if type_name == "vector2":
        return build.construct("vec4", v, build.number(0.0), one)
    if type_name in ("vector3", "color3"):
        return build.construct("vec4", v, one)
    if type_name in ("vector4", "color4"):
        return v
    if type_name in ("surfaceshader", "material", "volumeshader"):
        # colour is premultiplied (the surface scaled it by its opacity); alpha is what it covers
        third = build.construct("vec3", build.binary("/", one, build.number(3.0)))
        covered = build.binary("-", one, build.call("dot", build.field(v, "transparency"), third))
        return build.construct("vec4", build.field(v, "color"), covered)
    return build.construct("vec4", build.number(0.0), build.number(0.0), build.number(0.0), one)


def emit_shader(ctx: EmitContext, graph: Graph) -> dict[str, str]:
    ctx.private_uniform("u_worldMatrix", "matrix44", (VERTEX,))
    ctx.private_uniform("u_viewProjectionMatrix", "matrix44", (VERTEX,))
    ctx.app_data("i_position", "vector3")
    for node in graph.nodes:  # labelled first: a node's structural name is its place in the topological order
        ctx.names.node(node)
    for port in graph.interface:
        ctx.publish(port)
    ctx.features = frozenset(graph_features(graph) | ({LIGHTS_FEATURE} if graph.lights else set()))
    ctx.macros = environment_macros(graph.environment)
    ctx.lights = graph.lights
    ctx.texture_width = graph.texture_width
    ctx.define_functions(graph)
    ctx.emit_nodes(graph, ())
    assign_outputs(ctx, graph)
    finish(ctx, graph.interface_mode == "specialized", graph.passes)
    stages = {VERTEX: code_passes.vertex_stage(ctx), PIXEL: code_passes.pixel_stage(ctx)}
    return {name: text for name, text in stages.items() if text is not None}  # OSL has no vertex stage


def finish(ctx: EmitContext, variables: bool, counts: dict) -> None:
    """The stage's code typed and trimmed by the code passes (code/passes/): library sections
    resolved for the shader's features, only what main reaches kept, struct members nothing reads
    and calls through forwarding functions removed. With `variables` (specialized), uniforms
    nothing reads and vertex data the pixel stage does not read are dropped too, from the code
    and from the listings."""
    ctx.pixel.code = stages = code_passes.run(ctx, counts)
    if variables:
        used = stages.pixel_names
        blocks = ctx.pixel.blocks
        for block in ("PrivateUniforms", "PublicUniforms"):
            blocks[block].variables = {n: v for n, v in blocks[block].variables.items() if n in used}
        if "u_lightData" not in blocks["PrivateUniforms"]:
            blocks["LightData"].variables = {}
        read = {n for n in blocks["VertexData"].variables if n in used}
        for stage in ctx.stages.values():
            stage.blocks["VertexData"].variables = {n: v for n, v in stage.blocks["VertexData"].variables.items()
                                                    if n in read}
        ctx.vertex_main = {n: s for n, s in ctx.vertex_main.items() if n in read}
        vertex_used = set(collect(ctx.vertex_main.values()).names) | FIXED_VERTEX
        for block in ("AppData", "PrivateUniforms"):
            vb = ctx.vertex.blocks[block]
            vb.variables = {n: v for n, v in vb.variables.items() if n in vertex_used}


FIXED_VERTEX = {"i_position", "u_worldMatrix", "u_viewProjectionMatrix"}  # the position transform always runs
