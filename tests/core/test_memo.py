"""What follows from the library alone (resolved nodedefs, parsed implementations, expanded
nodegraph bodies) is memoised in the Library across requests: a warm generator must write exactly
what a fresh one writes, and a library edit (a new Library, a new key) must never see the old facts."""
import functools
import shutil
from pathlib import Path

import pytest

from shadergen import generator
from shadergen.api import Generator
from shadergen.code import build, ir
from shadergen.code import stage as code_stage
from shadergen.code.kept import Kept
from shadergen.library import DEFAULT_LIBRARY_ROOT, Library
from shadergen.passes import expand
from shadergen.targets.glsl import printer as glsl_printer
from shadergen.targets.glsl import target as glsl_target

from .conftest import doc

ROOT = Path(__file__).resolve().parents[2]
MARBLE = ROOT / "examples" / "marble_checker.mtlx"
GOLDEN = ROOT / "tests" / "golden"
LOCAL_DEFINITION = doc(
    '<nodedef name="ND_tint" node="tint"><input name="in" type="float" value="1"/><output name="out" type="float"/></nodedef>'
    '<implementation name="IM_tint" nodedef="ND_tint" target="genglsl" sourcecode="{{in}} * 2.0" />'
    '<tint name="t" type="float"/><multiply name="m" type="float"><input name="in1" type="float" nodename="t"/></multiply>'
    '<output name="o" type="float" nodename="m"/>')
DOCUMENTS = [MARBLE, GOLDEN / "glass.mtlx", GOLDEN / "standard_surface_coated.mtlx", LOCAL_DEFINITION]


def comparable(record: dict) -> dict:
    return {k: v for k, v in record.items() if k != "timings_ms"}


def records(gen: Generator, document, **options) -> list[dict]:
    return [comparable(r) for r in gen.records(document, all=True, **options)]


@pytest.mark.parametrize("interface", ["complete", "reduced", "specialized"])
@pytest.mark.parametrize("target", ["glsl", "wgsl"])
def test_memoised_and_fresh_generation_write_the_same_records(interface, target):
    warm = Generator(Library.load())
    for document in DOCUMENTS:  # everything of every document memoised before the comparison
        records(warm, document, interface=interface, target=target)
    for document in DOCUMENTS:
        fresh = Generator(Library.load())  # a new Library: nothing memoised
        assert records(warm, document, interface=interface, target=target) == \
            records(fresh, document, interface=interface, target=target), document
    assert any(key[0] == "body" for key in warm.library.facts)  # the bodies were reused, not rebuilt


def test_a_library_edit_is_never_served_from_the_old_librarys_memo(tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path / "cache"))
    library = Path(shutil.copytree(DEFAULT_LIBRARY_ROOT, tmp_path / "libraries"))
    before = Generator(Library.load(library))
    first = before.prepare(MARBLE).emit()
    source = library / "stdlib" / "genglsl" / "mx_noise_fractal.glsl"  # read, expanded and memoised above
    marker = "// edited after the first generation"
    source.write_text(source.read_text().replace("{", "{\n    " + marker))
    after = Generator(Library.load(library))
    assert after.library_hash != before.library_hash
    edited = after.prepare(MARBLE).emit()
    assert marker in edited["stages"]["pixel"] and marker not in first["stages"]["pixel"]
    assert edited["hash"] != first["hash"]


class Forgetful(dict):
    """A memo that keeps nothing: what it would hold (a vertex stage, a value's text) made afresh each time."""

    def __setitem__(self, key, value):
        pass


@pytest.mark.parametrize("target", ["glsl", "essl", "wgsl", "osl"])
def test_a_vertex_stage_from_the_memo_is_the_one_built_afresh(target, monkeypatch):
    warm = Generator(Library.load())
    for document in DOCUMENTS:  # every document's vertex stages memoised first
        records(warm, document, interface="specialized", target=target)
    served = [records(warm, document, interface="specialized", target=target) for document in DOCUMENTS]
    vertex_stages = {r["stages"].get("vertex") for rs in served for r in rs}
    assert target == "osl" or len(vertex_stages) > 1  # stages the memo could confuse (OSL has none)
    monkeypatch.setattr(code_stage, "VERTEX_STAGES", Kept(0, 0))  # (keeps nothing)
    assert served == [records(warm, document, interface="specialized", target=target) for document in DOCUMENTS]


