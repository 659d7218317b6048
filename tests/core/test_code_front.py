"""The code front end (shadergen/code: lex, parse, check, library): library source into typed IR."""
import os
import pickle
import shutil

import pytest

from shadergen.code import cachefile, ir
from shadergen.code.cachefile import library_items
from shadergen.code.check import check_modules, flat_items
from shadergen.code.externals import EXTERNALS
from shadergen.code.library import PRELUDE, PRELUDE_PATH, CodeLibrary, build, cache_key, inline_sources, source_files
from shadergen.code.parse import parse_expression, parse_module
from shadergen.code.passes import sections
from shadergen.code.types import ir_type
from shadergen.errors import ShaderGenError
from shadergen.library import Library, Scope, read_source
from shadergen.targets.closures import LIGHT_DATA_MEMBERS
from shadergen.targets.glsl.printer import GlslPrinter
from shadergen.targets.printed import PrintedLibrary


def printed(item) -> list[str]:
    return GlslPrinter("glsl").item(item)

@pytest.fixture(scope="module")
def library() -> Library:
    return Library.load()


def checked(sources: dict[str, str], externals=None) -> dict[str, ir.Module]:
    """Modules of the given sources, checked with the prelude."""
    modules = {PRELUDE: parse_module(PRELUDE, read_source(PRELUDE_PATH))}
    modules.update({path: parse_module(path, text) for path, text in sources.items()})
    check_modules(modules, externals or {}, (PRELUDE,))
    return modules


def function(module: ir.Module, name: str) -> ir.Function:
    return next(item for item in flat_items(module.items) if isinstance(item, ir.Function) and item.name == name)


# -- the whole library -----------------------------------------------------------------------------
def test_every_library_file_parses_and_checks(code, library):
    files = source_files(library.root)
    assert len(files) >= 100
    assert set(files) <= set(code.modules)
    untyped, calls = [], 0
    for path in files:
        module = code.module(path)
        text = read_source(os.path.join(library.root, path))
        assert len(module.features) == text.count("#pragma shadergen feature"), path
        assert all(len(f) == 4 and f[0].isidentifier() for f in module.features), path
        for inc in module.includes:
            assert inc in code.modules, (path, inc)
        for item in module.items:
            for node in ir.walk(item):
                assert node.where is not None and node.where[0] == path, (path, node)
                if isinstance(node, ir.Expr) and node.type is None:
                    untyped.append(node)
                if isinstance(node, ir.Call):
                    calls += 1
                    assert node.builtin or isinstance(node.callee, ir.Function), node
                if isinstance(node, ir.Name):
                    assert node.kind in ("local", "param", "global", "uniform", "builtin"), node
    assert untyped == []
    assert calls > 1000
    # aliases are resolved: no EDF or material is left in a type
    assert code.functions("mx_fresnel_airy")[0].returns == "vec3"
    assert code.struct("LightData").members[0] == ("int", "type")
    assert code.constant("MAX_LIGHT_SOURCES").value.value == 3
    assert code.constant("EDF") is None


def test_every_inline_expression_parses_and_checks(code, library):
    scope = Scope(library, None)
    count = 0
    for impls in library.implementations.values():
        for impl in impls:
            text = impl.get("sourcecode")
            if text is None:
                continue
            count += 1
            nodedef = library.nodedefs[impl.get("nodedef")]
            types = {i.name: ir_type(i.get("type")) for i in scope.nodedef_inputs(nodedef)}
            typed = code.expression(text, types)
            assert typed.type == ir_type(scope.nodedef_outputs(nodedef)[0].get("type")), (impl.name, text)
            assert code.expression(text, types) is typed  # memoised per (template, types)
            # the template itself stays untyped
            assert all(n.type is None for n in ir.walk(code.template(text)) if not isinstance(n, ir.Construct))
    assert count >= 500
    assert len(inline_sources(library)) == count and set(code.templates) == {t for t, _ in inline_sources(library)}


