"""The IR printers (targets/glsl/printer.py, targets/wgsl/printer.py): every library source file
printed compiles with the real compilers (glslangValidator for GLSL 4.00 and ESSL 3.00; for WGSL
naga inside wgpu, the validator the WGSL tests use), in a translation unit of its own with the
files it includes; parentheses come out where
precedence needs them and the printed text parses back to the same IR; printing is deterministic."""
import glob
import os
import subprocess

import pytest

from required_tools import require_wgpu, tool_path
from shadergen.code import ir
from shadergen.code.check import check_modules
from shadergen.code.externals import EXTERNALS
from shadergen.code.library import PRELUDE, PRELUDE_PATH
from shadergen.code.parse import parse_expression, parse_module
from shadergen.code.types import ir_type
from shadergen.errors import ShaderGenError
from shadergen.library import Library, Scope
from shadergen.targets.glsl.printer import GlslPrinter, same
from shadergen.targets.wgsl.printer import DEFINED, WgslPrinter, function_names, helpers, wgsl_type

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LIBRARIES = os.path.join(ROOT, "libraries")
SOURCES = sorted(os.path.relpath(p, LIBRARIES)
                 for p in glob.glob(os.path.join(LIBRARIES, "*/genglsl/**/*.glsl"), recursive=True))
# The globals the libraries read and do not define (the generator declares them).
HEADERS = {"glsl": "#version 400", "essl": "#version 300 es\nprecision highp float;\nprecision highp int;"}


def read(path: str) -> str:
    with open(path) as f:
        return f.read()


def parsed() -> dict[str, ir.Module]:
    """Every library file and the prelude, parsed only."""
    modules = {PRELUDE: parse_module(PRELUDE, read(PRELUDE_PATH))}
    for path in SOURCES:
        modules[path] = parse_module(path, read(os.path.join(LIBRARIES, path)))
    return modules


@pytest.fixture(scope="module")
def library() -> Library:
    return Library.load()


@pytest.fixture(scope="module")
def modules(code) -> dict[str, ir.Module]:
    assert sorted(code.modules) == sorted([PRELUDE, *SOURCES])
    return code.modules


def in_include_order(path: str, modules: dict, seen: set) -> list[str]:
    """`path` after the files it includes (each once), as the preprocessor would read them."""
    if path in seen:
        return []
    seen.add(path)
    order = []
    for included in modules[path].includes:
        order += in_include_order(included, modules, seen)
    return order + [path]


def feature_macros(modules: dict) -> list[str]:
    """Every feature macro a section of the libraries tests."""
    found = set()
    for module in modules.values():
        for item in module.items:
            found.update(n.macro for n in ir.walk(item) if type(n) is ir.Section and n.macro.startswith("MX_"))
    return sorted(found)


def printed(printer, items) -> list[str]:
    return [line for item in items for line in [*printer.item(item), ""]]


def glsl_unit(path: str, modules: dict, printer: GlslPrinter, defined: list[str]) -> str:
    """One library file as a fragment shader: the prelude, the externals, the files it includes."""
    lines = [HEADERS[printer.dialect], *[f"#define {m}" for m in defined], *printed(printer, modules[PRELUDE].items)]
    for name, t in EXTERNALS.items():
        lines.append(f"uniform {printer.declarator(t, name)};")
    for source in in_include_order(path, modules, set()):
        lines += printed(printer, modules[source].items)
    lines.append("out vec4 fragment_colour;\nvoid main() { fragment_colour = vec4(0.0); }")
    return "\n".join(lines) + "\n"


def externals_wgsl() -> list[str]:
    """The externals as WGSL: textures bound with their samplers, the rest private variables,
    and the facing flag the entry point copies."""
    lines, binding = [], 0
    for name, t in EXTERNALS.items():
        if t == "sampler2D":
            lines.append(f"@group(0) @binding({binding}) var {name}: texture_2d<f32>;")
            lines.append(f"@group(0) @binding({binding + 1}) var {name}_sampler: sampler;")
            binding += 2
        else:
            lines.append(f"var<private> {name}: {wgsl_type(t.replace('MAX_LIGHT_SOURCES', '3'))};")
    return [*lines, "var<private> front_facing: bool;"]


