"""The passes on the IR (shadergen/code/passes/) and the facts they read (shadergen/code/facts.py):
the cases of the text passes' tests (test_deadcode, test_deadfields, test_forwarding,
test_features, test_source_scans), on hand-built typed IR."""
from shadergen.code import ir
from shadergen.code.facts import (collect, early_exit_at_zero_weight, facts, prepared_state, reads_constant,
                                  uses_derivatives)
from shadergen.code.passes import fields, forward, reach, sections
from shadergen.code.passes import stage as stage_passes


# -- building typed IR by hand ---------------------------------------------------------------------
def fn(returns, name, params, *body):
    """A function; params: "type name", "out type name" or "inout type name" each."""
    made = []
    for p in params:
        words = p.split()
        qualifier = words[0] if len(words) == 3 else "in"
        made.append(ir.Param(qualifier, words[-2], words[-1], False))
    return ir.Function(returns, name, made, ir.Block(list(body), True))


def local(name, type_name):
    return ir.Name(name, "local", type=type_name)


def param(name, type_name):
    return ir.Name(name, "param", type=type_name)


def const(name, type_name="int"):
    return ir.Name(name, "global", type=type_name)


def lit(value, type_name="float"):
    return ir.Literal(value, str(value), type=type_name)


def call(function, *args):
    return ir.Call(function.name, list(args), type=function.returns, callee=function)


def builtin(name, type_name, *args):
    return ir.Call(name, list(args), type=type_name, builtin=True)


def member(base, name, type_name):
    return ir.Field(base, name, type=type_name)


def store(target, value, op="="):
    return ir.Assign(op, target, value)


def do(expr):
    return ir.ExprStatement(expr)


def ret(value=None):
    return ir.Return(value)


def brace_less(*body):
    return ir.Block(list(body), False)


def braced(*body):
    return ir.Block(list(body), True)


def calls_of(item) -> list[str]:
    return [n.name for n in ir.walk(item) if isinstance(n, ir.Call)]


# -- facts -----------------------------------------------------------------------------------------
TWICE = fn("float", "twice", ["float x"], ret(ir.Binary("*", lit(2.0), param("x", "float"), type="float")))
ITERATIONS = ir.Constant("int", "ITERATIONS", lit(2, "int"))
DEFAULT_ITERATIONS = ir.Section("ITERATIONS", False, [ITERATIONS], None)  # #ifndef X / #define X 2 / #endif
REPEATED = fn("float", "repeated", ["float x"],
              ir.Declare("float", "y", param("x", "float"), False),
              ir.For(ir.Declare("int", "i", lit(0, "int"), False),
                     ir.Binary("<", local("i", "int"), const("ITERATIONS"), type="bool"),
                     store(local("i", "int"), None, "++"),
                     brace_less(store(local("y", "float"), call(TWICE, local("y", "float"))))),
              ret(local("y", "float")))
SQUARE = fn("float", "square", ["float x"], ret(ir.Binary("*", param("x", "float"), param("x", "float"), type="float")))


def test_a_functions_facts_name_what_it_calls_and_reads():
    f = facts(REPEATED)
    assert f.calls == ("twice(float)",) and f.callees == (TWICE,)
    assert f.names == ("ITERATIONS",) and f.builtins == frozenset() and f.types == ()
    assert not f.writes_params and f.forwards is None and facts(REPEATED) is f  # memoised on the item


def test_derivatives_are_read_through_callees_and_explicit_lods_take_none():
    uv = param("uv", "vec2")
    lookup = fn("vec4", "lookup", ["sampler2D tex", "vec2 uv"],
                ret(builtin("texture", "vec4", param("tex", "sampler2D"), uv)))
    explicit = fn("vec4", "explicit", ["sampler2D tex", "vec2 uv"],
                  ret(builtin("textureLod", "vec4", param("tex", "sampler2D"), uv, lit(0.0))))
    caller = fn("vec4", "caller", ["sampler2D tex", "vec2 uv"], ret(call(lookup, param("tex", "sampler2D"), uv)))
    width = fn("float", "width", ["float x"], ret(builtin("fwidth", "float", param("x", "float"))))
    assert uses_derivatives(caller) and uses_derivatives(width) and not uses_derivatives(explicit)
    assert not uses_derivatives(TWICE)


def test_reading_a_constant_is_read_through_callees():
    context = fn("bool", "is_transmission", ["int c"],
                 ret(ir.Binary("==", param("c", "int"), const("CLOSURE_TYPE_TRANSMISSION"), type="bool")))
    lobe = fn("void", "lobe", ["int c"], do(call(context, param("c", "int"))))
    assert reads_constant(lobe, "CLOSURE_TYPE_TRANSMISSION") and not reads_constant(lobe, "CLOSURE_TYPE_INDIRECT")