def test_the_prelude_declares_the_closure_shader_and_light_types(code):
    """The types every target's closure convention writes (targets/closures.py): two colours for a
    BSDF and a shader, an EDF is its radiance, a material a surface shader; the light rig's
    members are those the convention lists for renderers."""
    for name in ("BSDF", "VDF"):
        assert code.struct(name).members == [("vec3", "response"), ("vec3", "throughput")]
    for name in ("surfaceshader", "volumeshader"):
        assert code.struct(name).members == [("vec3", "color"), ("vec3", "transparency")]
    assert code.struct("lightshader").members == [("vec3", "intensity"), ("vec3", "direction")]
    assert code.symbols.aliases == {"EDF": "vec3", "material": "surfaceshader"}
    assert code.constant("MAX_LIGHT_SOURCES").value.value == 3
    assert [n for _, n in code.struct("LightData").members] == [n for n, _ in LIGHT_DATA_MEMBERS]
    assert [t for t, _ in code.struct("LightData").members] == [ir_type(t) for _, t in LIGHT_DATA_MEMBERS]


def test_implicit_conversions_are_written_out():
    module = checked({"a.glsl": """
float f(float x) { return x; }
vec3 g(vec3 v, int i)
{
    float a = 1;
    vec2 p = vec2(i, 1.0);
    vec3 c = clamp(v, 0.0, 1.0) * 2.0 + f(i);
    return mix(c, v, 0.5) * a;
}
"""})["a.glsl"]
    body = function(module, "g").body.body
    assert isinstance(body[0].init, ir.Convert) and body[0].init.implicit and body[0].init.type == "float"
    first = body[1].init.args[0]
    assert isinstance(first, ir.Convert) and first.type == "float" and body[1].init.args[1].type == "float"
    total = body[2].init  # clamp(...) * 2.0 + f(i)
    clamp = total.left.left
    assert clamp.builtin and [a.type for a in clamp.args] == ["vec3"] * 3
    assert [type(a).__name__ for a in clamp.args] == ["Name", "Convert", "Convert"]
    assert not isinstance(total.left.right, ir.Convert)  # vec3 * float: the operator takes it
    call = total.right
    assert call.callee is function(module, "f") and isinstance(call.args[0], ir.Convert)


def test_swizzles_structs_and_aliases():
    module = checked({"a.glsl": """
struct S { vec3 v; float w[2]; };
EDF e(S s, vec4 c)
{
    BSDF b = BSDF(vec3(0.0), c.rgb);
    material m = material(s.v, vec3(s.w[1]));
    return b.response.bgr + m.color + EDF(0.0);
}
"""})["a.glsl"]
    fn = function(module, "e")
    assert fn.returns == "vec3" and fn.key == "e(S,vec4)"
    b, m, ret = fn.body.body
    assert isinstance(b.init, ir.Construct) and b.init.type == "BSDF"
    swizzle = b.init.args[1]
    assert swizzle.swizzle and swizzle.name == "xyz"
    assert m.type == "surfaceshader" and m.init.type == "surfaceshader"
    assert ret.value.left.left.name == "zyx"


# -- errors ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("source, where, what", [
    ("void f()\n{\n    float a = 1.0 +;\n}\n", "x.glsl:3:20", "unexpected ';'"),
    ("void f()\n{\n    float a = 1.0 $ 2.0;\n}\n", "x.glsl:3:19", "unexpected character '$'"),
    ("void f()\n{\n    float a = 1.0;\n", "x.glsl:4:1", "expected '}'"),
    ("#ifdef X\nvoid f() {}\n", "x.glsl:3:1", "has no #endif"),
    ("#version 400\n", "x.glsl:1:1", "preprocessor line"),
    ("const float A = 1.0u;\n", "x.glsl:1:17", "a float with an unsigned suffix"),
    ("const int A = 4294967296;\n", "x.glsl:1:15", "does not fit in 32 bits"),
])
def test_parse_errors_name_file_line_and_column(source, where, what):
    with pytest.raises(ShaderGenError) as info:
        parse_module("x.glsl", source)
    assert info.value.code == "invalid_source"
    assert info.value.message.startswith(where + ": "), info.value.message
    assert what in info.value.message


@pytest.mark.parametrize("source, where, what", [
    ("void f()\n{\n    float a = b;\n}\n", "x.glsl:3:15", "unknown name 'b'"),
    ("void f()\n{\n    vec3 a = vec2(1.0);\n}\n", "x.glsl:3:14", "a vec2 where a vec3 is expected"),
    ("void f(out float x) {}\nvoid g()\n{\n    f(1.0);\n}\n", "x.glsl:4:7", "is not a variable"),
    ("void f()\n{\n    nothing(1.0);\n}\n", "x.glsl:3:5", "unknown function 'nothing'"),
    ("void f(vec3 v)\n{\n    float a = v.xq;\n}\n", "x.glsl:3:15", "not a swizzle"),
    ("float f()\n{\n    return;\n}\n", "x.glsl:3:5", "without a value"),
])
def test_check_errors_name_file_line_and_column(source, where, what):
    with pytest.raises(ShaderGenError) as info:
        checked({"x.glsl": source})
    assert info.value.code == "invalid_source"
    assert info.value.message.startswith(where + ": "), info.value.message
    assert what in info.value.message


