"""The MSL target: the C-family printer with MSL's syntax (printer.py), and the stage assembler
below.

MSL has no variables at program scope but constants, so what GLSL's library code reads as
globals (uniforms, textures, vertex data, gl_FrontFacing) are members of one struct per stage,
`PixelStage`, whose member functions are the library's and the generated functions and whose
`shade()` is main (MaterialX's own MSL wraps its code alike). The entry points (`vertex
vertexMain`, `fragment fragmentMain`) take the stage's arguments, make the struct and call it.
Each stage's uniforms are one buffer (`constant VertexUniforms& vu [[buffer(0)]]`, `constant
PixelUniforms& pu [[buffer(0)]]`) laid out as the WGSL target's uniform buffer (wgsl/layout.py:
a vec3 packed, explicit padding), so one client buffer serves both; the record's `layout` gives
the offsets. A boolean travels as an int, read `(pu.name != 0)`. Textures are `texture2d<float>`
`[[texture(i)]]` with a `sampler` `[[sampler(i)]]` each; vertex data is `VertexData`
(`[[position]]`, `[[user(locn<i>)]]`), app data `AppData` (`[[attribute(i)]]`).
"""
from ...code import ir
from ...code.types import ir_type
from ...errors import ShaderGenError
from ...shader import PIXEL, VERTEX, Writer
from ..cfamily.printer import FRAGMENT_BUILTINS, CFamilyPrinter, helpers, type_name
from ..cfamily.target import CFamilyTarget, safe_name
from ..wgsl.layout import uniform_layout
from .printer import SYNTAX

# the WGSL buffer types of wgsl/layout.py as MSL spells them (a vec3 packed: 12 bytes, as WGSL's)
BUFFER_TYPES = {"f32": "float", "i32": "int", "vec2f": "float2", "vec3f": "packed_float3", "vec4f": "float4",
                "mat3x3f": "float3x3", "mat4x4f": "float4x4"}
HEADER = ("#include <metal_stdlib>", "using namespace metal;", "")