def zero_weight_lobe(*body):
    return fn("void", "f", ["ClosureData c", "float weight", "inout BSDF bsdf"], *body)


BSDF_ = param("bsdf", "BSDF")
THROUGHPUT = store(member(BSDF_, "throughput", "vec3"), ir.Construct("vec3", [lit(0.5)]))
SMALL_WEIGHT = ir.Binary("<", param("weight", "float"), const("MX_EPS", "float"), type="bool")


def test_a_lobe_returning_under_its_weight_before_writing_throughput_is_empty_at_zero_weight():
    assert early_exit_at_zero_weight(zero_weight_lobe(ir.If(SMALL_WEIGHT, brace_less(ret()), None), THROUGHPUT))
    assert not early_exit_at_zero_weight(zero_weight_lobe(THROUGHPUT, ir.If(SMALL_WEIGHT, brace_less(ret()), None)))
    # another condition first: still the closure's zero where the weight's return comes before any write
    other = ir.If(ir.Binary("!=", member(param("c", "ClosureData"), "closureType", "int"), lit(1, "int"), type="bool"),
                  brace_less(ret()), None)
    assert early_exit_at_zero_weight(zero_weight_lobe(other, ir.If(SMALL_WEIGHT, brace_less(ret()), None), THROUGHPUT))
    assert not early_exit_at_zero_weight(zero_weight_lobe(other, THROUGHPUT))  # no return reads the weight
    # `lobe.weight` of a prepared state counts; a local named weight does not
    lobe = fn("void", "g", ["ClosureData c", "SpecularLobe lobe", "inout BSDF bsdf"],
              ir.If(ir.Binary("==", member(param("lobe", "SpecularLobe"), "weight", "float"), lit(0.0), type="bool"),
                    brace_less(ret()), None), THROUGHPUT)
    assert early_exit_at_zero_weight(lobe)
    shadowed = fn("void", "h", ["ClosureData c", "inout BSDF bsdf"], ir.Declare("float", "weight", lit(0.0), False),
                  ir.If(ir.Binary("<", local("weight", "float"), lit(1.0), type="bool"), brace_less(ret()), None))
    assert not early_exit_at_zero_weight(shadowed)


def test_writing_the_closure_through_a_call_counts_as_writing_its_throughput():
    setter = fn("void", "opaque", ["inout BSDF b"], store(member(param("b", "BSDF"), "throughput", "vec3"),
                                                         ir.Construct("vec3", [lit(0.0)])))
    lobe = zero_weight_lobe(do(call(setter, BSDF_)), ir.If(SMALL_WEIGHT, brace_less(ret()), None))
    assert not early_exit_at_zero_weight(lobe)


class Library:
    """What prepared_state asks of a code library: a name's definitions, in library order."""

    def __init__(self, *functions):
        self.by_name = {}
        for f in functions:
            self.by_name.setdefault(f.name, []).append(f)

    def functions(self, name):
        return self.by_name.get(name, [])


def test_a_lobes_prepared_state_is_the_type_its_first_prepare_function_writes():
    lobe, other, flat = fn("void", "mx_lobe", [], ), fn("void", "mx_other", []), fn("void", "mx_flat", [])
    library = Library(fn("void", "mx_other_prepare", ["float a", "out OtherLobe lobe"]),
                      fn("void", "mx_lobe_prepare", ["ClosureData c", "float weight", "out LobeState state"]),
                      fn("void", "mx_lobe_prepare", ["float later", "out Ignored state"]),
                      fn("void", "notmx_flat_prepare", ["float a", "out FlatState s"]),
                      fn("void", "mx_flat_prepare", ["float a"]))
    assert prepared_state(lobe, library) == "LobeState" and prepared_state(other, library) == "OtherLobe"
    assert prepared_state(flat, library) is None  # writes no state
    assert prepared_state(fn("void", "flat", []), library) is None  # `notmx_flat_prepare` is another name
    assert prepared_state(fn("void", "mx_missing", []), library) is None


# -- sections --------------------------------------------------------------------------------------
def stub(name):
    return do(builtin(name, "void"))


SECTIONED = fn("float", "f", [],
               ir.Section("MX_FEATURE_A", True,
                          [stub("a"), ir.Section("MX_ENV_PREFILTER", True, [stub("prefiltered")], [stub("sampled")])],
                          [stub("notA")]),
               ir.Section("MX_FEATURE_B", False, [stub("notB")], None),
               ret(lit(0.0)))