def test_expression_errors_name_the_expression():
    with pytest.raises(ShaderGenError) as info:
        parse_expression("{{in}} * ", "stdlib_impl.mtlx: IM_x")
    assert info.value.message.startswith("stdlib_impl.mtlx: IM_x:1:10: ")


# -- sections ----------------------------------------------------------------------------------------
def resolved(stmts: list, defined: set[str]) -> list:
    """The statements as the preprocessor gives them for `defined` (sections resolved, unscoped
    blocks flattened), as nested tuples: ("if", condition name, then, else) and ("x", value)."""
    out = []
    for s in stmts:
        if isinstance(s, ir.Section):
            out += resolved(s.body if (s.macro in defined) == s.defined else s.other, defined)
        elif isinstance(s, ir.Block):
            out += resolved(s.body, defined) if not s.scoped else [("block", resolved(s.body, defined))]
        elif isinstance(s, ir.If):
            other = resolved([s.other], defined) if s.other is not None else []
            out.append(("if", label(s.condition), resolved([s.then], defined), other))
        elif isinstance(s, ir.Assign):
            out.append(("x", getattr(s.value, "value", None)))
    return out


def label(e: ir.Expr) -> str:
    """A condition by the name it starts with (`context == ...`: "context")."""
    while not isinstance(e, ir.Name):
        e = e.left if isinstance(e, ir.Binary) else e.base
    return e.name


def chain(stmts: list) -> list:
    """An if chain as its conditions in order, "else" for a final else clause."""
    (first,) = stmts
    out = []
    while True:
        out.append(first[1])
        other = first[3]
        if not other:
            return out
        if other[0][0] == "if" and len(other) == 1:
            first = other[0]
        else:
            return out + ["else"]


SECTION_ELSE = """
void f(bool a, bool t, bool u)
{
    int x = 0;
    if (a)
        x = 1;
#ifdef T
    else if (t)
        x = 2;
#endif
#ifdef U
    else if (u)
    {
        x = 3;
    }
#endif
#ifndef L
    else
        x = 4;
#endif
}
"""


@pytest.mark.parametrize("defined", [set(), {"T"}, {"U"}, {"L"}, {"T", "U"}, {"T", "L"}, {"U", "L"}, {"T", "U", "L"}])
def test_a_section_else_chain_is_the_preprocessors_for_each_macro_combination(defined):
    fn = function(checked({"x.glsl": SECTION_ELSE})["x.glsl"], "f")
    expected = ["a"] + [c for c, m in (("t", "T"), ("u", "U")) if m in defined] + ([] if "L" in defined else ["else"])
    ifs = [s for s in resolved(fn.body.body, defined) if s[0] == "if"]
    assert chain(ifs) == expected
    values = [s.value.value for s in ir.walk(fn.body) if isinstance(s, ir.Assign)]
    assert set(values) == {1, 2, 3, 4}


@pytest.mark.parametrize("defined", [set(), {"MX_FEATURE_TRANSMISSION"}, {"MX_FEATURE_LIGHTS"},
                                     {"MX_FEATURE_TRANSMISSION", "MX_FEATURE_LIGHTS"}])
def test_the_dielectric_bsdf_chain(code, defined):
    fn = code.functions("mx_dielectric_bsdf")[0]
    ifs = [s for s in resolved(fn.body.body, defined) if s[0] == "if"]
    transmission = ["transmission"] if "MX_FEATURE_TRANSMISSION" in defined else []
    lights = ["else"] if "MX_FEATURE_LIGHTS" in defined else []
    assert chain(ifs[1:]) == ["context"] + transmission + lights
    other = fn.body.body[3].other
    assert not other.scoped and isinstance(other.body[0], ir.Section) and other.body[0].else_branch


