"""The OSL target: the printer (printer.py), the shader assembler below, and OSL's closure
convention (closures.py).

One `.osl` shader per element, in the record's pixel stage (OSL has no vertex stage: the vertex
stage is absent). It is written in this order: OSL's own headers for the vector2/vector4/matrix33
structs, the structs and constants the code passes kept, the helper functions, the library and
generated functions, then `shader shadergen(...)`: its parameters the public uniforms (the
listing's names and types, initialised as GLSL initialises its uniforms, the ui hints as OSL
metadata), the private uniforms a renderer sets (no shader global holds them), and one output
parameter per pixel output: a colour and its alpha (`<output>_alpha`) for a value, a
`closure color` for a shader. The geometric streams the GL targets interpolate are the shader
globals (`P`, `N`, `u`, `v`, `dPdu`, `dPdv`), object space through `transform("object", ...)`.
"""
from ...code import ir
from ...code.types import is_array, size_of
from ...code.values import value_expr
from ...shader import Writer
from ..names import RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
from ..printing import INDENT
from .closures import OslClosureConvention
from .printer import OslPrinter, helpers, osl_type, safe_name

SHADER_NAME = "shadergen"
HEADERS = ("vector2.h", "vector4.h", "matrix33.h")
# MaterialX type -> OSL parameter type
PARAMETER_TYPES = {"float": "float", "integer": "int", "boolean": "int", "color3": "color", "vector3": "vector",
                   "vector2": "vector2", "vector4": "vector4", "color4": "vector4", "matrix33": "matrix33",
                   "matrix44": "matrix", "filename": "string", "string": "int"}  # a string: its enum index, as in GLSL
# the vertex data members the GL targets interpolate -> the shader globals that hold them
GEOMETRY = {"positionWorld": "P", "positionObject": 'transform("object", P)', "normalWorld": "N",
            "normalObject": 'transform("object", N)', "tangentWorld": "normalize(dPdu)",
            "tangentObject": 'transform("object", normalize(dPdu))', "bitangentWorld": "normalize(dPdv)",
            "bitangentObject": 'transform("object", normalize(dPdv))'}
# private uniforms a shader global holds
GLOBALS = {"u_time": "time", "u_viewPosition": 'point("camera", 0, 0, 0)',
           "u_worldMatrix": 'matrix("object", "common")', "u_worldInverseMatrix": 'matrix("common", "object")'}
# ui hint -> OSL metadata (the names OSL's documentation and renderers read)
METADATA = (("name", "label", "string"), ("folder", "page", "string"), ("min", "min", None), ("max", "max", None),
            ("softmin", "slidermin", None), ("softmax", "slidermax", None), ("doc", "help", "string"))


# Library functions OSL writes its own way: an image is read by OSL's texture() at the library's
# image-space coordinate (t from the top row, as OSL's), which wraps and filters itself (address
# modes: constant, clamp, periodic, mirror; filters: closest, linear, cubic), where the GL library
# reads texels to wrap and filter them; a file without alpha has alpha 1 ("fill"), as GL samples it
def image_fetch(texture_width: float | None) -> tuple[str, ...]:
    """mx_image_fetch in OSL; `texture_width` the filter width of a filtered read (None: OIIO's
    default 1; a closest read is one texel of the base level, width 0, as GL's texelFetch). A closest
    read asks for the centre of GL's texel, floor(uv * size): on an exact texel edge OIIO's
    "closest" takes the texel before it, GL's (and the GL library's) the texel after."""
    width = "1.0" if texture_width is None else repr(float(texture_width))
    return (
        "vector4 mx_image_fetch(string tex, vector4 dflt, vector2 uv, int uaddr, int vaddr, int filtertype)",
        "{",
        "    if ((uaddr == 0 && (uv.x < 0.0 || uv.x > 1.0)) || (vaddr == 0 && (uv.y < 0.0 || uv.y > 1.0)))",
        "        return dflt;",
        "    vector2 st = uv;",
        "    int size[2];",
        '    if (filtertype == 0 && gettextureinfo(tex, "resolution", size))',
        "        st = vector2((floor(uv.x * size[0]) + 0.5) / size[0], (floor(uv.y * size[1]) + 0.5) / size[1]);",
        '    string wraps[4] = {"clamp", "clamp", "periodic", "mirror"};',
        '    string interp = filtertype == 0 ? "closest" : filtertype == 1 ? "linear" : "cubic";',
        f"    float width = filtertype == 0 ? 0.0 : {width};",
        "    float alpha = dflt.w;",
        '    color rgb = texture(tex, st.x, st.y, "swrap", wraps[uaddr], "twrap", wraps[vaddr], "interp", interp, '
        '"width", width,',
        '                        "alpha", alpha, "fill", 1.0, "missingcolor", color(dflt.x, dflt.y, dflt.z),',
        '                        "missingalpha", dflt.w);',
        "    return vector4(rgb[0], rgb[1], rgb[2], alpha);",
        "}")