def test_the_vertex_stage_memo_tells_apart_code_that_prints_differently():
    x = build.name("x", "input", "vec3")
    assert ir.shape(build.construct("vec4", x, build.number(1.0))) == ir.shape(build.construct("vec4", x, build.number(1.0)))
    assert ir.shape(build.construct("vec4", x, build.number(1.0))) != ir.shape(build.construct("vec3", x, build.number(1.0)))
    assert ir.shape(ir.Literal(1, None, type="float")) != ir.shape(ir.Literal(1.0, None, type="float"))
    assert ir.shape(build.name("x", "input")) != ir.shape(build.name("x", "vertexdata"))


@pytest.mark.parametrize("target", ["glsl", "essl"])
def test_uniform_declarations_from_the_cache_are_the_ones_printed_afresh(target, monkeypatch):
    warm = Generator(Library.load())
    for document in DOCUMENTS:  # every document's uniforms cached first
        records(warm, document, interface="complete", target=target)
    served = [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]
    monkeypatch.setattr(glsl_target, "_shared_declaration", glsl_target._declaration)
    assert served == [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]
    # values Python compares equal are one key: they print alike
    declare = functools.partial(glsl_target.uniform_declaration, glsl_target.GlslTarget, "vec2", "u", "vector2")
    assert declare((1, 0)) == declare((1.0, 0.0)) == "uniform vec2 u = vec2(1.0, 0.0);"


@pytest.mark.parametrize("target", ["glsl", "essl", "vulkan"])
def test_values_printed_from_the_memo_are_the_ones_printed_afresh(target, monkeypatch):
    warm = Generator(Library.load())
    for document in DOCUMENTS:  # every document's values printed and kept first
        records(warm, document, interface="complete", target=target)
    assert glsl_printer.VALUE_LINES  # main's values went through the memo
    served = [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]
    monkeypatch.setattr(glsl_printer, "VALUE_LINES", Forgetful())
    assert served == [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]


# A document that defines a node of its own, as a nodegraph, used by two outputs: its facts are the
# document's, not the library's
OWN_NODEGRAPH = doc(
    '<nodedef name="ND_double" node="double"><input name="in" type="float" value="1"/><output name="out" type="float"/></nodedef>'
    '<nodegraph name="NG_double" nodedef="ND_double"><multiply name="m" type="float">'
    '<input name="in1" type="float" interfacename="in"/><input name="in2" type="float" value="2"/></multiply>'
    '<output name="out" type="float" nodename="m"/></nodegraph>'
    '<double name="a" type="float"><input name="in" type="float" value="0.25"/></double>'
    '<double name="b" type="float"><input name="in" type="float" value="0.5"/></double>'
    '<output name="oa" type="float" nodename="a"/><output name="ob" type="float" nodename="b"/>')


def test_a_documents_own_definitions_are_read_once_for_all_its_elements(monkeypatch):
    """A client asks for a document's elements one at a time: the scope of its definitions, and the
    nodegraph bodies it memoises, serve every element, and write what a fresh read writes."""
    gen = Generator(Library.load())
    document = gen.load(OWN_NODEGRAPH)
    built, build_body = [], expand.build_body
    monkeypatch.setattr(expand, "build_body", lambda *a: built.append(a) or build_body(*a))
    served = [comparable(gen.prepare(document, element=e).emit()) for e in ("oa", "ob", "oa")]
    assert len(built) == 1
    fresh = [comparable(Generator(Library.load()).prepare(gen.load(OWN_NODEGRAPH), element=e).emit())
             for e in ("oa", "ob", "oa")]
    assert served == fresh and served[0] != served[1]


# -- main's statements, typed, read and printed once per shape (code/statements.py) ------------------
@pytest.mark.parametrize("target", ["glsl", "essl", "vulkan", "wgsl", "osl"])
def test_statements_from_the_memo_write_the_records_written_afresh(target, monkeypatch):
    warm = Generator(Library.load())
    memo = warm.library.code().statements
    first = [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]
    served = [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]
    assert first == served and memo.entries  # the second time, from the memo
    monkeypatch.setattr(memo, "entries", Forgetful())
    assert served == [records(warm, document, interface="complete", target=target) for document in DOCUMENTS]
    assert not memo.entries  # (made afresh)