def wgsl_unit(path: str, modules: dict, printer: WgslPrinter) -> str:
    """One library file as a WGSL module: the prelude, the externals (textures bound, the rest
    private variables), the facing flag, the helpers its code calls, the files it includes."""
    sources = [PRELUDE, *in_include_order(path, modules, set())]
    lines = externals_wgsl()
    lines += helpers([item for source in sources for item in modules[source].items])
    for source in sources:
        lines += printed(printer, modules[source].items)
    lines.append("@fragment fn main() -> @location(0) vec4f { return vec4f(0.0); }")
    return "\n".join(lines) + "\n"


def rejected(units: dict[str, str], tmp_path, together: bool) -> list[str]:
    """The units glslangValidator rejects, with its log (`together`: 50 files a run, the one
    rejected found again alone)."""
    tool = tool_path("glslangValidator")
    paths = []
    for i, (name, text) in enumerate(sorted(units.items())):
        path = tmp_path / f"u{i}.frag"
        path.write_text(text)
        paths.append((name, path))
    failures = []
    for start in range(0, len(paths), 50 if together else 1):  # bounded command lines
        chunk = paths[start:start + (50 if together else 1)]
        run = subprocess.run([tool, *[str(p) for _, p in chunk]], capture_output=True, text=True, timeout=300)
        if run.returncode == 0:
            continue
        for name, p in chunk:
            one = run if len(chunk) == 1 else subprocess.run([tool, str(p)], capture_output=True, text=True, timeout=60)
            if one.returncode != 0:
                failures.append(f"{name}: {(one.stdout + one.stderr)[-800:]}")
    return failures


@pytest.mark.parametrize("dialect", ["glsl", "essl"])
def test_every_library_file_printed_compiles(modules, dialect, tmp_path):
    printer = GlslPrinter(dialect)
    every = feature_macros(modules)
    assert len(every) >= 10
    units = {}
    for path in SOURCES:
        units[f"{path} (no features)"] = glsl_unit(path, modules, printer, [])
        units[f"{path} (every feature)"] = glsl_unit(path, modules, printer, every)
    assert len(units) == 2 * len(SOURCES) >= 200
    failures = rejected(units, tmp_path, together=True)
    assert not failures, f"{len(failures)} of {len(units)} rejected:\n" + "\n".join(failures[:5])


@pytest.fixture(scope="module")
def wgsl_validator():
    """name -> source => name -> message of every WGSL module rejected (naga in wgpu-native)."""
    return require_wgpu()


def test_every_library_file_printed_as_wgsl_validates(modules, wgsl_validator):
    functions = [n for m in modules.values() for item in m.items for n in ir.walk(item) if type(n) is ir.Function]
    names = function_names(functions)
    every = feature_macros(modules)
    units = {}
    for defined, label in ((DEFINED, "no features"), (DEFINED | set(every), "every feature")):
        printer = WgslPrinter(names, defined=defined)
        for path in SOURCES:
            units[f"{path} ({label})"] = wgsl_unit(path, modules, printer)
    failures = wgsl_validator(units)
    assert len(units) == 2 * len(SOURCES)
    assert not failures, f"{len(failures)} of {len(units)} rejected:\n" + "\n".join(
        f"{name}: {message[:800]}" for name, message in sorted(failures.items())[:5])


def test_overloads_are_spelled_apart_whatever_the_order(modules):
    functions = [n for m in modules.values() for item in m.items for n in ir.walk(item) if type(n) is ir.Function]
    names = function_names(functions)
    assert names == function_names(list(reversed(functions)))
    assert len(set(names.values())) == len(names)  # one WGSL name per overload
    overloads = sorted(key for key in names if key.startswith("mx_sqr("))
    assert len(overloads) >= 2 and all(names[key].startswith("mx_sqr_") for key in overloads)
    assert names["mx_mix_bsdf(ClosureData,BSDF,BSDF,float,BSDF)"] == "mx_mix_bsdf"  # one of its name: kept