def test_a_needed_section_stays_without_its_directives_and_the_compilers_own_conditionals_stay():
    (out,), count = sections.run([SECTIONED], frozenset({"A", "B"}))
    assert count == 2
    body = out.body.body
    assert calls_of(body[0]) == ["a"] and isinstance(body[1], ir.Section) and body[1].macro == "MX_ENV_PREFILTER"
    assert len(body) == 3 and isinstance(body[2], ir.Return)


def test_a_section_no_node_needs_is_dropped_with_what_it_holds_and_its_else_side_stays():
    (out,), _ = sections.run([SECTIONED], frozenset())
    assert calls_of(out) == ["notA", "notB"]
    assert not any(isinstance(n, ir.Section) for n in ir.walk(out))


def test_an_unasked_stage_keeps_every_section():
    (out,), _ = sections.run([SECTIONED], None)
    assert calls_of(out) == ["a", "prefiltered", "sampled"]


def test_decided_macros_resolve_like_features_and_results_are_shared():
    (fis,), _ = sections.run([SECTIONED], frozenset({"A"}), frozenset({("MX_ENV_PREFILTER", False)}))
    (prefilter,), _ = sections.run([SECTIONED], frozenset({"A"}), frozenset({("MX_ENV_PREFILTER", True)}))
    assert calls_of(fis) == ["a", "sampled", "notB"] and calls_of(prefilter) == ["a", "prefiltered", "notB"]
    (again,), _ = sections.run([SECTIONED], frozenset({"A", "C"}), frozenset({("MX_ENV_PREFILTER", False),
                                                                             ("MX_ENV_HYBRID", True)}))
    assert again is fis  # the same decisions of the macros it mentions: the same resolved item
    untouched = [TWICE]
    assert sections.run(untouched, frozenset())[0][0] is TWICE


def test_a_section_holding_an_else_becomes_the_ifs_else_or_else_if_or_none():
    chain = ir.If(param("x", "bool"), braced(stub("first")),
                  brace_less(ir.Section("MX_FEATURE_T", True,
                                        [ir.If(param("y", "bool"), braced(stub("second")), None)], None)))
    top = ir.Section("MX_ENV_HYBRID", True, [fn("void", "hybrid", [], chain)], None)
    (kept,), _ = sections.run([top], frozenset({"T"}))
    inner = kept.body[0].body.body[0]
    assert isinstance(inner.other, ir.Block) and isinstance(inner.other.body[0], ir.If)
    (none,), _ = sections.run([top], frozenset())
    assert none.body[0].body.body[0].other is None  # the macro left alone: still a top-level Section
    otherwise = ir.If(param("x", "bool"), braced(stub("first")),
                      brace_less(ir.Section("MX_FEATURE_T", True, [braced(stub("second"))], None)))
    (out,), _ = sections.run([fn("void", "g", [], otherwise)], frozenset({"T"}))
    assert out.body.body[0].other.scoped and calls_of(out.body.body[0].other) == ["second"]


def test_an_if_a_section_empties_goes_when_its_condition_calls_nothing():
    emptied = fn("void", "g", [], ir.If(param("x", "bool"), braced(ir.Section("MX_FEATURE_T", True, [stub("t")], None)),
                                       None), stub("after"))
    (out,), _ = sections.run([emptied], frozenset())
    assert calls_of(out) == ["after"]


# -- reach -----------------------------------------------------------------------------------------
LIBRARY = [TWICE, SQUARE, DEFAULT_ITERATIONS, REPEATED]


def test_only_what_the_roots_reach_is_kept_in_library_order():
    reached, count = reach.run(LIBRARY, [do(call(TWICE, lit(1.0)))])
    assert reached.items == [TWICE] and count == 3 and reached.functions == ("twice(float)",)


def test_a_default_definition_is_kept_whole_only_where_its_name_is_used():
    reached, count = reach.run(LIBRARY, [do(call(REPEATED, lit(1.0)))])
    assert reached.items == [TWICE, DEFAULT_ITERATIONS, REPEATED] and count == 1
    assert reached.constants == ("ITERATIONS",)


def test_a_definition_comes_before_its_use_and_root_names_keep_items():
    lobe = ir.Struct("Lobe", [("float", "weight")])
    make = fn("Lobe", "make", [], ir.Declare("Lobe", "l", None, False), ret(local("l", "Lobe")))
    reached, _ = reach.run([make, SQUARE, lobe], [do(call(make))], names=["square"])
    assert reached.items == [lobe, make, SQUARE] and reached.structs == ("Lobe",)