def code_of(gen: Generator, document) -> code_stage.StageCode:
    """The pixel stage's code of `document`'s first element, as the code passes gave it."""
    got = []
    run = code_stage.run

    def keep(ctx, counts):
        code = run(ctx, counts)
        got.append(code)
        return code
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(generator.code_passes, "run", keep)
        gen.prepare(document).emit()
    return got[0]


def main_of(gen: Generator, document) -> ir.Block:
    """Main of `document`'s first element, as the code passes got it."""
    return code_of(gen, document).main


def statements_in(block: ir.Block) -> set[int]:
    return {id(n) for n in ir.walk(block) if isinstance(n, ir.Stmt)}


def test_a_main_built_alike_is_the_one_typed_before_and_a_changed_one_keeps_its_alike_statements():
    gen = Generator(Library.load())
    coated = main_of(gen, GOLDEN / "standard_surface_coated.mtlx")
    assert main_of(gen, GOLDEN / "standard_surface_coated.mtlx") is coated  # the whole of main, typed once
    glass = main_of(gen, GOLDEN / "glass.mtlx")
    # another material: the statements it builds alike are the ones typed before, the others its own
    assert statements_in(glass) & statements_in(coated) and statements_in(glass) - statements_in(coated)


def test_statements_built_alike_have_one_key_and_any_difference_another():
    from shadergen.code.statements import UNKEYED, Keys, Memo
    x = build.name("x", "local", "vec3")
    memo = Memo()  # a library's: one number for each structure

    def key(statement, generated=()):
        named: dict = {}
        for f in generated:
            named.setdefault(f.name, []).append(f)
        return Keys(named, memo).statement(statement)

    def call(*args, function="mx_f"):
        return ir.ExprStatement(build.call(function, *args))
    assert key(call(x, build.number(1.0))) == key(call(build.name("x", "local", "vec3"), build.number(1.0)))
    assert key(call(x, build.number(1.0))) != key(call(x, ir.Literal(1, None, type="float")))  # 1.0 and 1 print apart
    assert key(call(x)) != key(call(build.name("x", "uniform", "vec3")))
    assert key(call(x)) != key(call(build.name("x", "local", "vec4")))
    assert key(call(build.name("y", "local"))) is UNKEYED  # typed by the scope: no key
    # a call of a function the request wrote is keyed by that function: another body, another key
    body = [build.function("void", "g", [("in", "vec3", "p")], ir.Block([ir.Return(None)], True))]
    other = [build.function("void", "g", [("in", "vec3", "p")], ir.Block([], True))]
    assert key(call(x, function="g"), body) != key(call(x, function="g"), other)
    assert key(call(x, function="g"), body) == key(call(x, function="g"), [ir.replace(body[0])])
    # an inner statement is keyed (and looked up) even where the block around it has none
    keys = Keys({}, memo)
    inner = call(x)
    assert keys.statement(ir.Block([inner, call(build.name("y", "local"))], True)) is UNKEYED
    assert id(inner) in keys.found


def test_a_main_that_fails_its_typing_leaves_nothing_in_the_memo_and_fails_again():
    """Bad input reaching the checker through main (an implementation whose function takes
    other arguments): the statement memo keeps only what was typed, so the same document fails
    the same way the second time rather than being served a half-typed main."""
    source = Path(DEFAULT_LIBRARY_ROOT) / "stdlib" / "genglsl" / "lib" / "mx_hsv.glsl"
    bad = doc('<nodedef name="ND_odd" node="odd"><input name="in" type="color3" value="1,1,1"/>'
              '<output name="out" type="float"/></nodedef>'
              f'<implementation name="IM_odd" nodedef="ND_odd" target="genglsl" file="{source}" function="mx_hsvtorgb"/>'
              '<odd name="o" type="float"/><output name="out" type="float" nodename="o"/>')
    gen = Generator(Library.load())
    memo = gen.library.code().statements
    errors = [records(gen, bad)[0]["error"] for _ in range(2)]
    assert errors[0]["code"] == "invalid_source" and "mx_hsvtorgb" in errors[0]["message"]
    assert errors[1] == errors[0] and not memo.entries
    assert records(gen, MARBLE) == records(Generator(Library.load()), MARBLE) and memo.entries


