"""The stage assembler HLSL and Slang share (MSL's is targets/msl/target.py, on the same printer):
one module per stage, entry points marked `[shader("vertex")]` `vertexMain` and `[shader("pixel")]`
`fragmentMain`, which DXC and Slang both read.

Each stage's uniforms are one constant buffer (`VertexUniforms`, `PixelUniforms`), its members
read by their names as GLSL's uniforms are; matrices in it `row_major`, so the column-major
matrices a client uploads for GLSL arrive as the transposes the printer works with (syntax.py);
each texture a `Texture2D` and a `SamplerState` `<name>_sampler`. Vertex data is one struct,
`VertexData` (its position `SV_Position`, the rest `TEXCOORD<i>`), returned by the vertex stage
and kept in a static `vd` in the pixel stage, so library functions read it as GLSL's `vd.` block;
app data is `AppData` (`ATTRIBUTE<i>`). The fragment built-ins the code reads (gl_FrontFacing)
come in as the entry point's parameters, copied into statics.
"""
from functools import lru_cache

from ...code import ir
from ...code.types import ir_type
from ...errors import ShaderGenError
from ...shader import Writer
from ..closures import ClosureConvention
from ..names import RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
from .printer import FRAGMENT_BUILTINS, CFamilyPrinter, helpers, type_name
from .reserved import RESERVED_WORDS
from .syntax import Syntax

UNIFORM_BLOCKS = ("PrivateUniforms", "PublicUniforms")


def safe_name(name: str) -> str:
    """A library name the language reserves, respelled (the Namer keeps the document's off them)."""
    if name in FRAGMENT_BUILTINS:
        return FRAGMENT_BUILTINS[name]
    return f"{name}_" if name in RESERVED_WORDS else name


class CFamilyTarget:
    name: str
    syntax: Syntax
    library = "genglsl"  # the node libraries' implementations, printed from their IR
    reserved, reserved_prefixes, reserved_suffixes = RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
    closures = ClosureConvention()

    def layout(self, ctx) -> dict | None:
        """Uniforms are bound by name (the constant buffers' reflection)."""
        return None

    # -- names -------------------------------------------------------------------------------------
    def spell(self, n: ir.Name) -> str:
        if n.kind == "vertexdata":
            return f"vd.{safe_name(n.name)}"
        if n.kind == "input":
            return f"vin.{n.name}"
        if n.kind == "builtin" and n.name == "position":
            return "vd.position"
        return safe_name(n.name)

    def printer(self, key: tuple = ()) -> CFamilyPrinter:
        """The printer; `key` is what else its spelling depends on (MSL's boolean uniforms)."""
        return CFamilyPrinter(self.syntax, self.spell, safe_name)

    def item(self, printer: CFamilyPrinter, item, key: tuple = ()) -> tuple[str, ...]:
        """An item's lines: a library item's printed once per process for the same target and key,
        as GLSL's are (glsl/target.py; they recur in every request, and the code passes hand back
        the same rewritten item for the same edit): printing them again was most of the time an
        HLSL, Slang or MSL record took beyond GLSL's."""
        if item.where is None:  # generated for this shader
            return tuple(printer.item(item))
        return printed(type(self), key, item)

    # -- stage assembly ----------------------------------------------------------------------------
    def assemble_pixel(self, ctx) -> str:
        code = ctx.pixel.code
        outputs = list(ctx.pixel.blocks["Outputs"])
        if len(outputs) != 1:
            raise ShaderGenError("unsupported_output", f"{self.name} shaders have exactly one output", self.name)
        printer = self.printer()
        w = Writer()
        for items in (code.structs, code.constants):
            for item in items:
                w.extend(self.item(printer, item))
            if items:
                w.line()
        self._uniforms(ctx.pixel, "PixelUniforms", w)
        self._vertex_data_struct(ctx.pixel, w)
        w.line("static VertexData vd;")
        builtins = [name for name in FRAGMENT_BUILTINS if name in code.pixel_names]
        for name in builtins:
            w.line(f"static bool {FRAGMENT_BUILTINS[name]};")
        w.line()
        w.extend(helpers(code.functions + [code.main], self.syntax, code.structs, safe_name))
        for function in code.functions:
            w.extend(self.item(printer, function))
            w.line()
        w.line('[shader("pixel")]')
        parameters = ["VertexData vertexData"] + [f"bool {FRAGMENT_BUILTINS[name]}_in : SV_IsFrontFace"
                                                  for name in builtins]
        w.line(f"float4 fragmentMain({', '.join(parameters)}) : SV_Target")
        w.line("{")
        w.depth += 1
        w.line("vd = vertexData;")
        for name in builtins:
            w.line(f"{FRAGMENT_BUILTINS[name]} = {FRAGMENT_BUILTINS[name]}_in;")
        w.line(f"float4 {outputs[0].name};")
        w.depth -= 1
        w.extend(printer.statements(code.main.body, 1))
        w.line(f"    return {outputs[0].name};")
        w.line("}")
        return w.text()

    def assemble_vertex(self, ctx) -> str:
        printer = self.printer()
        w = Writer()
        self._uniforms(ctx.vertex, "VertexUniforms", w)
        w.line("struct AppData")
        w.line("{")
        for i, v in enumerate(ctx.vertex.blocks["AppData"]):
            w.line(f"    {self._type(v.type)} {v.name} : ATTRIBUTE{i};")
        w.line("};")
        w.line()
        self._vertex_data_struct(ctx.vertex, w)
        w.line('[shader("vertex")]')
        w.line("VertexData vertexMain(AppData vin)")
        w.line("{")
        w.line("    VertexData vd;")
        w.extend(printer.statements(ctx.pixel.code.vertex_main.body, 1))
        w.line("    return vd;")
        w.line("}")
        return w.text()

    # -- declarations ------------------------------------------------------------------------------
    def _type(self, materialx_type: str) -> str:
        return type_name(ir_type(materialx_type), self.syntax)

    def _uniforms(self, stage, buffer: str, w: Writer) -> None:
        """The stage's constant buffer, then its textures."""
        members, textures = [], []
        for block in UNIFORM_BLOCKS:
            for v in stage.blocks[block]:
                if v.type == "filename":
                    textures.append(v.name)
                elif v.type == "LightData":
                    members.append(f"LightData {v.name}[MAX_LIGHT_SOURCES];")
                elif v.type in ("matrix33", "matrix44"):
                    members.append(f"row_major {self._type(v.type)} {v.name};")
                else:
                    members.append(f"{self._type(v.type)} {v.name};")
        if members:
            w.line(f"cbuffer {buffer}")
            w.line("{")
            for member in members:
                w.line("    " + member)
            w.line("};")
            w.line()
        for name in textures:
            w.line(f"{self.syntax.texture} {name};")
            w.line(f"{self.syntax.sampler} {name}_sampler;")
        if textures:
            w.line()

    def _vertex_data_struct(self, stage, w: Writer) -> None:
        w.line("struct VertexData")
        w.line("{")
        w.line("    float4 position : SV_Position;")
        for i, v in enumerate(stage.blocks["VertexData"]):
            w.line(f"    {self._type(v.type)} {v.name} : TEXCOORD{i};")
        w.line("};")
        w.line()


@lru_cache(maxsize=8192)
def printed(target_class, key: tuple, item) -> tuple[str, ...]:
    return tuple(target_class().printer(key).item(item))
