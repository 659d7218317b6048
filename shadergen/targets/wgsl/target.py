"""The WGSL target: the same hooks as the GLSL target (glsl_target.py), spelled for WebGPU.

Two modules, one per stage (the record keeps its vertex and pixel texts): `vertexMain` and
`fragmentMain`. Each stage's uniforms live in one uniform buffer (group 0 the vertex stage's,
group 1 the pixel stage's, binding 0), laid out by WGSL's alignment rules (layout.py); the code
reads them by their GLSL names through the buffer (`pu.name`). Vertex data is one struct,
`VertexData`, returned by the vertex stage and kept in a private variable `vd` in the pixel stage
so functions may read it as GLSL's `vd.` block does.

The node libraries are the GLSL ones, translated when first used (translate.py).
"""
import re
from contextlib import contextmanager

from ...errors import ShaderGenError
from ...shader import PIXEL, VERTEX, Variable, Writer
from ..deadcode import used_functions
from ..glsl import LIGHT_DATA_MEMBERS, STRUCTS, TYPE_NAMES, ClosureConvention, Syntax, _float
from ..glsl_target import PLACEHOLDER, GlslTarget
from .builtins import HELPERS, RUNTIME_TYPES, WGSL_TYPES
from .layout import uniform_layout
from .translate import FRAGMENT_BUILTINS, Translator, Untranslatable

_TRANSLATOR: Translator | None = None
HELPER_LINES = HELPERS.splitlines() + [""]  # the same str objects each request, as the libraries' lines


def translator() -> Translator:
    """One translator per process: library files are translated once, on first use."""
    global _TRANSLATOR
    if _TRANSLATOR is None:
        from ...nodes.surface import ENVIRONMENT_UNIFORMS  # the uniforms the PBR library reads
        uniforms = {name: TYPE_NAMES[t] for name, t in ENVIRONMENT_UNIFORMS}
        uniforms |= {"u_numActiveLightSources": "int", "u_lightData": "LightData[]"}
        _TRANSLATOR = Translator(STRUCTS, uniforms)
    return _TRANSLATOR


def wgsl_type(type_name: str) -> str:
    glsl = TYPE_NAMES.get(type_name, type_name)
    return WGSL_TYPES.get(glsl, glsl)


class WgslSyntax(Syntax):
    name = "wgsl"
    uniform_initializers = False  # values come from the listing, through the uniform buffer

    def type_name(self, type_name: str) -> str:
        return wgsl_type(type_name)

    def literal(self, type_name: str, value, meta: dict | None = None) -> str:
        if type_name in self.struct_types:
            text, _ = translator().expression(super().literal(type_name, value, meta), {})
            return text
        text = super().literal(type_name, value, meta)
        if type_name in ("matrix33", "matrix44") and isinstance(value, tuple):
            return f"{wgsl_type(type_name)}({', '.join(_float(v) for v in value)})"
        return text

    def struct_definitions(self, used: set[str]) -> list[str]:
        return translator().structs(used | ({"surfaceshader"} if "material" in used else set()))

    def vertex_data_member(self, name: str) -> str:
        return f"vd.{name}"