def instantiated(expr, placeholders: set):
    """`expr` with each `{{input}}` a parameter `in_input` of its type (as a node's function)."""
    if type(expr) is ir.Placeholder:
        placeholders.add(expr.name)
        return ir.Name(f"in_{expr.name}", "param", type=expr.type)
    changes = {}
    for field in expr.FIELDS:
        value = getattr(expr, field)
        if isinstance(value, ir.Node):
            changes[field] = instantiated(value, placeholders)
        elif isinstance(value, list):
            changes[field] = [instantiated(v, placeholders) if isinstance(v, ir.Node) else v for v in value]
    return ir.replace(expr, **changes)


def inline_functions(code, library) -> list[ir.Function]:
    """Every inline implementation's expression, typed for its nodedef's inputs, as a function."""
    scope = Scope(library, None)
    out = []
    for name in sorted(library.implementations):
        for impl in library.implementations[name]:
            text = impl.get("sourcecode")
            if text is None:
                continue
            nodedef = library.nodedefs[impl.get("nodedef")]
            types = {i.name: ir_type(i.get("type")) for i in scope.nodedef_inputs(nodedef)}
            used: set = set()
            expr = instantiated(code.expression(text, types), used)
            if expr.type == "sampler2D":  # a texture passed on (`{{value}}` of a filename): no value to return
                continue
            params = [ir.Param("in", types[n], f"in_{n}", False) for n in sorted(used)]
            out.append(ir.Function(expr.type, f"inline_{len(out)}", params, ir.Block([ir.Return(expr)], True)))
    return out


def test_every_inline_expression_printed_compiles(code, library, modules, wgsl_validator, tmp_path):
    """The 516 inline expressions, each the body of a function, after the whole library: one
    fragment shader per GLSL dialect, one WGSL module."""
    inline = inline_functions(code, library)
    assert len(inline) >= 500
    order = [PRELUDE, *[p for path in SOURCES for p in in_include_order(path, modules, set()) if p != PRELUDE]]
    order = list(dict.fromkeys(order))
    items = [item for path in order for item in modules[path].items]
    units = {}
    for dialect in ("glsl", "essl"):
        printer = GlslPrinter(dialect)
        uniforms = [f"uniform {printer.declarator(t, n)};" for n, t in EXTERNALS.items() if n != "u_lightData"]
        lines = [HEADERS[dialect], *uniforms]
        lines += printed(printer, items[:len(modules[PRELUDE].items)])
        lines.append(f"uniform {printer.declarator(EXTERNALS['u_lightData'], 'u_lightData')};")
        lines += printed(printer, items[len(modules[PRELUDE].items):] + inline)
        lines.append("out vec4 fragment_colour;\nvoid main() { fragment_colour = vec4(0.0); }")
        units[dialect] = "\n".join(lines) + "\n"
    failures = rejected(units, tmp_path, together=False)
    functions = [n for item in items for n in ir.walk(item) if type(n) is ir.Function] + inline
    printer = WgslPrinter(function_names(functions))
    wgsl = [*externals_wgsl(), *helpers(items + inline), *printed(printer, items + inline)]
    wgsl.append("@fragment fn main() -> @location(0) vec4f { return vec4f(0.0); }")
    failures += [f"wgsl: {message}" for message in wgsl_validator({"wgsl": "\n".join(wgsl) + "\n"}).values()]
    assert not failures, "\n".join(failures)