def test_uniforms_and_names_read_are_reported():
    shade = fn("vec3", "shade", [], ret(ir.Name("u_envMatrix", "uniform", type="mat4")))
    root = [do(call(shade)), do(ir.Name("vd_uv", "vertexdata", type="vec2"))]
    reached, _ = reach.run([shade], root)
    assert reached.uniforms == {"u_envMatrix"} and reached.names == {"u_envMatrix", "vd_uv"}


# -- fields ----------------------------------------------------------------------------------------
LOBE = ir.Struct("Lobe", [("float", "weight"), ("vec3", "frame"), ("vec3", "tilted"), ("vec3", "spare"),
                          ("bool", "flag")])
L = local("lobe", "Lobe")
FILL = fn("void", "fill", ["out vec3 v"], store(param("v", "vec3"), ir.Construct("vec3", [lit(1.0)])))
TILT = fn("vec3", "tilt", ["vec3 v"], ret(ir.Field(param("v", "vec3"), "zyx", type="vec3", swizzle=True)))
W = param("w", "float")


def prepare(*extra):
    return fn("Lobe", "prepare", ["float w"],
              ir.Declare("Lobe", "lobe", None, False),
              store(member(L, "weight", "float"), W),
              store(member(L, "frame", "vec3"), ir.Construct("vec3", [W])),
              store(member(L, "tilted", "vec3"), call(TILT, member(L, "frame", "vec3"))),
              store(ir.Field(member(L, "tilted", "vec3"), "z", type="float", swizzle=True),
                    builtin("max", "float", ir.Field(member(L, "tilted", "vec3"), "z", type="float", swizzle=True),
                            lit(0.0))),
              store(member(L, "spare", "vec3"), ir.Construct("vec3", [lit(0.0)])),
              ir.If(ir.Binary(">", W, lit(0.5), type="bool"), brace_less(store(member(L, "flag", "bool"),
                                                                               lit(True, "bool"))), None),
              *extra,
              ret(L))


def reduced(items, roots):
    """What the stage's passes keep (code/passes/stage.py: reach, then fields and forward, until
    nothing changes)."""
    return stage_passes.run(items, None, frozenset(), roots)[0].items


def test_members_only_stored_go_with_their_stores_and_what_only_they_called():
    lobe_fn = prepare()
    roots = [ir.Declare("Lobe", "l", call(lobe_fn, lit(1.0)), False),
             ir.Declare("float", "x", member(local("l", "Lobe"), "weight", "float"), False)]
    items = reduced([LOBE, TILT, lobe_fn], roots)
    struct, function = items
    assert [m for _, m in struct.members] == ["weight"]
    assert [type(s).__name__ for s in function.body.body] == ["Declare", "Assign", "Return"]
    assert TILT not in items  # only a dead member's store called it
    counted = fields.run([LOBE, TILT, lobe_fn], roots)[1]
    assert counted == 4 + 5  # frame, tilted, spare, flag; their five stores (the flag's under its if)


def test_the_stage_counts_each_pass():
    lobe_fn = prepare()
    roots = [ir.Declare("Lobe", "l", call(lobe_fn, lit(1.0)), False),
             ir.Declare("float", "x", member(local("l", "Lobe"), "weight", "float"), False)]
    reached, counts = stage_passes.run([SECTIONED, LOBE, TILT, lobe_fn, SAMPLES, REFLECTED], frozenset(), frozenset(),
                                       roots)
    assert counts == {"sections": 2, "reach": 3 + 1, "fields": 9, "forward": 0}  # f, samples, reflected; tilt
    assert [type(i).__name__ for i in reached.items] == ["Struct", "Function"]


def test_a_member_the_roots_read_stays():
    lobe_fn = prepare()
    roots = [ir.Declare("Lobe", "l", call(lobe_fn, lit(1.0)), False),
             ir.Declare("vec3", "t", member(local("l", "Lobe"), "tilted", "vec3"), False)]
    struct, tilt, function = reduced([LOBE, TILT, lobe_fn], roots)
    assert [m for _, m in struct.members] == ["frame", "tilted"] and tilt is TILT  # nothing reads the weight
    assert "spare" not in {n.name for n in ir.walk(function) if isinstance(n, ir.Field)}