def test_a_surfaces_closure_calls_are_built_once_for_all_its_contexts():
    main = main_of(Generator(Library.load()), GOLDEN / "standard_surface_coated.mtlx")
    contexts = {}  # the context's closure data -> its statements after it, but for the one adding up
    for block in (n for n in ir.walk(main) if isinstance(n, ir.Block)):
        for i, s in enumerate(block.body):
            if isinstance(s, ir.Declare) and s.name == "closureData":
                contexts[s.init.args[0].name] = [id(c) for c in block.body[i + 1:-1]]
    # the BSDF's calls under each light, in the environment and along the view direction are one
    # list of statements; the EDF's, in the emission context, are its own
    reflection = contexts.pop("CLOSURE_TYPE_REFLECTION")
    assert reflection and reflection == contexts.pop("CLOSURE_TYPE_INDIRECT") == contexts.pop("CLOSURE_TYPE_TRANSMISSION")
    assert set(contexts.pop("CLOSURE_TYPE_EMISSION")).isdisjoint(reflection) and not contexts


def test_main_statements_built_from_alike_parts_are_taken_typed_and_not_built_again(monkeypatch):
    from shadergen.code.library import CodeLibrary
    made = []
    instance = CodeLibrary.instance

    def counted(self, expression_text, values, where="inline expression"):
        made.append(expression_text)
        return instance(self, expression_text, values, where)
    monkeypatch.setattr(CodeLibrary, "instance", counted)

    def scaled(factor: str):
        return doc('<texcoord name="t" type="vector2"/><multiply name="m" type="vector2">'
                   f'<input name="in1" type="vector2" nodename="t"/><input name="in2" type="float" value="{factor}"/>'
                   '</multiply><output name="o" type="vector2" nodename="m"/>')
    gen = Generator(Library.load())
    first = records(gen, scaled("2"), interface="specialized")
    assert made  # built, typed, remembered
    made.clear()
    assert records(gen, scaled("2"), interface="specialized") == first and not made  # taken, not built
    other = records(gen, scaled("3"), interface="specialized")  # another value in the source: built
    assert made and other == records(Generator(Library.load()), scaled("3"), interface="specialized")


def test_what_a_statement_is_built_from_has_one_key_and_any_difference_another():
    from shadergen.code.statements import alike_key
    x = build.name("x", "local", "vec3")
    assert alike_key(("call", "mx_f", x, build.number(1.0))) == \
        alike_key(("call", "mx_f", build.name("x", "local", "vec3"), build.number(1.0)))
    assert alike_key(("call", "mx_f", x, build.number(1.0))) != \
        alike_key(("call", "mx_f", x, ir.Literal(1, None, type="float")))  # 1.0 and 1 print apart
    assert alike_key(("call", "mx_f", x)) != alike_key(("call", "mx_f", build.name("x", "uniform", "vec3")))
    assert alike_key(("call", "mx_f", x)) != alike_key(("call", "mx_g", x))
    assert alike_key(("assign", "vec3", "a", x)) != alike_key(("assign", "vec3", "b", x))
    # typed by the scope, or built from other expressions: keyed (if at all) once built
    assert alike_key(("call", "mx_f", build.name("y", "local"))) is None
    assert alike_key(("assign", "vec3", "a", build.binary("*", x, x))) is None


def test_the_statements_of_a_function_main_calls_are_typed_once_for_each_shape():
    gen = Generator(Library.load())
    memo = gen.library.code().statements

    def light_dispatch(document):
        return next(f for f in code_of(gen, document).functions if getattr(f, "name", None) == "sampleLightSource")
    first = light_dispatch(GOLDEN / "standard_surface_coated.mtlx")
    again = light_dispatch(GOLDEN / "glass.mtlx")  # another material, the same lights
    assert again is not first  # the request's own function, with the statements typed before
    assert [id(s) for s in again.body.body] == [id(s) for s in first.body.body]
    assert all(id(s) in {id(e.statement) for e in memo.entries.values()} for s in again.body.body)