RULES = """
vec4 mx_rules(vec3 v, float x, int i, sampler2D tex, vec2 uv, mat3 m, bool c, out float r)
{
    vec3 a = mod(v, 2.0);
    float b = atan(x, 1.0) + inversesqrt(x) + dFdx(x) + dFdy(x);
    vec3 d = clamp(v, 0.0, 1.0) * float(i) + vec3(i);
    bvec3 below = lessThan(v, vec3(0.5));
    bool nan = isnan(x) || v == a;
    mat3 n = c ? m : inverse(m);
    mat3 s = mat3(2.0);
    float w[3] = float[3](1.0, 2.0, 3.0);
    a.xy = uv * 2.0;
    x += 1;
    i++;
    r = x;
    if (c)
        return textureLod(tex, uv, 0);
    return texture(tex, uv) + vec4(mix(a, d, below), w[i]);
}
"""


def test_wgsl_rules_on_checked_code(wgsl_validator):
    """GLSL's built-ins, conversions, spreads, choices and writes as WGSL has them; the validator
    takes it."""
    modules = {PRELUDE: parse_module(PRELUDE, read(PRELUDE_PATH)), "t.glsl": parse_module("t.glsl", RULES)}
    check_modules(modules, {}, (PRELUDE,))
    items = modules["t.glsl"].items
    (function,) = [item for item in items if type(item) is ir.Function]
    printed_lines = WgslPrinter(function_names([function])).item(function)
    assert printed_lines == [
        'fn mx_rules(v: vec3f, x__in: f32, i__in: i32, tex: texture_2d<f32>, tex_sampler: sampler, uv: vec2f,',
        '            m: mat3x3f, c: bool, r: ptr<function, f32>) -> vec4f {',
        '    var x: f32 = x__in;',
        '    var i: i32 = i__in;',
        '    var a: vec3f = v - vec3f(2.0) * floor(v / vec3f(2.0));',
        '    let b: f32 = atan2(x, 1.0) + inverseSqrt(x) + dpdx(x) + -dpdy(x);',
        '    let d: vec3f = clamp(v, vec3f(0.0), vec3f(1.0)) * f32(i) + vec3f(f32(i));',
        '    let below: vec3<bool> = v < vec3f(0.5);',
        '    let nan: bool = (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u || all(v == a);',
        '    let n: mat3x3f = mx_select_mat3x3f(mx_inverse_mat3(m), m, c);',
        '    let s: mat3x3f = mat3x3f(2.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 2.0);',
        '    var w: array<f32, 3> = array<f32, 3>(1.0, 2.0, 3.0);',
        '    let swizzled_0 = uv * 2.0;',
        '    a.x = swizzled_0.x;',
        '    a.y = swizzled_0.y;',
        '    x += 1.0;',
        '    i++;',
        '    *r = x;',
        '    if (c) { return textureSampleLevel(tex, tex_sampler, uv, 0.0); }',
        '    return textureSample(tex, tex_sampler, uv) + vec4f(select(a, d, below), w[i]);',
        '}',
    ]
    module = [*printed(WgslPrinter(), modules[PRELUDE].items), *helpers(items), *printed_lines]
    assert not wgsl_validator({"rules": "\n".join(module) + "\n"})


MORE_BUILTINS = """
float mx_more(float x, uint u, int i, vec3 v, mat3 m, mat3 n, sampler2D tex)
{
    int a = floatBitsToInt(x) + findMSB(i) + findLSB(i) + bitCount(i) + textureQueryLevels(tex);
    uvec3 b = floatBitsToUint(v);
    float c = uintBitsToFloat(u) + intBitsToFloat(i) + roundEven(x) + acosh(x) + trunc(x) + fma(x, x, x);
    mat3 d = matrixCompMult(m, n);
    return c + float(a) + d[0].x + float(b.x);
}
"""