def test_a_store_that_calls_an_out_function_keeps_its_member():
    fill2 = fn("vec3", "fill2", ["inout vec3 v"], ret(param("v", "vec3")))
    lobe_fn = prepare(store(member(L, "tilted", "vec3"), call(fill2, member(L, "spare", "vec3"))))
    roots = [ir.Declare("Lobe", "l", call(lobe_fn, lit(1.0)), False),
             ir.Declare("float", "x", member(local("l", "Lobe"), "weight", "float"), False)]
    struct = reduced([LOBE, TILT, fill2, lobe_fn], roots)[0]
    assert {"spare", "tilted"} <= {m for _, m in struct.members}


def test_a_store_calling_a_function_that_writes_only_its_own_locals_goes():
    fill2 = fn("vec3", "fill2", ["inout vec3 v"], ret(param("v", "vec3")))
    pure = fn("vec3", "pure", ["vec3 v"], ir.Declare("vec3", "t", param("v", "vec3"), False),
              do(call(fill2, local("t", "vec3"))), ret(local("t", "vec3")))
    lobe_fn = prepare(store(member(L, "tilted", "vec3"), call(pure, member(L, "spare", "vec3"))))
    roots = [ir.Declare("Lobe", "l", call(lobe_fn, lit(1.0)), False),
             ir.Declare("float", "x", member(local("l", "Lobe"), "weight", "float"), False)]
    struct = reduced([LOBE, TILT, fill2, pure, lobe_fn], roots)[0]
    assert [m for _, m in struct.members] == ["weight"]


def test_a_struct_built_by_its_constructor_or_a_globals_type_keeps_every_member():
    pair = ir.Struct("Pair", [("float", "a"), ("float", "b")])
    roots = [ir.Declare("Pair", "p", ir.Construct("Pair", [lit(1.0), lit(2.0)]), False),
             ir.Declare("float", "x", member(local("p", "Pair"), "a", "float"), False)]
    assert fields.run([pair], roots) == ([pair], 0)
    light = ir.Struct("LightData", [("int", "type"), ("float", "decay_rate")])
    uniform = ir.Global("LightData[MAX_LIGHT_SOURCES]", "u_lightData", "uniform")
    assert fields.run([light, uniform], []) == ([light, uniform], 0)
    read = [ir.Declare("int", "t", member(ir.Index(ir.Name("u_lightData", "uniform", type="LightData[3]"), lit(0, "int"),
                                                   type="LightData"), "type", "int"), False)]
    assert fields.run([light], read) == ([light], 0)  # a uniform the generator declares: its layout stays


def test_a_struct_keeps_its_first_member_and_what_storing_it_reads():
    pair = ir.Struct("Pair", [("float", "a"), ("float", "b")])
    p = local("p", "Pair")
    make = fn("Pair", "make", [], ir.Declare("Pair", "p", None, False),
              store(member(p, "b", "float"), lit(1.0)), store(member(p, "a", "float"), member(p, "b", "float")),
              ret(p))
    (struct, function), count = fields.run([pair, make], [do(call(make))])
    assert struct.members == [("float", "a")] or [m for _, m in struct.members] == ["a", "b"]
    assert [m for _, m in struct.members] == ["a", "b"] and count == 0  # a stays, and it reads b


# -- forward ---------------------------------------------------------------------------------------
N = param("N", "vec3")
ALBEDO = param("albedo", "vec3")
SAMPLES = fn("float", "samples", ["vec3 N", "bool film", "out vec3 albedo"], store(ALBEDO, N),
             ret(ir.Select(param("film", "bool"), lit(1.0), lit(0.0), type="float")))
REFLECTED = fn("float", "reflected", ["vec3 N", "out vec3 albedo"], ret(call(SAMPLES, N, lit(False, "bool"), ALBEDO)))
SWAPPED = fn("float", "swapped", ["bool film", "vec3 N", "out vec3 albedo"],
             ret(call(SAMPLES, N, param("film", "bool"), ALBEDO)))
A = local("a", "vec3")


def lobe_calling(reflected):
    return fn("float", "lobe", ["vec3 N"], ir.Declare("vec3", "a", None, False),
              ir.Declare("float", "r", call(reflected, builtin("normalize", "vec3", N), A), False),
              ret(ir.Binary("+", local("r", "float"), call(SWAPPED, lit(True, "bool"), N, A), type="float")))


def test_callers_call_the_target_and_the_forward_goes():
    lobe = lobe_calling(REFLECTED)
    items, count = forward.run([SAMPLES, REFLECTED, SWAPPED, lobe], [do(call(lobe, N))])
    assert count == 1 and REFLECTED not in items and len(items) == 3
    redirected = items[-1].body.body[1].init
    assert redirected.callee is SAMPLES and [type(a).__name__ for a in redirected.args] == ["Call", "Literal", "Name"]
    assert redirected.args[1].value is False and redirected.args[2].name == "a"
    assert facts(REFLECTED).forwards[0] is SAMPLES and facts(SWAPPED).forwards is None  # reorders: stays


