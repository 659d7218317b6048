"""The WGSL target: the printer (printer.py), the stage assembler below, and the hardware closure
convention (targets/closures.py).

Two modules, one per stage (the record keeps its vertex and pixel texts): `vertexMain` and
`fragmentMain`. Each stage's uniforms live in one uniform buffer (group 0 the vertex stage's,
group 1 the pixel stage's, binding 0), laid out by WGSL's alignment rules (layout.py); the code
reads a uniform through its buffer (`pu.name`; a boolean, which travels as an i32, compared with
0). Vertex data is one struct, `VertexData`, returned by the vertex stage and kept in a private
variable `vd` in the pixel stage, so functions may read it as GLSL's `vd.` block. The fragment
built-ins the code reads (gl_FrontFacing) come in as the entry point's parameters, copied into
private variables.
"""
from functools import lru_cache

from ...code import ir
from ...code.passes.rewrite import items_in
from ...code.types import ir_type
from ...errors import ShaderGenError
from ...shader import PIXEL, VERTEX, Writer
from ..closures import ClosureConvention
from ..names import RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
from .layout import uniform_layout
from .printer import FRAGMENT_BUILTINS, WgslPrinter, function_names, helpers, safe_name, wgsl_type
from .runtime import Runtime


class WgslTarget:
    name = "wgsl"
    library = "genglsl"  # the node libraries' implementations, printed from their IR
    reserved, reserved_prefixes, reserved_suffixes = RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
    closures = ClosureConvention()

    def layout(self, ctx) -> dict:
        """Byte offsets of every uniform in its stage's buffer, and the texture bindings."""
        return {stage: uniform_layout(ctx.stages[stage], group) for group, stage in enumerate((VERTEX, PIXEL))}

    # -- stage assembly ----------------------------------------------------------------------------
    def assemble_pixel(self, ctx) -> str:
        code = ctx.pixel.code
        outputs = list(ctx.pixel.blocks["Outputs"])
        if len(outputs) != 1:
            raise ShaderGenError("unsupported_output", "wgsl shaders have exactly one output", "wgsl")
        booleans = self._booleans(ctx.pixel)
        runtime = Runtime()  # generated constant operations made run-time (runtime.py)
        main = runtime.statement(code.main)
        items = [runtime.statement(i) if isinstance(i, ir.Function) and i.where is None else i for i in code.functions]
        items = list(runtime.functions.values()) + items
        functions = [f for item in items for f in items_in(item) if isinstance(f, ir.Function)]
        names = function_names(functions)
        printer = WgslPrinter(names, lambda n: self._pixel_name(n, booleans))
        key = (frozenset(names.items()), booleans)
        w = Writer()
        for item in code.structs:
            w.extend(library_item(printer, item, key))
        if code.structs:
            w.line()
        for item in code.constants:
            w.extend(library_item(printer, item, key))
        if code.constants:
            w.line()
        self._uniform_struct(ctx.pixel, 1, "pu", w)
        interpolated = len(ctx.pixel.blocks["VertexData"]) > 0
        if interpolated:
            self._vertex_data_struct(ctx.pixel, w)
            w.line("var<private> vd: VertexData;")
            w.line()
        builtins = [(wgsl_name, wgsl_type(t)) for name, (wgsl_name, t) in FRAGMENT_INPUTS.items()
                    if name in code.pixel_names]
        for name, t in builtins:
            w.line(f"var<private> {name}: {t};")
        if builtins:
            w.line()
        w.extend(helpers(items + [main]))
        for function in items:
            w.extend(library_item(printer, function, key))
            w.line()
        w.line("@fragment")
        parameters = (["vertexData: VertexData"] if interpolated else []) + \
            [f"@builtin({name}) {name}_in: {t}" for name, t in builtins]
        w.line(f"fn fragmentMain({', '.join(parameters)}) -> @location(0) vec4f {{")
        w.depth += 1
        if interpolated:
            w.line("vd = vertexData;")
        for name, _ in builtins:
            w.line(f"{name} = {name}_in;")
        w.line(f"var {outputs[0].name}: vec4f;")
        w.depth -= 1
        w.extend(printer.statements(main.body, 1))
        w.line(f"    return {outputs[0].name};")
        w.line("}")
        return w.text()

    def assemble_vertex(self, ctx) -> str:
        booleans = self._booleans(ctx.vertex)
        printer = WgslPrinter({}, lambda n: self._vertex_name(n, booleans))
        w = Writer()
        self._uniform_struct(ctx.vertex, 0, "vu", w)
        w.line("struct AppData {")
        for i, v in enumerate(ctx.vertex.blocks["AppData"]):
            w.line(f"    @location({i}) {v.name}: {_type(v.type)},")
        w.line("}")
        w.line()
        self._vertex_data_struct(ctx.vertex, w)
        w.line("@vertex")
        w.line("fn vertexMain(vin: AppData) -> VertexData {")
        w.line("    var vd: VertexData;")
        w.extend(printer.statements(ctx.pixel.code.vertex_main.body, 1))
        w.line("    return vd;")
        w.line("}")
        return w.text()

    # -- names -------------------------------------------------------------------------------------
    @staticmethod
    def _booleans(stage) -> frozenset[str]:
        return frozenset(v.name for block in ("PrivateUniforms", "PublicUniforms") for v in stage.blocks[block]
                         if v.type == "boolean")

    def _pixel_name(self, n: ir.Name, booleans) -> str:
        return self._name(n, "pu", booleans)

    def _vertex_name(self, n: ir.Name, booleans) -> str:
        if n.kind == "input":
            return f"vin.{n.name}"
        if n.kind == "builtin" and n.name == "position":
            return "vd.position"
        return self._name(n, "vu", booleans)

    @staticmethod
    def _name(n: ir.Name, buffer: str, booleans) -> str:
        if n.kind == "uniform" and n.type != "sampler2D":  # textures are bindings of their own
            read = f"{buffer}.{n.name}"
            return f"({read} != 0)" if n.name in booleans else read
        if n.kind == "vertexdata":
            return f"vd.{n.name}"
        return safe_name(n.name)

    # -- declarations ------------------------------------------------------------------------------
    def _uniform_struct(self, stage, group: int, instance: str, w: Writer) -> None:
        """The stage's uniform buffer and its textures."""
        layout = uniform_layout(stage, group)
        if layout["members"]:
            struct = f"{stage.name.capitalize()}Uniforms"
            w.line(f"struct {struct} {{")
            for m in layout["members"]:
                w.line(f"    {m['name']}: {m['wgsl']},  // offset {m['offset']}")
            w.line("}")
            w.line(f"@group({group}) @binding(0) var<uniform> {instance}: {struct};")
            w.line()
        for t in layout["textures"]:
            w.line(f"@group({group}) @binding({t['texture_binding']}) var {t['name']}: texture_2d<f32>;")
            w.line(f"@group({group}) @binding({t['sampler_binding']}) var {t['name']}_sampler: sampler;")
        if layout["textures"]:
            w.line()

    def _vertex_data_struct(self, stage, w: Writer) -> None:
        w.line("struct VertexData {")
        w.line("    @builtin(position) position: vec4f,")
        for i, v in enumerate(stage.blocks["VertexData"]):
            w.line(f"    @location({i}) {v.name}: {_type(v.type)},")
        w.line("}")
        w.line()


# GLSL's fragment built-in variables the libraries read -> (WGSL name, IR type)
FRAGMENT_INPUTS = {name: (wgsl, "bool") for name, wgsl in FRAGMENT_BUILTINS.items()}


def _type(materialx_type: str) -> str:
    return wgsl_type(ir_type(materialx_type))


def library_item(printer: WgslPrinter, item, key: tuple) -> tuple[str, ...]:
    """An item's lines: a library item's printed once per process for the same key (the shader's
    function names, which name overloads by what else the shader holds, and its boolean uniforms:
    all the printing depends on), as GLSL's are (glsl/target.py); a material requested again, or
    another of the same node graph, prints none of them again."""
    if item.where is None:  # generated for this shader
        return tuple(printer.item(item))
    return _printed(key, item)


@lru_cache(maxsize=8192)
def _printed(key: tuple, item) -> tuple[str, ...]:
    names, booleans = key
    return tuple(WgslPrinter(dict(names), lambda n: WgslTarget._name(n, "pu", booleans)).item(item))