def test_wgsl_forms_of_the_other_builtins(wgsl_validator):
    """Bit casts and bit counts, roundEven, matrixCompMult column by column, textureQueryLevels."""
    modules = {PRELUDE: parse_module(PRELUDE, read(PRELUDE_PATH)), "t.glsl": parse_module("t.glsl", MORE_BUILTINS)}
    check_modules(modules, {}, (PRELUDE,))
    (function,) = [item for item in modules["t.glsl"].items if type(item) is ir.Function]
    printed_lines = WgslPrinter().item(function)
    assert printed_lines == [
        'fn mx_more(x: f32, u: u32, i: i32, v: vec3f, m: mat3x3f, n: mat3x3f, tex: texture_2d<f32>,',
        '           tex_sampler: sampler) -> f32 {',
        '    let a: i32 = bitcast<i32>(x) + firstLeadingBit(i) + firstTrailingBit(i) + countOneBits(i) +',
        '                 i32(textureNumLevels(tex));',
        '    let b: vec3u = bitcast<vec3u>(v);',
        '    let c: f32 = bitcast<f32>(u) + bitcast<f32>(i) + round(x) + acosh(x) + trunc(x) + fma(x, x, x);',
        '    let d: mat3x3f = mat3x3f(m[0] * n[0], m[1] * n[1], m[2] * n[2]);',
        '    return c + f32(a) + d[0].x + f32(b.x);',
        '}',
    ]
    assert not wgsl_validator({"more": "\n".join(printed_lines) + "\n"})


def test_wgsl_shifts_by_an_unsigned_amount():
    i, u = ir.Name("i", "local", type="int"), ir.Name("u", "local", type="uint")
    assert WgslPrinter().expression(ir.Binary("<<", u, i, type="uint")) == "u << u32(i)"
    assert WgslPrinter().expression(ir.Binary(">>", u, ir.Literal(16, "16", type="int"), type="uint")) == "u >> 16"
    assert WgslPrinter().statements([ir.Assign("<<=", u, i)], 0) == ["u <<= u32(i);"]


def test_wgsl_matrix_of_another_size_as_glsl_fills_it():
    m3, m4 = ir.Name("m", "local", type="mat3"), ir.Name("q", "local", type="mat4")
    assert WgslPrinter().expression(ir.Construct("mat4", [m3])) == \
        "mat4x4f(vec4f(m[0], 0.0), vec4f(m[1], 0.0), vec4f(m[2], 0.0), vec4f(0.0, 0.0, 0.0, 1.0))"
    assert WgslPrinter().expression(ir.Construct("mat3", [m4])) == "mat3x3f(q[0].xyz, q[1].xyz, q[2].xyz)"


def test_globals():
    """A uniform's initialiser in GLSL 4.00, none in ESSL 3.00 (which has none); a target's own
    variable is not declared; a WGSL module-scope variable is private."""
    uniform = ir.Global("float", "u_x", "uniform", init=ir.Literal(0.5, "0.5", type="float"))
    assert GlslPrinter("glsl").item(uniform) == ["uniform float u_x = 0.5;"]
    assert GlslPrinter("essl").item(uniform) == ["uniform float u_x;"]
    lights = ir.Global("LightData[3]", "u_lightData", "uniform")
    assert GlslPrinter("glsl").item(lights) == ["uniform LightData u_lightData[3];"]
    facing = ir.Global("bool", "gl_FrontFacing", "builtin")
    assert GlslPrinter("glsl").item(facing) == [] == WgslPrinter().item(facing)
    table = ir.Global("float", "t", "global", init=ir.Literal(1, "1", type="int"))
    assert WgslPrinter().item(table) == ["var<private> t: f32 = 1.0;"]