class MslTarget(CFamilyTarget):
    name = "msl"
    syntax = SYNTAX

    def layout(self, ctx) -> dict:
        """Byte offsets of every uniform in its stage's buffer (WGSL's), and the texture slots."""
        return {stage: uniform_layout(ctx.stages[stage], 0) for stage in (VERTEX, PIXEL)}

    # -- names -------------------------------------------------------------------------------------
    def printer(self, key: tuple = ()) -> CFamilyPrinter:
        """key: (the stage's buffer, its boolean uniforms), what reading a uniform depends on."""
        if not key:
            return super().printer()
        buffer, booleans = key

        def spell(n: ir.Name) -> str:
            if n.kind == "uniform" and n.type != "sampler2D":
                read = f"{buffer}.{n.name}"
                return f"({read} != 0)" if n.name in booleans else read
            return self.spell(n)
        return CFamilyPrinter(self.syntax, spell, safe_name)

    @staticmethod
    def key(stage, buffer: str) -> tuple:
        return buffer, frozenset(v.name for block in ("PrivateUniforms", "PublicUniforms")
                                 for v in stage.blocks[block] if v.type == "boolean")

    # -- stage assembly ----------------------------------------------------------------------------
    def assemble_pixel(self, ctx) -> str:
        code = ctx.pixel.code
        outputs = list(ctx.pixel.blocks["Outputs"])
        if len(outputs) != 1:
            raise ShaderGenError("unsupported_output", "msl shaders have exactly one output", "msl")
        key = self.key(ctx.pixel, "pu")
        printer = self.printer(key)
        w = Writer()
        for line in HEADER:
            w.line(line)
        for items in (code.structs, code.constants):
            for item in items:
                w.extend(self.item(printer, item, key))
            if items:
                w.line()
        layout = uniform_layout(ctx.pixel, 0)
        self._buffer_struct("PixelUniforms", layout, w)
        self._vertex_data_struct(ctx.pixel, w)
        builtins = [name for name in FRAGMENT_BUILTINS if name in code.pixel_names]
        w.line("struct PixelStage")
        w.line("{")
        w.depth += 1
        members = (["constant PixelUniforms& pu;"] if layout["members"] else []) + \
            [f"{kind} {t['name']}{suffix};" for t in layout["textures"]
             for kind, suffix in ((self.syntax.texture, ""), (self.syntax.sampler, "_sampler"))] + \
            ["VertexData vd;"] + [f"bool {FRAGMENT_BUILTINS[name]};" for name in builtins]
        for member in members:
            w.line(member)
        w.line()
        w.extend(helpers(code.functions + [code.main], self.syntax, code.structs, safe_name))
        for function in code.functions:
            w.extend(self.item(printer, function, key))
            w.line()
        w.line("float4 shade()")
        w.line("{")
        w.line(f"    float4 {outputs[0].name};")
        w.depth -= 1
        w.extend(printer.statements(code.main.body, 2))
        w.line(f"        return {outputs[0].name};")
        w.line("    }")
        w.line("};")
        w.line()
        parameters = ["VertexData vertexData [[stage_in]]"] + \
            (["constant PixelUniforms& pu [[buffer(0)]]"] if layout["members"] else []) + \
            [f"{self.syntax.texture} {t['name']} [[texture({i})]], {self.syntax.sampler} {t['name']}_sampler "
             f"[[sampler({i})]]" for i, t in enumerate(layout["textures"])] + \
            [f"bool {FRAGMENT_BUILTINS[name]} [[front_facing]]" for name in builtins]
        w.line("fragment float4 fragmentMain(" + ",\n                             ".join(parameters) + ")")
        w.line("{")
        arguments = (["pu"] if layout["members"] else []) + \
            [n for t in layout["textures"] for n in (t["name"], t["name"] + "_sampler")] + \
            ["vertexData"] + [FRAGMENT_BUILTINS[name] for name in builtins]
        w.line(f"    PixelStage stage{{{', '.join(arguments)}}};")
        w.line("    return stage.shade();")
        w.line("}")
        return w.text()

    def assemble_vertex(self, ctx) -> str:
        printer = self.printer(self.key(ctx.vertex, "vu"))
        w = Writer()
        for line in HEADER:
            w.line(line)
        layout = uniform_layout(ctx.vertex, 0)
        self._buffer_struct("VertexUniforms", layout, w)
        w.line("struct AppData")
        w.line("{")
        for i, v in enumerate(ctx.vertex.blocks["AppData"]):
            w.line(f"    {self._type(v.type)} {v.name} [[attribute({i})]];")
        w.line("};")
        w.line()
        self._vertex_data_struct(ctx.vertex, w)
        uniforms = ", constant VertexUniforms& vu [[buffer(0)]]" if layout["members"] else ""
        w.line(f"vertex VertexData vertexMain(AppData vin [[stage_in]]{uniforms})")
        w.line("{")
        w.line("    VertexData vd;")
        w.extend(printer.statements(ctx.pixel.code.vertex_main.body, 1))
        w.line("    return vd;")
        w.line("}")
        return w.text()

    # -- declarations ------------------------------------------------------------------------------
    @staticmethod
    def _buffer_struct(name: str, layout: dict, w: Writer) -> None:
        """The uniform buffer's struct, each member at WGSL's offset (padding written out)."""
        if not layout["members"]:
            return
        w.line(f"struct {name}")
        w.line("{")
        end = 0
        for m in layout["members"]:
            if m["offset"] > end:
                w.line(f"    char pad_{end}[{m['offset'] - end}];")
            if m["type"] == "LightData":
                w.line(f"    LightData {m['name']}[MAX_LIGHT_SOURCES];")
            else:
                w.line(f"    {BUFFER_TYPES.get(m['wgsl'], m['wgsl'])} {m['name']};  // offset {m['offset']}")
            end = m["offset"] + m["size"]
        if layout["size"] > end:
            w.line(f"    char pad_{end}[{layout['size'] - end}];")
        w.line("};")
        w.line()

    def _vertex_data_struct(self, stage, w: Writer) -> None:
        w.line("struct VertexData")
        w.line("{")
        w.line("    float4 position [[position]];")
        for i, v in enumerate(stage.blocks["VertexData"]):
            w.line(f"    {self._type(v.type)} {v.name} [[user(locn{i})]];")
        w.line("};")
        w.line()

    def _type(self, materialx_type: str) -> str:
        return type_name(ir_type(materialx_type), self.syntax)