def test_an_inline_expression_naming_no_input_fails_each_time_it_is_asked_for():
    """Bad input on the path that takes statements built alike before (EmitContext.add_alike):
    the expression is made only where nothing alike was typed, and its error is the document's."""
    bad = doc('<nodedef name="ND_odd" node="odd"><input name="in" type="float" value="1"/>'
              '<output name="out" type="float"/></nodedef>'
              '<implementation name="IM_odd" nodedef="ND_odd" target="genglsl" sourcecode="{{nope}} * 2.0"/>'
              '<texcoord name="t" type="vector2"/><extract name="x" type="float">'
              '<input name="in" type="vector2" nodename="t"/></extract>'
              '<odd name="o" type="float"><input name="in" type="float" nodename="x"/></odd>'
              '<output name="out" type="float" nodename="o"/>')
    gen = Generator(Library.load())
    errors = [records(gen, bad)[0]["error"] for _ in range(2)]
    assert errors[0]["code"] == "invalid_implementation" and "nope" in errors[0]["message"]
    assert errors[1] == errors[0]
    assert records(gen, MARBLE) == records(Generator(Library.load()), MARBLE)


# -- the pixel stage's code and text, once per structure (code/stage.py) ------------------------------
def twin(value: str, uimin: str) -> str:
    """Documents of one structure: a colour, its value and its ui metadata their own."""
    return doc(f'<multiply name="m" type="color3"><input name="in1" type="color3" value="{value}"/>'
               f'<input name="in2" type="float" value="2" uimin="{uimin}"/></multiply>'
               '<output name="out" type="color3" nodename="m"/>')


TWINS = [twin("0.1, 0.2, 0.3", "0"), twin("0.4, 0.5, 0.6", "0.25")]


@pytest.mark.parametrize("target", ["glsl", "essl", "vulkan", "wgsl", "osl", "msl", "hlsl", "slang"])
def test_pixel_stages_from_the_memo_are_the_ones_written_afresh(target, monkeypatch):
    warm = Generator(Library.load())
    code = warm.library.code()
    documents = DOCUMENTS + TWINS
    for values in ("listing", "source"):
        first = [records(warm, document, target=target, values=values) for document in documents]
        assert code.stages  # kept the first time
        served = [records(warm, document, target=target, values=values) for document in documents]
        monkeypatch.setattr(code, "stages", Kept(0, 0))
        assert served == first == [records(warm, document, target=target, values=values) for document in documents]
        monkeypatch.undo()


@pytest.mark.parametrize(("target", "values"), [("glsl", "source"), ("osl", "listing")])
def test_the_pixel_stage_memo_tells_apart_what_an_assembler_reads_of_the_variables(target, values):
    """One structure, one main: GLSL initialises a uniform to the document's value (values in the
    source), OSL writes a parameter's ui metadata as its hints."""
    warm = Generator(Library.load())
    texts = [records(warm, twin_, target=target, values=values)[0]["stages"]["pixel"] for twin_ in TWINS]
    assert texts[0] != texts[1]
    assert texts == [records(Generator(Library.load()), twin_, target=target, values=values)[0]["stages"]["pixel"]
                     for twin_ in TWINS]


def test_a_structure_asked_for_again_runs_no_pass_and_prints_nothing(monkeypatch):
    gen = Generator(Library.load())
    first = records(gen, GOLDEN / "standard_surface_coated.mtlx")
    calls = []

    def counted(function):
        def call(*args):
            calls.append(function.__name__)
            return function(*args)
        return call
    for owner, name in ((code_stage.stage_passes, "run"), (glsl_target.GlslTarget, "assemble_pixel")):
        monkeypatch.setattr(owner, name, counted(getattr(owner, name)))
    assert records(gen, GOLDEN / "standard_surface_coated.mtlx") == first
    assert not calls
    glass = records(gen, GOLDEN / "glass.mtlx")  # another structure: the passes run, the stage is printed
    assert calls == ["run", "assemble_pixel"] and "error" not in glass[0]


def test_a_full_stage_memo_keeps_what_it_holds_and_takes_no_more():
    """A walk over more structures than the memo holds, again and again, still finds the first
    ones (a memo that let old entries go for new ones would find none)."""
    kept = Kept(3, 10)
    for round_ in range(2):
        for n in range(6):
            kept.keep(n, str(n) * 2, 2)
    assert [kept.get(n) for n in range(6)] == ["00", "11", "22", None, None, None]
    kept = Kept(3, 5)
    kept.keep("a", "aaaa", 4)
    kept.keep("b", "bb", 2)  # past the size: not taken
    kept.keep("c", "c", 1)
    assert (kept.get("a"), kept.get("b"), kept.get("c"), len(kept)) == ("aaaa", None, "c", 2)