def test_names_are_spelled_by_the_caller():
    """`spell` decides how a Name prints (the stage assembler's vertex data): in expressions,
    declarations and parameters alike."""
    def spell(name):
        return f"vd.{name.name}" if name.kind == "vertexdata" else f"my_{name.name}"

    position = ir.Name("position", "vertexdata", type="vec3")
    stmt = ir.Declare("vec3", "p", ir.Binary("*", position, ir.Literal(2.0, "2.0", type="float"), type="vec3"), False)
    assert GlslPrinter("glsl", spell=spell).statements([stmt], 0) == ["vec3 my_p = vd.position * 2.0;"]
    assert WgslPrinter(spell=spell).statements([stmt], 0) == ["var my_p: vec3f = vd.position * 2.0;"]
    f = ir.Function("float", "f", [ir.Param("in", "float", "x", False)],
                    ir.Block([ir.Return(ir.Name("x", "param", type="float"))], True))
    assert GlslPrinter("glsl", spell=spell).item(f)[0] == "float f(float my_x)"
    assert WgslPrinter(spell=spell).item(f) == ["fn f(my_x: f32) -> f32 {", "    return my_x;", "}"]


# -- precedence and round trips ---------------------------------------------------------------------
def name(n):
    return ir.Name(n, None)


def binary(op, a, b):
    return ir.Binary(op, a, b)


PRECEDENCE = [  # (IR, how GLSL prints it)
    (binary("-", name("a"), binary("-", name("b"), name("c"))), "a - (b - c)"),
    (binary("-", binary("-", name("a"), name("b")), name("c")), "a - b - c"),
    (ir.Unary("-", ir.Unary("-", name("x"))), "-(-x)"),
    (binary("*", binary("+", name("a"), name("b")), name("c")), "(a + b) * c"),
    (binary("+", name("a"), binary("*", name("b"), name("c"))), "a + b * c"),
    (binary("==", binary("<", name("a"), name("b")), name("c")), "a < b == c"),
    (binary("<", name("a"), binary("==", name("b"), name("c"))), "a < (b == c)"),
    (binary("/", name("a"), binary("*", name("b"), name("c"))), "a / (b * c)"),
    (binary("||", name("a"), binary("&&", name("b"), name("c"))), "a || (b && c)"),
    (binary("&&", binary("||", name("a"), name("b")), name("c")), "(a || b) && c"),
    (ir.Field(binary("+", name("v"), name("w")), "xy"), "(v + w).xy"),
    (ir.Field(ir.Unary("-", name("v")), "x"), "(-v).x"),
    (ir.Select(name("p"), ir.Select(name("q"), name("a"), name("b")), name("c")), "p ? (q ? a : b) : c"),
    (ir.Select(name("p"), name("a"), ir.Select(name("q"), name("b"), name("c"))), "p ? a : q ? b : c"),
    (binary("*", ir.Select(name("p"), name("a"), name("b")), name("c")), "(p ? a : b) * c"),
    (ir.Unary("!", binary("&&", name("p"), name("q"))), "!(p && q)"),
    (ir.Index(ir.Call("f", [name("a")]), binary("+", name("i"), ir.Literal(1, "1"))), "f(a)[i + 1]"),
]


@pytest.mark.parametrize("expr, text", PRECEDENCE, ids=[t for _, t in PRECEDENCE])
def test_glsl_parentheses_from_precedence_and_round_trip(expr, text):
    printed = GlslPrinter("glsl").expression(expr)
    assert printed == text
    assert same(parse_expression(printed, "case"), expr)


WGSL_PRECEDENCE = [  # WGSL does not chain comparisons nor mix && with ||: parentheses there
    (binary("==", binary("<", name("a"), name("b")), name("c")), "(a < b) == c"),
    (binary("&&", binary("||", name("a"), name("b")), name("c")), "(a || b) && c"),
    (binary("||", name("a"), binary("&&", name("b"), name("c"))), "a || (b && c)"),
    (binary("&", binary("|", name("a"), name("b")), name("c")), "(a | b) & c"),
    (binary("-", name("a"), binary("-", name("b"), name("c"))), "a - (b - c)"),
    (ir.Unary("-", ir.Unary("-", name("x"))), "-(-x)"),
    (binary("*", binary("+", name("a"), name("b")), name("c")), "(a + b) * c"),
]