def test_a_forward_main_calls_stays():
    lobe = lobe_calling(REFLECTED)
    items, count = forward.run([SAMPLES, REFLECTED, SWAPPED, lobe], [do(call(REFLECTED, N, A)), do(call(lobe, N))])
    assert count == 0 and REFLECTED in items


def test_a_forward_with_another_type_or_qualifier_stays():
    inout = fn("float", "reflected", ["vec3 N", "inout vec3 albedo"], ret(call(SAMPLES, N, lit(False, "bool"), ALBEDO)))
    assert facts(inout).forwards is None
    twice = fn("float", "twice", ["float x"], ret(call(SAMPLES, param("x", "float"), lit(False, "bool"), ALBEDO)))
    assert facts(twice).forwards is None


def test_a_target_with_two_definitions_keeps_its_forwards():
    other = fn("float", "samples", ["vec2 N", "bool film", "out vec3 albedo"], ret(lit(0.0)))
    lobe = lobe_calling(REFLECTED)
    assert forward.run([SAMPLES, other, REFLECTED, lobe], [do(call(lobe, N))])[1] == 0


def test_a_forward_with_a_twin_in_a_sections_other_side_stays():
    twin = fn("float", "reflected", ["vec3 N", "out vec3 albedo"], ret(lit(1.0)))
    lobe = lobe_calling(REFLECTED)
    section = ir.Section("MX_ENV_HYBRID", True, [REFLECTED], [twin])
    assert forward.run([SAMPLES, section, lobe], [do(call(lobe, N))]) == ([SAMPLES, section, lobe], 0)


def test_chains_of_forwards_reach_the_last_target():
    outer = fn("float", "outer", ["vec3 N", "out vec3 albedo"], ret(call(REFLECTED, N, ALBEDO)))
    user = fn("float", "user", ["vec3 N"], ir.Declare("vec3", "a", None, False), ret(call(outer, N, A)))
    items, count = forward.run([SAMPLES, REFLECTED, outer, user], [do(call(user, N))])
    assert items[0] is SAMPLES and len(items) == 2 and items[1].body.body[1].value.callee is SAMPLES and count == 2
    assert collect([items[1]]).calls == ("samples(vec3,bool,vec3)",)


# -- on the library's own IR -----------------------------------------------------------------------
# The text passes and scans of today are the reference: the IR passes keep no more than they do,
# and read the same facts of every lobe (test_source_scans, test_passes).
import os  # noqa: E402
import re  # noqa: E402

import pytest  # noqa: E402

from shadergen.code.check import flat_items  # noqa: E402
from shadergen.code.types import ir_type  # noqa: E402
from shadergen.code.externals import environment_macros  # noqa: E402
from shadergen.library import default_library  # noqa: E402
from shadergen.nodes.base import SourceFunctionImpl, implementation_for  # noqa: E402

CLOSURE_TYPES = {"BSDF", "EDF", "VDF"}


def function_of(code, impl):
    return next(i for i in flat_items(code.module(impl.path).items)
                if isinstance(i, ir.Function) and i.name == impl.function)


def items_of(code, impl) -> list:
    """The items of an implementation's files, its includes first (the generator's order)."""
    return [item for path in impl.files for item in code.module(path).items]


def source_implementations():
    """(nodedef, SourceFunctionImpl) of every library function implementation, each once."""
    library = default_library()
    found, seen = [], set()
    for nodedef_name, elements in sorted(library.implementations.items()):
        for e in elements:
            if e.category != "implementation" or not e.get("file") or e.get("sourcecode") is not None:
                continue
            impl = implementation_for(e, library)
            if isinstance(impl, SourceFunctionImpl) and (impl.path, impl.function) not in seen:
                seen.add((impl.path, impl.function))
                found.append((library.nodedefs.get(nodedef_name), impl))
    return found


def lobes():
    return [(nodedef, impl) for nodedef, impl in source_implementations()
            if {o.get("type") for o in nodedef.children_of("output")} & CLOSURE_TYPES]


# What the IR says of the library's lobes and functions; when these passes replaced the text scans
# (targets/glsl.py ClosureConvention, nodes/base.py takes_derivatives), both agreed on every lobe
# and implementation but one (the text scan credited mx_layer_vdf with its file's mx_layer_bsdf).
PREPARED = {"mx_conductor_bsdf": "SpecularLobe", "mx_dielectric_bsdf": "SpecularLobe",
            "mx_generalized_schlick_bsdf": "SpecularLobe"}
