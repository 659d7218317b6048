"""A shader's code from what the generator asked for to what the targets print: the generated code
typed with the library's (code/check.py), then the code passes, named and counted in the
record's `"passes"`:

- `sections`: the library's feature sections resolved for the shader's features and decided
  compiler macros (passes/sections.py);
- `forward`: calls through forwarding functions made to their targets (passes/forward.py);
- `reach`: only the functions, structs, constants and uniforms main reaches (passes/reach.py);
- `fields`: struct members nothing reads, with the statements that only store them
  (passes/fields.py).

(passes/stage.py runs them, reach again after fields and forward until nothing changes.) The
result, a StageCode, is what every target's stage assembler prints: one mechanism for all. A
library function a target writes its own way (its `own_functions`: OSL's image read) enters the
passes without its body, so what only the library's body calls is not reached.

Materials of one structure (and every request for one material) build one main: where main has
a structure (code/statements.py: it is numbered), the passes' result for it is kept per library, by that number and everything else the passes read (`run`), and so is the
stage's text, by that and what an assembler reads of the stage's variables (`pixel_stage`).
"""
from functools import lru_cache

from ..shader import PIXEL, VERTEX
from . import build, ir
from .kept import Kept
from .library import MAX_STAGE_TEXT, MAX_STAGES, PRELUDE  # (PRELUDE: the closure, shader and light structs)
from .passes import stage as stage_passes
from .types import ir_type



class StageCode:
    """What the passes kept of the pixel stage, in order: `structs`, `constants` (with the
    sections of macros left to the target that hold no function), `functions` (and the sections
    that do), then main, the vertex stage's main, and every name the pixel code reads."""
    __slots__ = ("structs", "constants", "functions", "main", "vertex_main", "pixel_names", "shared", "key")

    def __init__(self, structs, constants, functions, main, vertex_main, pixel_names, shared=None, key=None):
        self.structs = structs
        self.constants = constants
        self.functions = functions
        self.main = main
        self.vertex_main = vertex_main
        self.pixel_names = pixel_names
        self.shared = shared  # main's statements typed once per shape, with their lines (code/statements.py)
        self.key = key  # what the passes read, where main has a structure (`run`), else None

    def copy(self) -> "StageCode":
        """Its own, for a request (the vertex stage's main is set on it)."""
        return StageCode(self.structs, self.constants, self.functions, self.main, self.vertex_main,
                         self.pixel_names, self.shared, self.key)


def vertex_main(ctx) -> ir.Block:
    """The vertex stage: the position transform, then each vertex data member's assignment."""
    world = build.name("hPositionWorld", "local", "vec4")
    position = build.construct("vec4", build.name("i_position", "input", "vec3"), build.number(1.0))
    return ir.Block([
        ir.Declare("vec4", "hPositionWorld", build.binary("*", build.name("u_worldMatrix", "uniform", "mat4"), position),
                   False),
        ir.Assign("=", build.name("position", "builtin", "vec4"),
                  build.binary("*", build.name("u_viewProjectionMatrix", "uniform", "mat4"), world)),
        *ctx.vertex_main.values(),
    ], True)


def externals(ctx, stage: str) -> dict[str, str]:
    """The IR types of the variables the generator declared for a stage: what its code may read."""
    out = {}
    for block in ctx.stages[stage].blocks.values():
        for v in block:
            if block.name == "LightData":
                continue  # members of the light struct, not variables
            out[v.name] = "LightData[]" if v.type == "LightData" else ir_type(v.type)
    return out