@pytest.mark.parametrize("expr, text", WGSL_PRECEDENCE, ids=[t for _, t in WGSL_PRECEDENCE])
def test_wgsl_parentheses_where_its_grammar_needs_them(expr, text):
    assert WgslPrinter().expression(expr) == text


def test_printed_library_parses_back_to_the_same_ir():
    """Every library file printed as GLSL, parsed again: the same items (comments, sections,
    brace-less bodies and all)."""
    printer = GlslPrinter("glsl")
    differ = []
    for path, module in parsed().items():
        text = "\n".join(line for item in module.items for line in [*printer.item(item), ""])
        again = parse_module(path, text)
        if not same(again.items, module.items):
            differ.append(path)
    assert not differ, differ[:5]


def test_printing_is_deterministic(modules):
    """The same text from another printer, and from items printed in the reverse order."""
    functions = [n for m in modules.values() for item in m.items for n in ir.walk(item) if type(n) is ir.Function]
    items = [item for m in modules.values() for item in m.items]
    names = function_names(functions)
    for make in (lambda: GlslPrinter("glsl"), lambda: GlslPrinter("essl"), lambda: WgslPrinter(names)):
        first = [make().item(item) for item in items]
        printer = make()
        backwards = [printer.item(item) for item in reversed(items)]
        assert first == list(reversed(backwards))


def test_what_wgsl_cannot_say_is_an_unsupported_node_error_naming_it(modules):
    texture = ir.Name("tex", "param", type="sampler2D")
    uv = ir.Name("uv", "local", type="vec2")
    query = ir.Call("textureQueryLod", [texture, uv], type="vec2", where=("lib/x.glsl", 3, 7), builtin=True)
    with pytest.raises(ShaderGenError) as caught:
        WgslPrinter().expression(query)
    assert caught.value.code == "unsupported_node" and "textureQueryLod" in caught.value.message
    assert caught.value.where == "lib/x.glsl:3:7"
    placeholder = ir.Placeholder("in", type="float")
    for printer in (GlslPrinter("glsl"), WgslPrinter()):
        with pytest.raises(ShaderGenError) as caught:
            printer.expression(placeholder)
        assert caught.value.code == "unsupported_node" and "laceholder" in caught.value.message


def test_wgsl_out_parameters_pointers_and_copies():
    """An out parameter is a pointer (`*r` read, `&a` passed), an assigned in parameter a copy,
    a member passed as an out argument goes through a variable copied back after the call."""
    k, r = ir.Name("k", "param", type="float"), ir.Name("r", "param", type="float")
    body = ir.Block([ir.Assign("*=", k, ir.Literal(2.0, "2.0", type="float")), ir.Assign("=", r, k)], True)
    params = [ir.Param("in", "float", "k", False), ir.Param("out", "float", "r", False)]
    writes = ir.Function("void", "mx_write", params, body)
    v = ir.Name("v", "local", type="vec3")
    call = ir.Call("mx_write", [ir.Literal(1.0, "1.0", type="float"), ir.Field(v, "x", type="float", swizzle=True)],
                   type="void", callee=writes)
    printer = WgslPrinter(function_names([writes]))
    assert printer.item(writes) == ["fn mx_write(k__in: f32, r: ptr<function, f32>) {", "    var k: f32 = k__in;",
                                    "    k *= 2.0;", "    *r = k;", "}"]
    assert printer.statements([ir.ExprStatement(call)], 1) == [
        "    var written_0: f32 = v.x;", "    mx_write(1.0, &written_0);", "    v.x = written_0;"]


def test_long_argument_lists_wrap_aligned_after_the_parenthesis():
    args = [name(f"argument_number_{i}") for i in range(9)]
    stmt = ir.Declare("float", "t", ir.Call("mx_function_with_a_long_name", args), False)
    lines = GlslPrinter("glsl").statements([stmt], 1)
    assert len(lines) == 3 and all(len(line) <= 110 for line in lines)
    column = lines[0].index("(") + 1
    assert all(line[:column].isspace() and line[column] != " " for line in lines[1:])