TRANSMITTING = {"mx_absorption_vdf", "mx_anisotropic_vdf", "mx_dielectric_bsdf", "mx_generalized_schlick_bsdf"}
DERIVATIVE_FAMILIES = ("mx_heighttonormal", "mx_hextiled", "mx_image_", "mx_latlongimage", "mx_split",
                       "mx_subsurface_bsdf", "mx_triplanarprojection")


def test_the_lobes_zero_weight_exits_and_prepared_states(code):
    checked = 0
    for _, impl in lobes():
        function = function_of(code, impl)
        assert prepared_state(function, code) == PREPARED.get(impl.function), impl.function
        assert impl.prepared_state == PREPARED.get(impl.function) and impl.empty_at_zero_weight == \
            early_exit_at_zero_weight(function), impl.function
        checked += 1
    assert checked >= 25
    early = {impl.function for _, impl in lobes() if early_exit_at_zero_weight(function_of(code, impl))}
    assert early == {"mx_dielectric_bsdf", "mx_generalized_schlick_bsdf", "mx_sheen_bsdf"}


def test_the_lobes_answering_the_transmission_context(code):
    """The closure pass asks it of lobes only (an operator passes on what its lobes answer)."""
    for nodedef, impl in lobes():
        if any(i.get("type") in CLOSURE_TYPES for i in nodedef.children_of("input")):
            continue
        answers = reads_constant(function_of(code, impl), "CLOSURE_TYPE_TRANSMISSION")
        assert answers == (impl.function in TRANSMITTING) == impl.handles_transmission, impl.function


def test_derivative_use_of_every_function_implementation(code):
    implementations = source_implementations()
    for _, impl in implementations:
        expected = impl.function.startswith(DERIVATIVE_FAMILIES)
        assert uses_derivatives(function_of(code, impl)) == expected == impl.uses_derivatives, impl.function
    assert len(implementations) > 100


def stage(code, impl, features, environment):
    """What a stage of the implementation alone keeps: calls of it (and its _prepare) its roots."""
    called = {impl.function, impl.function + "_prepare"}
    roots = [do(ir.Call(i.name, [], callee=i)) for i in flat_items(code.module(impl.files[-1]).items)
             if isinstance(i, ir.Function) and i.name in called]
    reached, _ = stage_passes.run(items_of(code, impl), features, environment_macros(environment), roots)
    return [i for unit in reached.items for i in flat_items([unit])]


def names(items) -> set[str]:
    return {i.name for i in items}


SETTINGS = [(frozenset(), "fis"), (frozenset({"LIGHTS", "THIN_FILM", "TRANSMISSION", "REFRACTION"}), "prefilter"),
            (None, None)]


@pytest.mark.parametrize("features, environment", SETTINGS)
def test_every_implementations_stage_keeps_its_function_and_only_the_overloads_called(code, features, environment):
    """Reach keeps what is called, by key: of an overloaded name only the overloads called."""
    for _, impl in source_implementations():
        kept = stage(code, impl, features, environment)
        assert impl.function in names(kept), impl.function
        called = {key for f in kept if isinstance(f, ir.Function) for key in facts(f).calls}
        roots = {f.key for f in kept if isinstance(f, ir.Function) and f.name in (impl.function, impl.function + "_prepare")}
        assert {f.key for f in kept if isinstance(f, ir.Function)} <= called | roots, impl.function


def lobe_stage(code, function, features, environment=None):
    impl = next(impl for _, impl in lobes() if impl.function == function)
    return stage(code, impl, features, environment)


def test_a_film_of_thickness_0_leaves_the_thin_film_out_and_the_film_brings_it(code):
    plain = names(lobe_stage(code, "mx_dielectric_bsdf", frozenset({"FRESNEL_DIELECTRIC"})))
    assert "mx_fresnel_airy" not in plain and "mx_fresnel_dielectric" in plain
    assert "mx_refraction_solid_sphere" not in plain and "MX_ALBEDO_DIELECTRIC_LEAVING" not in plain
    film = names(lobe_stage(code, "mx_dielectric_bsdf", frozenset({"FRESNEL_DIELECTRIC", "THIN_FILM"})))
    assert "mx_fresnel_airy" in film