def test_a_dangling_else_after_endif_follows_the_section_on_both_sides():
    fn = function(checked({"x.glsl": """
void f(bool s)
{
    int x = 0;
#ifdef S
    if (s)
        x = 1;
    else
#endif
    {
        x = 2;
    }
    x = 3;
}
"""})["x.glsl"], "f")
    assert resolved(fn.body.body, {"S"}) == [("if", "s", [("x", 1)], [("block", [("x", 2)])]), ("x", 3)]
    assert resolved(fn.body.body, set()) == [("block", [("x", 2)]), ("x", 3)]


# -- what the parser keeps ---------------------------------------------------------------------------
def test_comments_literals_and_bodies():
    module = parse_module("x.glsl", """// the file's own comment

// what f does
float f(float a)
{
    // a comment of its own
    // on two lines
    float b = 1e-20;  // after code
    if (a > 0.5)
        return a;
    return b;
}
""")
    fn = module.items[0]
    assert fn.comment == ["what f does"]
    comment, declare, branch, _ = fn.body.body
    assert comment.lines == ["a comment of its own", "on two lines"]
    assert declare.comment == "after code" and declare.init.text == "1e-20" and declare.init.value == 1e-20
    assert branch.then.scoped is False and fn.body.scoped is True
    assert fn.where == ("x.glsl", 4, 1) and declare.where == ("x.glsl", 8, 11)


