"""The IR printers (targets/glsl/printer.py, targets/wgsl/printer.py): every library source file
printed compiles with the real compilers (glslangValidator for GLSL 4.00 and ESSL 3.00, naga for
WGSL), in a translation unit of its own with the files it includes; parentheses come out where
precedence needs them and the printed text parses back to the same IR; printing is deterministic."""
import glob
import os
import subprocess

import pytest

from required_tools import tool_path
from shadergen.code import ir
from shadergen.code.parse import parse_expression, parse_module
from shadergen.targets.glsl import STRUCTS
from shadergen.targets.glsl.printer import GlslPrinter, same
from shadergen.targets.wgsl.printer import WgslPrinter

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SOURCES = sorted(os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, "libraries/*/genglsl/**/*.glsl"),
                                                               recursive=True))
# The globals the libraries read and do not define (BRIEF: environment uniforms, lights, facing).
GLOBALS = """\
uniform mat4 u_envMatrix;
uniform sampler2D u_envRadiance;
uniform float u_envLightIntensity;
uniform int u_envRadianceMips;
uniform int u_envRadianceSamples;
uniform sampler2D u_envIrradiance;
uniform bool u_refractionTwoSided;
uniform vec3 u_viewPosition;
uniform int u_numActiveLightSources;
uniform LightData u_lightData[MAX_LIGHT_SOURCES];
"""
HEADERS = {"glsl": "#version 400\n", "essl": "#version 300 es\nprecision highp float;\nprecision highp int;\n"}


@pytest.fixture(scope="module")
def modules() -> dict[str, ir.Module]:
    out = {}
    for path in SOURCES:
        with open(os.path.join(ROOT, path)) as f:
            out[path] = parse_module(path, f.read())
    return out


def in_include_order(path: str, modules: dict, seen: set) -> list[str]:
    """`path` after the files it includes (each once), as the preprocessor would read them."""
    if path in seen:
        return []
    seen.add(path)
    order = []
    for included in modules[path].includes:
        order += in_include_order(included, modules, seen)
    return order + [path]


def macros(modules: dict) -> list[str]:
    """Every feature macro a section of the libraries tests."""
    found = set()
    for module in modules.values():
        for item in module.items:
            found.update(n.macro for n in ir.walk(item) if type(n) is ir.Section and n.macro.startswith("MX_"))
    return sorted(found)


def glsl_unit(path: str, modules: dict, printer: GlslPrinter, defined: list[str]) -> str:
    lines = [HEADERS[printer.dialect].rstrip("\n")]
    lines += [f"#define {m}" for m in defined]
    lines += [STRUCTS[name] for name in STRUCTS]
    lines.append(GLOBALS)
    for source in in_include_order(path, modules, set()):
        for item in modules[source].items:
            lines += printer.item(item)
            lines.append("")
    lines.append("out vec4 fragment_colour;\nvoid main() { fragment_colour = vec4(0.0); }")
    return "\n".join(lines) + "\n"


def compile_all(units: dict[str, str], tmp_path) -> list[str]:
    """glslangValidator over every unit at once: the names of those it rejects, with its log."""
    tool = tool_path("glslangValidator")
    paths = []
    for i, (name, text) in enumerate(sorted(units.items())):
        path = tmp_path / f"u{i}.frag"
        path.write_text(text)
        paths.append((name, path))
    failures = []
    for start in range(0, len(paths), 50):  # bounded command lines
        chunk = paths[start:start + 50]
        run = subprocess.run([tool, *[str(p) for _, p in chunk]], capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            for name, p in chunk:
                one = subprocess.run([tool, str(p)], capture_output=True, text=True, timeout=60)
                if one.returncode != 0:
                    failures.append(f"{name}: {one.stdout[-800:]}")
    return failures


@pytest.mark.parametrize("dialect", ["glsl", "essl"])
def test_every_library_file_printed_compiles(modules, dialect, tmp_path):
    printer = GlslPrinter(dialect)
    every = macros(modules)
    units = {}
    for path in SOURCES:
        units[f"{path} (no features)"] = glsl_unit(path, modules, printer, [])
        units[f"{path} (every feature)"] = glsl_unit(path, modules, printer, every)
    assert len(units) == 2 * len(SOURCES) >= 200
    failures = compile_all(units, tmp_path)
    assert not failures, f"{len(failures)} of {len(units)} rejected:\n" + "\n".join(failures[:5])


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


def test_printed_library_parses_back_to_the_same_ir(modules):
    """Every library file printed as GLSL, parsed again: the same items (comments, sections,
    brace-less bodies and all)."""
    printer = GlslPrinter("glsl")
    differ = []
    for path, module in modules.items():
        text = "\n".join(line for item in module.items for line in [*printer.item(item), ""])
        again = parse_module(path, text)
        if not same(again.items, module.items):
            differ.append(path)
    assert not differ, differ[:5]


def test_printing_is_deterministic(modules):
    printer = GlslPrinter("glsl")
    first = [printer.item(item) for m in modules.values() for item in m.items]
    again = [GlslPrinter("glsl").item(item) for m in modules.values() for item in m.items]
    assert first == again


def test_long_argument_lists_wrap_aligned_after_the_parenthesis():
    args = [name(f"argument_number_{i}") for i in range(9)]
    stmt = ir.Declare("float", "t", ir.Call("mx_function_with_a_long_name", args), False)
    lines = GlslPrinter("glsl").statements([stmt], 1)
    assert len(lines) == 3 and all(len(line) <= 110 for line in lines)
    column = lines[0].index("(") + 1
    assert all(line[:column].isspace() and line[column] != " " for line in lines[1:])