OWN_FUNCTIONS = {"mx_image_fetch": image_fetch}


class OslTarget:
    name = "osl"
    library = "genglsl"  # the node libraries' implementations, printed from their IR
    reserved, reserved_prefixes, reserved_suffixes = RESERVED, RESERVED_PREFIXES, RESERVED_SUFFIXES
    closures = OslClosureConvention()
    # an OSL function sees its arguments alone: a shader parameter (a texture) is no global of it
    functions_see_uniforms = False
    own_functions = frozenset(OWN_FUNCTIONS)  # written as above, not printed from the library (code/stage.py)
    writes_ui = True  # a parameter's ui metadata are its hints: its stage's text depends on them (code/stage.py)

    def __init__(self):
        self.printer = OslPrinter(self.spell)

    def layout(self, ctx) -> dict | None:
        return None  # parameters are bound by name

    def spell(self, name: ir.Name) -> str:
        if name.kind == "vertexdata":
            return self.geometry(name)
        if name.kind == "builtin":
            return {"gl_FrontFacing": "!backfacing()"}.get(name.name, name.name)
        if name.kind == "uniform" and name.name in GLOBALS:
            return GLOBALS[name.name]
        return safe_name(name.name)

    @staticmethod
    def geometry(name: ir.Name) -> str:
        member = name.name
        if member in GEOMETRY:
            return GEOMETRY[member]
        if member.startswith("texcoord_"):
            return "vector(u, v, 0.0)" if name.type == "vec3" else "vector2(u, v)"
        # colours and geometric properties no global holds (a renderer's attribute lookup would go
        # here): what the GL renderer binds for a mesh without them, white colours (render/geometry.py),
        # else the type's zero
        materialx_type = {"vec4": "vector4", "vec2": "vector2", "vec3": "vector3"}.get(name.type, "float")
        white = (1.0,) * size_of(name.type) if member.startswith("color_") else None
        return OslPrinter().render(value_expr(materialx_type, white), None, 0)

    # -- assembly ----------------------------------------------------------------------------------
    def assemble_vertex(self, ctx) -> None:
        return None

    def assemble_pixel(self, ctx) -> str:
        code = ctx.pixel.code
        w = Writer()
        for header in HEADERS:
            w.line(f'#include "{header}"')
        w.line()
        arrays = {c.name: c for c in code.constants if type(c) is ir.Constant and c.type and is_array(c.type)}
        # the GL closures' structs are OSL's closures; a parameter's struct keeps every member, for
        # its default (the code passes drop those nothing reads)
        parameter_types = {v.type for block in ("PublicUniforms", "PrivateUniforms") for v in ctx.pixel.blocks[block]}
        structs = [ctx.code.symbols.items.get(s.name, s) if s.name in parameter_types else s for s in code.structs
                   if osl_type(s.name) != "closure color"]
        items = structs + [c for c in code.constants if not (type(c) is ir.Constant and c.name in arrays)]
        for item in items:
            w.extend(self.printer.item(item))
        if items:
            w.line()
        w.extend(helpers([f for f in code.functions if getattr(f, "name", None) not in OWN_FUNCTIONS] + [code.main],
                         ctx.texture_width))
        for function in code.functions:
            if type(function) is ir.Function and function.name in OWN_FUNCTIONS:
                w.extend(OWN_FUNCTIONS[function.name](ctx.texture_width))
            else:
                w.extend(self.printer.item(with_arrays(function, arrays)))
            w.line()
        self.shader(ctx, w)
        return w.text()

    def shader(self, ctx, w: Writer) -> None:
        stage = ctx.pixel
        parameters = []
        for block in ("PublicUniforms", "PrivateUniforms"):
            for v in stage.blocks[block]:
                if v.name not in GLOBALS and v.type != "LightData":
                    parameters.append(self.parameter(v))
        outputs = {}
        for v in stage.blocks["Outputs"]:
            closure = self.closures.output_closure(ctx, v.name)
            outputs[v.name] = closure
            if closure:
                parameters.append(f"output closure color {v.name} = 0")
            else:
                parameters.append(f"output color {v.name} = 0")
                parameters.append(f"output float {v.name}_alpha = 1")
        w.line(f"shader {SHADER_NAME}(")
        for i, p in enumerate(parameters):
            w.line(INDENT + p + ("," if i + 1 < len(parameters) else ""))
        w.line(")")
        main = code_main(stage.code.main, outputs)
        w.extend(self.printer.statements([main], 0))

    def parameter(self, v) -> str:
        osl = PARAMETER_TYPES.get(v.type) or osl_type(v.type)
        if v.type == "filename":
            default = ir.Literal(None, osl_string(str(v.initializer or "")), type="string")
            text = self.printer.render(default, None, 0)
        else:
            initializer = v.initializer
            if v.type == "string" and not isinstance(initializer, int):
                initializer = 0  # a string that is no enum's: none
            listing_type = "integer" if v.type == "string" else v.type
            text = self.printer.render(value_expr(listing_type, initializer), None, 0)
            if osl == "closure color":  # a closure parameter: no closure until one is connected
                text = "0"
            elif osl not in ("float", "int", "color", "vector", "matrix") and text.startswith(osl + "("):
                text = "{" + text[len(osl) + 1:-1] + "}"  # a struct parameter's default is a list
        metadata = [m for m in (self.metadata(hint, key, kind, v) for hint, key, kind in METADATA) if m]
        hints = f" [[ {', '.join(metadata)} ]]" if metadata else ""
        return f"{osl} {v.name} = {text}{hints}"

    @staticmethod
    def metadata(hint: str, key: str, kind, v) -> str | None:
        value = (v.ui or {}).get(hint)
        if value is None or isinstance(value, (tuple, list)):  # OSL metadata of vectors: not written
            return None
        if kind == "string" or isinstance(value, str):
            return f"string {key} = {osl_string(str(value).replace(chr(10), ' '))}"
        if isinstance(value, bool):
            return f"int {key} = {int(value)}"
        if isinstance(value, int) and v.type in ("integer", "string"):
            return f"int {key} = {value}"
        return f"float {key} = {float(value)!r}"