def run(ctx, counts: dict) -> StageCode:
    """The pixel stage's code through the passes; its `vertex_main` is left to `vertex_stage`,
    once the generator knows which vertex data the pixel stage reads."""
    code = ctx.code
    main = ctx.pixel.main.block()
    stage_variables = externals(ctx, PIXEL)
    generated = ctx.pixel.generated
    main, shared = code.statements.share(main, generated, ctx.pixel.alike_found, ctx.pixel.alike_fresh)
    # what the passes read: the target (its own functions), main's structure and its functions',
    # the library items the request asked for, the features, the decided macros, the variables
    key = shared.key and (type(ctx.target), shared.key, tuple(map(id, ctx.pixel.items)), ctx.features, ctx.macros,
                          tuple(stage_variables.items()))
    known = code.stages.get(key) if key else None
    if known is not None:
        stage, passes = known
        counts.update(passes)
        return stage.copy()
    code.check_generated(generated, [main], stage_variables, shared.hits)
    shared.remember()
    # the structs a stage variable has (a uniform's, the light array's) are part of its layout
    layouts = [t.split("[")[0] for t in stage_variables.values() if code.struct(t.split("[")[0]) is not None]
    items = code.module(PRELUDE).items + ctx.pixel.items
    own = getattr(ctx.target, "own_functions", ())
    if own:
        items = [without_body(i) if isinstance(i, ir.Function) and i.name in own else i for i in items]
    reached, passes = stage_passes.run(items, ctx.features, ctx.macros, [main, *generated], layouts, code, shared)
    counts.update(passes)
    structs, constants, functions = [], [], []
    for i in reached.items:  # one look at each item (a section's is a walk of its body)
        (structs if isinstance(i, ir.Struct) else functions if has_function(i) else constants).append(i)
    functions += generated
    stage = StageCode(structs, constants, functions, main, None, frozenset(reached.names), shared, key)
    if key:
        code.stages.keep(key, (stage.copy(), passes))
    return stage


def pixel_stage(ctx) -> str:
    """The pixel stage's text, once the code passes ran: printed once per library for what the
    target's assembler reads, where main has a structure (its StageCode's `key`): the stage's
    code, every stage's variables (`variables_key`) and the OSL texture filter width."""
    code = ctx.pixel.code
    if code.key is None:
        return ctx.target.assemble_pixel(ctx)
    ui = getattr(ctx.target, "writes_ui", False)
    key = (code.key, tuple([variables_key(stage, ui) for stage in ctx.stages.values()]), ctx.texture_width)
    memo = ctx.code.stages
    text = memo.get(key)
    if text is None:
        text = ctx.target.assemble_pixel(ctx)
        memo.keep(key, text, len(text))
    return text


def variables_key(stage, ui: bool = False) -> tuple:
    """What a stage assembler may read of a stage's variables: each block's name, type and
    initializer, and their ui metadata where the target `writes_ui` (OSL's parameter hints);
    never a listing's value or path."""
    if ui:
        return tuple([(block.name, tuple([(v.name, v.type, repr(v.initializer), repr(v.ui)) for v in block]))
                      for block in stage.blocks.values()])
    return tuple([(block.name, tuple([(v.name, v.type, repr(v.initializer)) for v in block]))
                  for block in stage.blocks.values()])


@lru_cache(maxsize=256)
def without_body(function: ir.Function) -> ir.Function:
    """`function` with an empty body (one copy per library item, so the passes' memos still hit)."""
    return ir.replace(function, body=ir.Block([], True))


def has_function(item) -> bool:
    """A function, or a section (of a macro left to the target) holding one."""
    if isinstance(item, ir.Section):
        return any(has_function(i) for i in (*item.body, *item.other))
    return isinstance(item, ir.Function)


VERTEX_STAGES = Kept(MAX_STAGES, MAX_STAGE_TEXT)  # vertex_stage's memo, key -> text (per process)
UNKEPT = object()


def vertex_stage(ctx) -> str | None:
    """The vertex stage's text (None where the target has none), once its vertex data is final:
    its main built, typed and printed. Many materials share one (the same vertex data for the same
    target), so it is made once per process for each key that covers what its text depends on: the
    target, the library (which types the code), the stage's variables and its main's statements."""
    key = (type(ctx.target), ctx.code.key, variables_key(ctx.vertex), ir.shape(list(ctx.vertex_main.values())))
    text = VERTEX_STAGES.get(key, UNKEPT)  # (None is a text: OSL has no vertex stage)
    if text is not UNKEPT:
        return text
    vertex = vertex_main(ctx)
    ctx.code.check_generated([], [vertex], externals(ctx, VERTEX))
    ctx.pixel.code.vertex_main = vertex
    text = ctx.target.assemble_vertex(ctx)
    VERTEX_STAGES.keep(key, text, len(text or ""))
    return text
