"""The GLSL target (and ESSL, its variant): the hooks the generator and the dynamic nodes write
through, so that neither holds any GLSL text.

A target is a Syntax (lexical facts: type names, literals, declarations) plus these hooks:
statements (declare, assign, call, branch), expressions the dynamic nodes need (normalize, a
matrix transform, a cross product, a component, a conversion), function signatures, the closure
calling convention (the shading-context argument, the surface's contexts, the light dispatch), and
stage assembly (header, structs, variable blocks, functions, main). A WGSL or OSL target
implements the same hooks.
"""
import re

from ..shader import PIXEL, Variable, Writer
from .deadcode import used_functions
from .glsl import LIGHT_DATA_MEMBERS, STRUCTS, ClosureConvention, EsslSyntax, GlslSyntax, Syntax

PLACEHOLDER = re.compile(r"\{\{\s*(\w+)\s*\}\}")
CONDITION_OPERATORS = {"greater": ">", "greatereq": ">=", "equal": "=="}


class GlslTarget:
    name = "glsl"
    library = "genglsl"  # the implementation target of the node libraries
    syntax_class: type[Syntax] = GlslSyntax
    closures = ClosureConvention()

    def __init__(self):
        self.syntax = self.syntax_class()

    # -- statements --------------------------------------------------------------------------
    def declare(self, type_name: str, name: str, expression: str | None = None) -> str:
        t = self.syntax.type_name(type_name)
        return f"{t} {name};" if expression is None else f"{t} {name} = {expression};"

    def assign(self, target: str, expression: str) -> str:
        return f"{target} = {expression};"

    def call(self, function: str, args: list[str]) -> str:
        return f"{function}({', '.join(args)});"

    def function_opener(self, name: str, params: list[tuple[str, str]], outputs: list[tuple[str, str]]) -> str:
        """The signature of a function with value parameters and output parameters, (type, name)."""
        parts = [f"{self.syntax.type_name(t)} {n}" for t, n in params]
        parts += [f"out {self.syntax.type_name(t)} {n}" for t, n in outputs]
        return f"void {name}({', '.join(parts)})"

    def count_loop(self, index: str, bound: str) -> str:
        """`for` an integer from 0 up to `bound`."""
        return f"for (int {index} = 0; {index} < {bound}; ++{index})"

    def branch_opener(self, index: int, condition: str | None) -> str:
        """The k-th branch of an if/else chain; no condition is the final else."""
        if condition is None:
            return "else"
        return f"{'if' if index == 0 else 'else if'} ({condition})"

    def compare(self, kind: str, a: str, b: str) -> str:
        return f"{a} {CONDITION_OPERATORS[kind]} {b}"

    def select(self, condition: str, if_true: str, if_false: str) -> str:
        return f"{condition if condition.isidentifier() else f'({condition})'} ? {if_true} : {if_false}"

    def below(self, value: str, bound: int, type_name: str) -> str:
        return f"{value} < {bound if type_name == 'integer' else f'{bound}.0'}"

    # -- library code ------------------------------------------------------------------------------
    def library_source(self, path: str, text: str) -> str:
        """A library function file as this target writes it (the libraries are GLSL)."""
        return text

    def inline(self, expression: str, inputs: dict[str, tuple[str, str]]) -> str:
        """A library's inline expression with its inputs' values, `inputs`: name -> (value, type)."""
        return PLACEHOLDER.sub(lambda m: self.syntax.negative_safe(inputs[m.group(1)][0]), expression)

    def layout(self, ctx) -> dict | None:
        """Where a client puts each uniform, for targets whose uniforms live in buffers."""
        return None

    # -- expressions the dynamic nodes write -------------------------------------------------------
    def normalize(self, e: str) -> str:
        return f"normalize({e})"

    def transform(self, matrix: str, e: str, point: bool) -> str:
        """A 3-vector through a 4x4 matrix, as a point (w 1) or a direction (w 0)."""
        return f"({matrix} * {self.syntax.type_name('vector4')}({e}, {'1.0' if point else '0.0'})).xyz"

    def cross(self, a: str, b: str) -> str:
        return f"cross({a}, {b})"

    def convert(self, e: str, type_name: str) -> str:
        return f"{self.syntax.type_name(type_name)}({e})"

    def components(self, e: str, which: str) -> str:
        """Components by colour letters (r, g, b, a)."""
        return f"{e}.{which}" if which else e

    def world_position(self) -> str:
        """The world-space position the vertex stage computes before anything else."""
        return "hPositionWorld.xyz"

    def output_color(self, type_name: str, v: str) -> str:
        """Every pixel output is an RGBA colour."""
        vec4 = self.syntax.type_name("color4")
        if type_name in ("float", "integer", "boolean"):
            s = v if type_name == "float" else self.convert(v, "float")
            return f"{vec4}({s}, {s}, {s}, 1.0)"
        if type_name == "vector2":
            return f"{vec4}({v}, 0.0, 1.0)"
        if type_name in ("vector3", "color3"):
            return f"{vec4}({v}, 1.0)"
        if type_name in ("vector4", "color4"):
            return v
        if type_name in ("surfaceshader", "material", "volumeshader"):
            # colour is premultiplied (the surface scaled it by its opacity); alpha is what it covers
            return f"{vec4}({v}.color, 1.0 - dot({v}.transparency, {self.convert('1.0 / 3.0', 'vector3')}))"
        return f"{vec4}(0.0, 0.0, 0.0, 1.0)"

    # -- closure calling convention ----------------------------------------------------------------
    def closure_arguments(self) -> list[str]:
        """What a closure function takes before its inputs: the shading context."""
        return ["closureData"]

    def emit_surface(self, ctx, result: str, opacity: str, position: str, normal: str,
                     contexts: list[tuple[str, object]]) -> None:
        """A surface shader: its closure inputs evaluated once per shading context, in order.
        `contexts`: (context, closure input), the context one of "reflection" (once per light),
        "indirect" (the environment), "emission", "transmission"."""
        w = ctx.body
        zero = self.convert("0.0", "color3")
        w.line(self.declare("surfaceshader", result, self.syntax.literal("surfaceshader", None)))
        with w.scope():
            w.line(self.declare("vector3", "N", f"normalize({normal})"))
            w.line(self.declare("vector3", "V", f"normalize(u_viewPosition - {position})"))
            w.line(self.declare("vector3", "P", position))
            w.line(self.declare("vector3", "L", zero))
            w.line(self.declare("float", "occlusion", "1.0"))
            w.line(self.declare("float", "surfaceOpacity", opacity))
            point: list[str] = []

            def point_arguments() -> list[str]:  # the closure data lobes are prepared with
                if not point:
                    w.line("// lobes prepared once per shading point, before any light")
                    w.line(self.declare("ClosureData", "pointData",
                                        "ClosureData(CLOSURE_TYPE_DEFAULT, L, V, N, P, occlusion)"))
                    point.append("pointData")
                return point

            for inp in {id(inp): inp for context, inp in contexts if context != "emission"}.values():
                ctx.emit_lobes(inp, point_arguments)
            for context, inp in contexts:
                if context == "reflection":
                    with w.block(self.count_loop("activeLightIndex", "numActiveLightSources()")):
                        w.line(self.declare("lightshader", "lightShader"))
                        w.line(self.call("sampleLightSource", ["u_lightData[activeLightIndex]", position, "lightShader"]))
                        w.line("L = lightShader.direction;")
                        self._context(ctx, inp, context, f"{result}.color += lightShader.intensity * {{}}.response;")
                    continue
                accumulate = {"indirect": f"{result}.color += occlusion * {{}}.response;",
                              "emission": f"{result}.color += {{}};",
                              "transmission": f"{result}.color += {{}}.response;"}[context]
                comment = {"indirect": "environment", "emission": "emission",
                           "transmission": "transmission, seen along the view direction"}[context]
                with w.scope(comment):
                    self._context(ctx, inp, context, accumulate)
            w.line(f"{result}.color *= surfaceOpacity;")
            one = self.convert("1.0", "color3")
            w.line(f"{result}.transparency = mix({one}, {result}.transparency, surfaceOpacity);")

    CONTEXTS = {"reflection": "CLOSURE_TYPE_REFLECTION", "indirect": "CLOSURE_TYPE_INDIRECT",
                "emission": "CLOSURE_TYPE_EMISSION", "transmission": "CLOSURE_TYPE_TRANSMISSION"}

    def _context(self, ctx, inp, context: str, accumulate: str) -> None:
        closure_type = self.CONTEXTS[context]
        ctx.body.line(self.declare("ClosureData", "closureData",
                                   f"ClosureData({closure_type}, L, V, N, P, occlusion)"))
        value = ctx.emit_closures(inp, context)
        ctx.body.line(accumulate.format(value))

    def emit_light_dispatch(self, ctx, lights: list[tuple[int, str]]) -> None:
        """LightData members, numActiveLightSources() and sampleLightSource() calling each light
        shader by its type id."""
        ctx.used_types.update(("LightData", "lightshader"))
        for name, type_name in LIGHT_DATA_MEMBERS:
            ctx.add_variable(PIXEL, "LightData", Variable(name, type_name))
        w = ctx.pixel.functions
        with w.block("int numActiveLightSources()"):
            w.line("return min(u_numActiveLightSources, MAX_LIGHT_SOURCES);")
        w.line()
        with w.block("void sampleLightSource(LightData light, vec3 position, out lightshader result)"):
            w.line("result.intensity = vec3(0.0);")
            w.line("result.direction = vec3(0.0);")
            for i, (type_id, function) in enumerate(lights):
                w.line(f"{'if' if i == 0 else 'else if'} (light.type == {type_id})")
                w.line(f"    {function}(light, position, result);")
        w.line()

    # -- stage assembly --------------------------------------------------------------------------
    def used_functions(self, function_lines: list[str], roots: str) -> tuple[list[str], set[str]]:
        return used_functions(function_lines, roots)

    def assemble_pixel(self, ctx) -> str:
        w = Writer()
        for line in self.syntax.header():
            w.line(line)
        w.line()
        structs = self.syntax.struct_definitions({t for t in ctx.used_types if t in STRUCTS})
        if structs:
            for s in structs:
                w.line(s)
            w.line()
        self._declarations(ctx.pixel, w)
        self._vertex_data(ctx.pixel, w, "in")
        for v in ctx.pixel.blocks["Outputs"]:
            w.line(f"out vec4 {v.name};")
        w.line()
        if ctx.pixel.functions.lines:
            w.lines.extend(ctx.pixel.functions.lines)
        with w.block("void main()"):
            w.lines.extend("    " + ln if ln else "" for ln in ctx.pixel.main.lines)
        return w.text()

    def assemble_vertex(self, ctx) -> str:
        w = Writer()
        for line in self.syntax.header():
            w.line(line)
        w.line()
        self._declarations(ctx.vertex, w)
        for v in ctx.vertex.blocks["AppData"]:
            w.line(f"in {self.syntax.type_name(v.type)} {v.name};")
        w.line()
        self._vertex_data(ctx.vertex, w, "out")
        with w.block("void main()"):
            w.line("vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);")
            w.line("gl_Position = u_viewProjectionMatrix * hPositionWorld;")
            for line in ctx.vertex_main.values():
                w.line(line)
        return w.text()

    def _declarations(self, stage, w: Writer) -> None:
        for block in ("PrivateUniforms", "PublicUniforms"):
            variables = list(stage.blocks[block])
            if variables:
                w.line(f"// Uniform block: {block}")
                for v in variables:
                    meta = {"enum": ""}  # listing values of enums are already indices
                    w.line(self.syntax.uniform_declaration(v.type, v.name, v.initializer, meta))
                w.line()

    def _vertex_data(self, stage, w: Writer, direction: str) -> None:
        members = list(stage.blocks["VertexData"])
        if not members:
            return
        if self.syntax.vertex_data_block:
            w.line(f"{direction} VertexData")
            w.line("{")
            for v in members:
                w.line(f"    {self.syntax.type_name(v.type)} {v.name};")
            w.line("} vd;")
        else:
            for v in members:
                w.line(f"{direction} {self.syntax.type_name(v.type)} {self.syntax.vertex_data_member(v.name)};")
        w.line()


class EsslTarget(GlslTarget):
    name = "essl"
    syntax_class = EsslSyntax