def osl_string(text: str) -> str:
    """`text` as an OSL string literal: backslashes, quotes and control characters escaped."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"')
    return '"' + "".join(c if c >= " " else f"\\{ord(c):03o}" for c in escaped) + '"'


def with_arrays(function, arrays: dict):
    """`function` declaring the constant arrays it reads as its first locals: OSL has no variables
    at file scope."""
    if type(function) is not ir.Function or not arrays:
        return function
    read = sorted({n.name for n in ir.walk(function.body) if type(n) is ir.Name and n.kind == "global"
                   and n.name in arrays})
    if not read:
        return function
    body = function.body.body if type(function.body) is ir.Block else [function.body]
    declared = [ir.Declare(arrays[n].type, n, arrays[n].value, False) for n in read]
    return ir.replace(function, body=ir.Block(declared + list(body), True))


def code_main(main: ir.Block, outputs: dict[str, bool]) -> ir.Block:
    """main's body with each write of a vec4 pixel output split into the colour and alpha
    parameters (closure outputs are written by the closure convention as they are)."""
    body = []
    for s in main.body:
        if type(s) is ir.Assign and type(s.target) is ir.Name and s.target.kind == "output" \
                and not outputs.get(s.target.name):
            name = s.target.name
            rgba = ir.Name(f"{name}_rgba", "local", type="vec4")
            body.append(ir.Declare("vec4", rgba.name, s.value, False))
            body.append(ir.Assign("=", ir.Name(name, "output", type="vec3"),
                                  ir.Field(rgba, "xyz", type="vec3", swizzle=True)))
            body.append(ir.Assign("=", ir.Name(f"{name}_alpha", "output", type="float"),
                                  ir.Field(rgba, "w", type="float", swizzle=True)))
        else:
            body.append(s)
    return ir.replace(main, body=body, scoped=True)