# -- the cache -------------------------------------------------------------------------------------
def test_the_cache_round_trips_and_a_corrupt_file_is_rebuilt(library, tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    built = CodeLibrary.load(library, EXTERNALS)
    (cached,) = [p for p in tmp_path.iterdir() if p.name.startswith("code-")]
    reloaded = CodeLibrary.load(library, EXTERNALS)
    assert reloaded.modules is not built.modules
    # the file's bytes again (a plain pickle of the reloaded state would differ in what it shares:
    # a body read apart has strings of its own)
    assert cachefile.dumps(reloaded.state(), library_items(reloaded.modules)) == \
        cachefile.dumps(built.state(), library_items(built.modules))
    # a reloaded call still resolves to the function object of its module
    call = next(n for n in ir.walk(reloaded.functions("mx_dielectric_bsdf")[0]) if isinstance(n, ir.Call) and n.callee)
    assert call.callee in reloaded.functions(call.name)

    data = cached.read_bytes()
    cached.write_bytes(data[:100] + b"garbage" + data[107:])
    rebuilt = CodeLibrary.load(library, EXTERNALS)
    assert pickle.dumps(rebuilt.state()) == pickle.dumps(built.state())
    assert cached.read_bytes() == data
    cached.write_bytes(b"")
    assert pickle.dumps(CodeLibrary.load(library, EXTERNALS).state()) == pickle.dumps(built.state())
    assert cached.read_bytes() == data


def test_a_reloaded_function_reads_its_params_facts_and_body_when_first_asked(library, tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    built = CodeLibrary.load(library, EXTERNALS)
    reloaded = CodeLibrary.load(library, EXTERNALS)
    key = next(f.key for f in built.functions("mx_dielectric_bsdf") if f.facts.stores)
    fn = next(f for f in reloaded.functions("mx_dielectric_bsdf") if f.key == key)
    assert set(fn.pending.locations) == {"params", "facts", "body"}  # nothing of any read yet
    assert fn.facts.stores and set(fn.pending.locations) == {"params", "body"}  # the facts alone
    # the body's member stores are the very statements the facts name (the fields pass removes them by identity)
    statements = {id(n) for n in ir.walk(fn.body)}
    assert set(fn.pending.locations) == {"params"} and all(id(store.statement) in statements for store in fn.facts.stores)
    assert fn.key == fn.name + "(" + ",".join(p.type for p in fn.params) + ")" and not fn.pending.locations
    assert printed(fn) == printed(next(f for f in built.functions("mx_dielectric_bsdf") if f.key == key))


def test_a_field_damaged_in_the_file_is_read_from_the_file_built_again(library, tmp_path, monkeypatch):
    """The state is checked when the file is read, each deferred field when it is first read: a
    field damaged on disk, cut off, or in a file gone since, has the file built and written again
    (the same bytes), and it and every field read after it come from that."""
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    built = CodeLibrary.load(library, EXTERNALS)
    (cached,) = [p for p in tmp_path.iterdir() if p.name.startswith("code-")]
    data = cached.read_bytes()
    key = next(f.key for f in built.functions("mx_dielectric_bsdf") if f.facts.stores)

    def function(code):
        return next(f for f in code.functions("mx_dielectric_bsdf") if f.key == key)

    def every_function(code):
        return [printed(f) for f in library_items(code.modules) if isinstance(f, ir.Function)]
    pending = function(CodeLibrary.load(library, EXTERNALS)).pending
    middle = pending.area.start + pending.locations["body"][0] + pending.locations["body"][1] // 2
    expected = every_function(built)
    for damage in (data[:middle] + bytes([data[middle] ^ 0xFF]) + data[middle + 1:], data[:middle]):
        cached.write_bytes(damage)
        reloaded = CodeLibrary.load(library, EXTERNALS)  # its state is sound: read as it is
        assert cached.read_bytes() == damage
        assert printed(function(reloaded)) == printed(function(built))
        assert cached.read_bytes() == data
        assert every_function(reloaded) == expected
    reloaded = CodeLibrary.load(library, EXTERNALS)
    cached.unlink()  # gone before a field was read (the fields are read from the file when first asked for)
    assert every_function(reloaded) == expected and cached.read_bytes() == data


def test_a_reloaded_librarys_inline_templates_are_read_when_first_asked(library, tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    built = CodeLibrary.load(library, EXTERNALS)
    reloaded = CodeLibrary.load(library, EXTERNALS)
    text, *others = list(reloaded.templates)
    assert list(built.templates) == [text, *others] and not reloaded.templates.values
    template = reloaded.template(text)
    assert list(reloaded.templates.values) == [text] and text not in reloaded.templates.locations
    assert reloaded.template(text) is template and ir.shape(template) == ir.shape(built.template(text))


def test_a_function_with_sections_comes_resolved_from_the_cache_with_its_printed_lines(library, tmp_path, monkeypatch):
    """What a cold process's sections pass gets for a library function: the copy the cache holds
    (read only once a stage asks), equal to resolving it afresh, the same object request after
    request, and printed by the printed library's file, not again."""
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    CodeLibrary.load(library, EXTERNALS)  # builds the cache
    reloaded = CodeLibrary.load(library, EXTERNALS)
    assert not [p for p in tmp_path.iterdir() if p.name.startswith("resolutions-")]  # written when first asked
    PrintedLibrary(reloaded, "glsl", printed)  # writes the printed library, the copies' lines too
    (resolutions,) = [p for p in tmp_path.iterdir() if p.name.startswith("resolutions-")]
    written = resolutions.read_bytes()
    for damage in (b"", written[:100] + b"garbage" + written[107:]):  # missing, damaged: written again alike
        resolutions.write_bytes(damage)
        CodeLibrary.load(library, EXTERNALS).read_resolutions()
        assert resolutions.read_bytes() == written
    reloaded = CodeLibrary.load(library, EXTERNALS)
    assert reloaded.resolved is None  # nothing read before a stage asks
    function = next(f for f in library_items(reloaded.modules) if isinstance(f, ir.Function)
                    and any(m.startswith(sections.FEATURE_PREFIX) for m in sections.macros_in(f)))
    # a stage without the features, which decides no other macro (no environment chosen)
    decisions = tuple((m, False if m.startswith(sections.FEATURE_PREFIX) else None) for m in sections.macros_in(function))
    copies, count = reloaded.resolution(function, decisions)
    fresh, fresh_count = sections.resolve(function, decisions)
    assert count == fresh_count > 0 and [ir.shape(i) for i in copies] == [ir.shape(i) for i in fresh]
    resolved, _ = sections.run([function], frozenset(), frozenset(), reloaded)
    assert resolved == list(copies)  # the very objects: later passes' memos and the printed lines hit
    read = PrintedLibrary(reloaded, "glsl", lambda item: pytest.fail("printed again"))
    assert read.lines(copies[0]) == tuple(printed(copies[0]))
    assert read.lines(fresh[0]) is None  # a copy made here is printed from its IR


def test_library_items_are_printed_once_per_library_into_a_file(library, code, tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    items = library_items(code.modules)
    written = PrintedLibrary(code, "glsl", printed)
    (path,) = [p for p in tmp_path.iterdir() if p.name.startswith("printed-glsl-")]
    read = PrintedLibrary(code, "glsl", lambda item: pytest.fail("printed again"))
    expected = [tuple(printed(i)) for i in items]
    assert [written.lines(i) for i in items] == expected == [read.lines(i) for i in items]
    assert read.lines(ir.replace(items[-1])) is None  # a copy a pass made is printed from its IR
    path.write_bytes(b"damaged")
    assert PrintedLibrary(code, "glsl", printed).lines(items[0]) == tuple(printed(items[0]))


def test_builds_in_different_orders_give_equal_pickles(library, tmp_path):
    """Two copies of the library whose files were written in opposite orders (a folder lists
    them in the order they were made), and externals given in another order."""
    roots = []
    for name, order in (("a", 1), ("b", -1)):
        root = tmp_path / name / "libraries"
        files = sorted(os.path.relpath(os.path.join(d, f), library.root)
                       for d, _, fs in os.walk(library.root) for f in fs)
        for relative in files[::order]:
            (root / relative).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(os.path.join(library.root, relative), root / relative)
        roots.append(Library.load(str(root)))
    reversed_externals = dict(reversed(list(EXTERNALS.items())))
    a = build(roots[0], EXTERNALS, cache_key(roots[0], EXTERNALS))
    b = build(roots[1], reversed_externals, cache_key(roots[1], reversed_externals))
    assert pickle.dumps(a[1:]) == pickle.dumps(b[1:])


def test_a_comment_after_code_belongs_to_the_innermost_statement_ending_there():
    fn = parse_module("x.glsl", """
void f(float a)
{
    if (a > 0.5)
        return;  // early
    if (a < 0.0)
    {  // negative
        a = 0.0;
    }  // done
    else  // the rest
        a = 1.0;
}
""").items[0]
    first, second = fn.body.body
    assert first.then.body[0].comment == "early" and first.comment is None
    assert second.then.body[0].comment == "negative" and second.then.comment == "done"
    assert second.other.comment is None and second.other.body[0].comment == "the rest"


@pytest.mark.parametrize("text", [
    "(" * 5000 + "1.0" + ")" * 5000,
    "- " * 5000 + "1.0",
    " + ".join(["{{in}}"] * 5000),
    "f(" * 3000 + "1.0" + ")" * 3000,
])
def test_deeply_nested_expressions_are_refused_not_a_recursion_error(code, text):
    with pytest.raises(ShaderGenError) as info:
        code.template(text, "doc.mtlx: IM_deep")
    assert info.value.code == "invalid_source" and "nested more than" in info.value.message
    assert info.value.message.startswith("doc.mtlx: IM_deep:1:")


def test_deeply_nested_statements_are_refused_not_a_recursion_error():
    body = "if (a) " * 3000 + "a = false;"
    for source in (f"void f(bool a) {{ {body} }}", "void f(bool a) " + "{" * 3000 + "}" * 3000,
                   "void f(bool a) { if (a) {} " + "else if (a) {} " * 3000 + "}"):
        with pytest.raises(ShaderGenError) as info:
            parse_module("x.glsl", source)
        assert "nested more than" in info.value.message


def test_an_else_section_with_an_else_side_and_a_second_final_else():
    fn = function(checked({"x.glsl": """
void f(bool a)
{
    int x = 0;
    if (a)
        x = 1;
#ifdef T
    else
        x = 2;
#else
    else
        x = 3;
#endif
}
"""})["x.glsl"], "f")
    assert resolved(fn.body.body, {"T"}) == [("if", "a", [("x", 1)], [("x", 2)])]
    assert resolved(fn.body.body, set()) == [("if", "a", [("x", 1)], [("x", 3)])]
    with pytest.raises(ShaderGenError) as info:
        parse_module("x.glsl", "void f(bool a)\n{\n    if (a) {}\n#ifdef T\n    else {}\n#endif\n    else {}\n}\n")
    assert info.value.message.startswith("x.glsl:7:5: an 'else' after the final 'else'")


def test_modules_are_found_by_absolute_or_relative_path(code, library):
    relative = os.path.join("pbrlib", "genglsl", "mx_dielectric_bsdf.glsl")
    assert code.module(os.path.join(library.root, relative)) is code.module(relative)
    assert code.module(relative).includes == (os.path.join("pbrlib", "genglsl", "lib", "mx_specular.glsl"),
                                              os.path.join("pbrlib", "genglsl", "lib", "mx_albedo_dielectric.glsl"))
    with pytest.raises(ShaderGenError) as info:
        code.module("nowhere.glsl")
    assert info.value.code == "missing_source"
