"""The GLSL 4.00 and ESSL 3.00 targets: the printer (printer.py), the stage assembler below, and
the hardware closure convention (targets/closures.py).

A stage is written in this order: the version (and ESSL's precisions), the structs and constants
the code passes kept, the uniform blocks, the stage's inputs and outputs (vertex data as an
interface block `vd`, or in ESSL, which has none, as `vd_<member>` variables), the functions,
main. Uniforms are initialised to their values where GLSL allows it (not in ESSL).
"""
from functools import lru_cache

from ...code import ir
from ...code.types import ir_type
from ...code.values import value_expr
from ...shader import Writer
from ..closures import ClosureConvention
from ..names import RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
from ..printed import PrintedLibrary
from .printer import GlslPrinter

BUILTINS = {"position": "gl_Position"}


class GlslTarget:
    name = "glsl"
    library = "genglsl"  # the implementation target of the node libraries
    dialect = "glsl"
    header = ("#version 400",)
    uniform_initializers = True
    vertex_data_block = True  # interface blocks for vertex -> pixel data
    # one spelling of every name in every target (names.py): a client binds the same names in each
    reserved, reserved_prefixes, reserved_suffixes = RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
    closures = ClosureConvention()
    printer_class = GlslPrinter

    def __init__(self):
        self.printer = self.printer_class(self.dialect, self.spell)

    def spell(self, name: ir.Name) -> str:
        if name.kind == "vertexdata":
            return f"vd.{name.name}" if self.vertex_data_block else f"vd_{name.name}"
        if name.kind == "builtin":
            return BUILTINS.get(name.name, name.name)  # the library reads GLSL's own (gl_FrontFacing)
        return name.name

    def printed_library(self, ctx) -> PrintedLibrary:
        """The library's items as this target prints them (targets/printed.py), read once per library."""
        return ctx.scope.library.fact(("printed", self.name),
                                      lambda: PrintedLibrary(ctx.code, self.name, self.printer.item))

    def item(self, item, library: PrintedLibrary) -> tuple[str, ...]:
        """An item's lines: a library item's as printed once per library (`library`), a copy a
        pass made once per process (the code passes hand back the same rewritten item for the
        same edit)."""
        if item.where is None:  # generated for this shader
            return tuple(self.printer.item(item))
        lines = library.lines(item)
        return lines if lines is not None else printed(type(self), item)

    def layout(self, ctx) -> dict | None:
        """Where a client puts each uniform: GLSL uniforms are bound by name."""
        return None

    # -- stage assembly --------------------------------------------------------------------------
    def assemble_pixel(self, ctx) -> str:
        code = ctx.pixel.code
        library = self.printed_library(ctx)
        w = self._start()
        items = code.structs + code.constants
        for item in items:
            w.extend(self.item(item, library))
        if items:
            w.line()
        self._uniforms(ctx.pixel, w)
        self._vertex_data(ctx.pixel, w, "in")
        for location, v in enumerate(ctx.pixel.blocks["Outputs"]):
            w.line(f"{self.io('out', location)} vec4 {v.name};")
        w.line()
        # the statements of main and of the functions it calls that were typed once per shape
        # (code/statements.py) are printed once per target (this class) and depth
        self.printer.shared = (code.shared.hits, type(self)) if code.shared is not None else None
        try:
            for function in code.functions:
                w.extend(self.item(function, library))
                w.line()
            self._main(code.main, w)
        finally:
            self.printer.shared = None
        return w.text()

    def assemble_vertex(self, ctx) -> str:
        w = self._start()
        self._uniforms(ctx.vertex, w)
        for location, v in enumerate(ctx.vertex.blocks["AppData"]):
            w.line(f"{self.io('in', location)} {listed_type(v)} {v.name};")
        w.line()
        self._vertex_data(ctx.vertex, w, "out")
        self._main(ctx.pixel.code.vertex_main, w)
        return w.text()

    def _start(self) -> Writer:
        w = Writer()
        for line in self.header:
            w.line(line)
        w.line()
        return w

    @staticmethod
    def io(direction: str, location: int) -> str:
        """A stage input's or output's qualifiers: GLSL matches them by name."""
        return direction

    def _main(self, body: ir.Block, w: Writer) -> None:
        w.line("void main()")
        w.extend(self.printer.statements([body], 0))

    def _uniforms(self, stage, w: Writer) -> None:
        for block in ("PrivateUniforms", "PublicUniforms"):
            variables = list(stage.blocks[block])
            if variables:
                w.line(f"// Uniform block: {block}")
                for v in variables:
                    initialised = self.uniform_initializers and v.type not in ("filename", "LightData")
                    w.line(uniform_declaration(type(self), listed_type(v), v.name, v.type,
                                               v.initializer if initialised else None))
                w.line()

    def _vertex_data(self, stage, w: Writer, direction: str) -> None:
        members = list(stage.blocks["VertexData"])
        if not members:
            return
        if self.vertex_data_block:
            w.line(f"{self.io(direction, 0)} VertexData")
            w.line("{")
            for v in members:
                w.line(f"    {listed_type(v)} {v.name};")
            w.line("} vd;")
        else:
            for location, v in enumerate(members):
                w.line(f"{self.io(direction, location)} {listed_type(v)} vd_{v.name};")
        w.line()


@lru_cache(maxsize=8192)
def printed(target_class, item) -> tuple[str, ...]:
    return tuple(target_class().printer.item(item))


def uniform_declaration(target_class, listed: str, name: str, materialx_type: str, value) -> str:
    """A uniform's declaration, initialised to `value` where it has one. Materials share most of
    their uniforms (a node's inputs at their defaults), so each is printed once per process; equal
    values print alike (value_expr writes a value as its type's numbers: 1, 1.0 and True are one
    float's 1.0)."""
    try:
        return _shared_declaration(target_class, listed, name, materialx_type, value)
    except TypeError:  # a value no cache can key (a list): printed each time
        return _declaration(target_class, listed, name, materialx_type, value)


def _declaration(target_class, listed: str, name: str, materialx_type: str, value) -> str:
    init = None if value is None else value_expr(materialx_type, value, {"enum": ""})  # listed enums are indices
    return target_class().printer.global_declaration(ir.Global(listed, name, "uniform", None, init))


_shared_declaration = lru_cache(maxsize=16384)(_declaration)


def listed_type(v) -> str:
    """A listed variable's IR type, which GLSL spells as it is (the light array's length is the
    prelude's MAX_LIGHT_SOURCES)."""
    return "LightData[MAX_LIGHT_SOURCES]" if v.type == "LightData" else ir_type(v.type)


class EsslTarget(GlslTarget):
    name = "essl"
    dialect = "essl"
    header = ("#version 300 es", "precision highp float;", "precision highp int;")
    uniform_initializers = False  # ESSL has no uniform initialisers: values come from the listing
    vertex_data_block = False  # ESSL 3.00 has no in/out interface blocks