def test_lights_and_transmission_bring_their_contexts_code(code):
    unlit = names(lobe_stage(code, "mx_dielectric_bsdf", frozenset()))
    lit_ = names(lobe_stage(code, "mx_dielectric_bsdf", frozenset({"LIGHTS"})))
    clear = names(lobe_stage(code, "mx_dielectric_bsdf", frozenset({"TRANSMISSION", "REFRACTION"})))
    assert "mx_specular_reflection" not in unlit and "mx_specular_reflection" in lit_
    assert "mx_specular_transmission_albedo" not in unlit | lit_ and "mx_specular_transmission_albedo" in clear
    assert "mx_surface_transmission" in clear


def test_an_environment_method_resolves_the_compilers_own_conditional(code):
    def sections_left(items):
        return {n.macro for i in items for n in ir.walk(i) if isinstance(n, ir.Section)}

    both = lobe_stage(code, "mx_conductor_bsdf", frozenset())
    fis = lobe_stage(code, "mx_conductor_bsdf", frozenset(), "fis")
    prefilter = lobe_stage(code, "mx_conductor_bsdf", frozenset(), "prefilter")
    hybrid = lobe_stage(code, "mx_conductor_bsdf", frozenset(), "hybrid")
    assert "MX_ENV_PREFILTER" in sections_left(both) and not sections_left(fis + prefilter + hybrid)
    assert "mx_ggx_sample_visible_normal" in names(fis) and "MX_DFG_C1" not in names(fis)
    assert "MX_DFG_C1" in names(prefilter) and "mx_ggx_sample_visible_normal" not in names(prefilter)
    assert "mx_environment_corrected_radiance" in names(hybrid)
    assert "mx_environment_corrected_radiance" not in names(prefilter) | names(fis)


def test_the_librarys_forwarders_are_called_straight(code):
    fresnel = lobe_stage(code, "mx_dielectric_bsdf", frozenset({"FRESNEL_DIELECTRIC"}), "fis")
    assert "mx_fresnel_eval_film" in names(fresnel) and "mx_fresnel_eval" not in names(fresnel)
    reflected = lobe_stage(code, "mx_conductor_bsdf", frozenset(), "fis")
    assert "mx_environment_samples" in names(reflected) and "mx_environment_reflected" not in names(reflected)
    assert "mx_environment_reflected" in names(lobe_stage(code, "mx_conductor_bsdf", frozenset({"THIN_FILM"}), "fis"))


# test_features' own source (its pragma at the top, where the libraries have theirs), parsed
# (untyped: the sections pass needs no types)
FEATURE_SOURCE = """#pragma shadergen feature A unless x == 0
float f()
{
#ifdef MX_FEATURE_A
    a();
#ifdef MX_ENV_PREFILTER
    prefiltered();
#else
    sampled();
#endif
#else
    notA();
#endif
#ifndef MX_FEATURE_B
    notB();
#endif
    return 0.0;
}
"""


def test_the_text_tests_sections_resolve_alike_on_the_parsed_source():
    from shadergen.code.parse import parse_module
    module = parse_module("f.glsl", FEATURE_SOURCE)
    assert module.features == (("A", "x", "==", "0"),)  # the pragma is the module's, not code
    (both,), _ = sections.run(module.items, frozenset({"A", "B"}))
    assert calls_of(both) == ["a", "prefiltered", "sampled"]
    assert [n.macro for n in ir.walk(both) if isinstance(n, ir.Section)] == ["MX_ENV_PREFILTER"]
    assert calls_of(sections.run(module.items, frozenset())[0][0]) == ["notA", "notB"]
    assert calls_of(sections.run(module.items, None)[0][0]) == ["a", "prefiltered", "sampled"]


def test_elif_in_a_section_is_refused_before_any_pass():
    from shadergen.code.parse import parse_module
    from shadergen.errors import ShaderGenError
    with pytest.raises(ShaderGenError) as error:
        parse_module("f.glsl", "float f()\n{\n#ifdef MX_FEATURE_A\n    a();\n#elif X\n#endif\n    return 0.0;\n}\n")
    assert error.value.code == "invalid_source" and "f.glsl:5:1" in str(error.value)


def test_a_copy_of_an_item_reads_its_own_facts_even_from_a_cache_without_them():
    import pickle
    f = fn("float", "g", [], ret(call(TWICE, lit(1.0))))
    assert facts(f).calls == ("twice(float)",) and f.facts is not None
    copy = ir.replace(f, body=ir.Block([ret(lit(0.0))], True))
    assert copy.facts is None and facts(copy).calls == () and facts(f).calls == ("twice(float)",)
    old = pickle.loads(pickle.dumps(fn("float", "h", [], ret(lit(1.0)))))
    del old.facts  # as an item of a library cache written before Item had its facts
    assert facts(ir.replace(old, name="h2")).calls == () and facts(old).calls == ()