class WgslTarget(GlslTarget):
    name = "wgsl"
    syntax_class = WgslSyntax
    closures = ClosureConvention()

    def __init__(self):
        super().__init__()
        self.pointer_parameters: dict[str, list[bool]] = {}  # graph function -> which parameters are outputs
        self.texture_parameters: dict[str, list[bool]] = {}  # graph function -> which are a texture and sampler
        self.outputs_in_scope: set[str] = set()

    # -- statements ------------------------------------------------------------------------------
    def declare(self, type_name: str, name: str, expression: str | None = None) -> str:
        t = self.syntax.type_name(type_name)
        return f"var {name}: {t};" if expression is None else f"var {name}: {t} = {expression};"

    def assign(self, target: str, expression: str) -> str:
        return f"{'*' if target in self.outputs_in_scope else ''}{target} = {expression};"

    def call(self, function: str, args: list[str]) -> str:
        outputs = self.pointer_parameters.get(function)
        if outputs is not None:
            args = [f"{a}, {a}_sampler" if texture else a for a, texture in zip(args, self.texture_parameters.get(function, [False] * len(args)))]
        else:
            signature = translator().signature(function)
            if signature is None:
                raise ShaderGenError("unsupported_node", f"'{function}' has no WGSL translation", function)
            function = signature.name
            args = [f"{a}, {a}_sampler" if t == "sampler2D" else a for a, (_, t, _) in zip(args, signature.params)]
            outputs = [q != "in" for q, _, _ in signature.params]
        return f"{function}({', '.join('&' + a if out else a for a, out in zip(args, outputs))});"

    def function_opener(self, name: str, params: list[tuple[str, str]], outputs: list[tuple[str, str]]) -> str:
        self.pointer_parameters[name] = [False] * len(params) + [True] * len(outputs)
        self.texture_parameters[name] = [t == "filename" for t, _ in params] + [False] * len(outputs)
        self.outputs_in_scope = {n for _, n in outputs}
        parts = [f"{n}: texture_2d<f32>, {n}_sampler: sampler" if t == "filename" else f"{n}: {self.syntax.type_name(t)}"
                 for t, n in params]
        parts += [f"{n}: ptr<function, {self.syntax.type_name(t)}>" for t, n in outputs]
        return f"fn {name}({', '.join(parts)})"

    # -- expressions the dynamic nodes write -------------------------------------------------------
    def inline(self, expression: str, inputs: dict[str, tuple[str, str]]) -> str:
        """A library's inline expression (GLSL) with its inputs' values: translated with their types."""
        names = {f"inline_{k}": v for k, v in inputs.items()}
        if inputs and all(_literal(v) for v, _ in inputs.values()) and not PLACEHOLDER.fullmatch(expression.strip()):
            names = {k: (f"mx_runtime_{wgsl_type(t)}({v})" if wgsl_type(t) in RUNTIME_TYPES else v, t)
                     for k, (v, t) in names.items()}  # see builtins.RUNTIME_TYPES
        template = PLACEHOLDER.sub(r"inline_\1", expression)
        try:
            text, _ = translator().expression(template, {k: TYPE_NAMES.get(t, t) for k, (_, t) in names.items()})
        except Untranslatable as e:
            raise Untranslatable(e.message.removeprefix("no WGSL translation: "), expression) from None
        return re.sub(r"\binline_\w+\b", lambda m: _primary(names[m.group()][0]), text)

    def library_source(self, path: str, text: str) -> str:
        try:
            return translator().file(path, text)
        except Untranslatable as e:
            raise Untranslatable(e.message.removeprefix("no WGSL translation: "), path) from None

    def select(self, condition: str, if_true: str, if_false: str) -> str:
        return f"select({if_false}, {if_true}, {condition})"

    def count_loop(self, index: str, bound: str) -> str:
        return f"for (var {index}: i32 = 0; {index} < {bound}; {index}++)"

    def emit_light_dispatch(self, ctx, lights: list[tuple[int, str]]) -> None:
        ctx.used_types.update(("LightData", "lightshader"))
        for name, type_name in LIGHT_DATA_MEMBERS:
            ctx.add_variable(PIXEL, "LightData", Variable(name, type_name))
        self.pointer_parameters["sampleLightSource"] = [False, False, True]
        w = ctx.pixel.functions
        with _braces(w, "fn numActiveLightSources() -> i32"):
            w.line("return min(u_numActiveLightSources, MAX_LIGHT_SOURCES);")
        w.line()
        with _braces(w, "fn sampleLightSource(light: LightData, position: vec3f, result: ptr<function, lightshader>)"):
            w.line("(*result).intensity = vec3f(0.0);")
            w.line("(*result).direction = vec3f(0.0);")
            for i, (type_id, function) in enumerate(lights):
                w.line(f"{'if' if i == 0 else 'else if'} (light.type_ == {type_id}) {{ {function}(light, position, result); }}")
        w.line()

    # -- stage assembly ----------------------------------------------------------------------------
    def used_functions(self, function_lines: list[str], roots: str) -> tuple[list[str], set[str]]:
        """The functions main reaches, WGSL's stand-ins for GLSL built-ins among them."""
        return used_functions(HELPER_LINES + function_lines, roots)

    def layout(self, ctx) -> dict:
        """Byte offsets of every uniform in its stage's buffer, and the texture bindings."""
        return {stage: uniform_layout(ctx.stages[stage], group) for group, stage in enumerate((VERTEX, PIXEL))}

    def _uniform_struct(self, stage, group: int, instance: str, w: Writer) -> dict[str, str]:
        """The stage's uniform buffer; returns how the code reads each uniform."""
        layout = uniform_layout(stage, group)
        reads = {}
        if layout["members"]:
            struct = f"{stage.name.capitalize()}Uniforms"
            with _braces(w, f"struct {struct}"):
                for m in layout["members"]:
                    w.line(f"{m['name']}: {m['wgsl']},  // offset {m['offset']}")
            w.line(f"@group({group}) @binding(0) var<uniform> {instance}: {struct};")
            w.line()
            for m in layout["members"]:
                read = f"{instance}.{m['name']}"
                reads[m["name"]] = f"({read} != 0)" if m["type"] == "boolean" else read
        for t in layout["textures"]:
            w.line(f"@group({group}) @binding({t['texture_binding']}) var {t['name']}: texture_2d<f32>;")
            w.line(f"@group({group}) @binding({t['sampler_binding']}) var {t['name']}_sampler: sampler;")
        if layout["textures"]:
            w.line()
        return reads

    def _vertex_data_struct(self, stage, w: Writer) -> None:
        with _braces(w, "struct VertexData"):
            w.line("@builtin(position) position: vec4f,")
            for i, v in enumerate(stage.blocks["VertexData"]):
                w.line(f"@location({i}) {v.name}: {self.syntax.type_name(v.type)},")
        w.line()

    def assemble_pixel(self, ctx) -> str:
        w = Writer()
        structs = self.syntax.struct_definitions({t for t in ctx.used_types if t in STRUCTS})
        for s in structs:
            w.line(s)
        if structs:
            w.line()
        reads = self._uniform_struct(ctx.pixel, 1, "pu", w)
        interpolated = len(ctx.pixel.blocks["VertexData"]) > 0
        if interpolated:
            self._vertex_data_struct(ctx.pixel, w)
            w.line("var<private> vd: VertexData;")
            w.line()
        outputs = list(ctx.pixel.blocks["Outputs"])
        if len(outputs) != 1:
            raise ShaderGenError("unsupported_output", "wgsl shaders have exactly one output", "wgsl")
        builtins = self._fragment_builtins(ctx.pixel.functions.lines + ctx.pixel.main.lines)
        for name, wgsl_type in builtins:
            w.line(f"var<private> {name}: {wgsl_type};")
        if builtins:
            w.line()
        w.lines.extend(ctx.pixel.functions.lines)
        w.line("@fragment")
        parameters = (["vertexData: VertexData"] if interpolated else []) + \
            [f"@builtin({name}) {name}_in: {wgsl_type}" for name, wgsl_type in builtins]
        with _braces(w, f"fn fragmentMain({', '.join(parameters)}) -> @location(0) vec4f"):
            if interpolated:
                w.line("vd = vertexData;")
            for name, _ in builtins:
                w.line(f"{name} = {name}_in;")
            w.line(f"var {outputs[0].name}: vec4f;")
            w.lines.extend("    " + ln if ln else "" for ln in ctx.pixel.main.lines)
            w.line(f"return {outputs[0].name};")
        return _read_through(w.text(), reads)

    def _fragment_builtins(self, lines: list[str]) -> list[tuple[str, str]]:
        """The fragment built-ins (WGSL name, type) the code reads: the entry point receives them."""
        text = "\n".join(lines)
        return [(name, self.syntax.type_name("boolean" if t == "bool" else t)) for name, t in FRAGMENT_BUILTINS.values()
                if re.search(rf"\b{name}\b", text)]

    def assemble_vertex(self, ctx) -> str:
        w = Writer()
        reads = self._uniform_struct(ctx.vertex, 0, "vu", w)
        inputs = list(ctx.vertex.blocks["AppData"])
        with _braces(w, "struct AppData"):
            for i, v in enumerate(inputs):
                w.line(f"@location({i}) {v.name}: {self.syntax.type_name(v.type)},")
        w.line()
        self._vertex_data_struct(ctx.vertex, w)
        w.line("@vertex")
        with _braces(w, "fn vertexMain(vin: AppData) -> VertexData"):
            w.line("var vd: VertexData;")
            w.line("let hPositionWorld = u_worldMatrix * vec4f(i_position, 1.0);")
            w.line("vd.position = u_viewProjectionMatrix * hPositionWorld;")
            for line in ctx.vertex_main.values():
                w.line(line)
            w.line("return vd;")
        return _read_through(w.text(), reads | {v.name: f"vin.{v.name}" for v in inputs})


@contextmanager
def _braces(w: Writer, opener: str):
    """WGSL's own style: the brace on the opener's line."""
    w.line(opener + " {")
    w.depth += 1
    try:
        yield
    finally:
        w.depth -= 1
        w.line("}")


def _primary(text: str) -> str:
    """An operand as it can stand in any expression: names and calls as they are, anything else (a
    negative literal, an operator) in parentheses."""
    return text if re.fullmatch(r"[\w.]+|\w+\((?:[^()]|\([^()]*\))*\)", text) else f"({text})"


LITERAL_WORDS = set(WGSL_TYPES.values()) | {"true", "false"}


def _literal(text: str) -> bool:
    """Nothing in it is read at run time: numbers, and type constructors of numbers."""
    return all(word in LITERAL_WORDS for word in re.findall(r"\b[A-Za-z_]\w*", text))


def _read_through(text: str, reads: dict[str, str]) -> str:
    """Bare uniform and input names read through their buffer or struct (not declarations or members)."""
    if not reads:
        return text
    pattern = re.compile(r"(?<![\w.])(" + "|".join(map(re.escape, sorted(reads, key=len, reverse=True))) + r")\b(?!\s*:)")
    return pattern.sub(lambda m: reads[m.group(1)], text)

