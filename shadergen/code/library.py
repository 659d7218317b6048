"""The library's shader code as typed IR: every source file parsed and checked once per library.

A CodeLibrary is made from a loaded data library (shadergen/library.py's Library: its folder and
the hash that names its content). Its source files (`*.glsl` under a `genglsl` folder) and the
prelude (code/prelude.glsl: the closure, shader and light types) are parsed (code/parse.py) and
checked (code/check.py) together, and every inline implementation's expression (`sourcecode`, or
an `.inline` file, as nodes/base.py reads them) is parsed into a template. The result is pickled
in the cache folder beside the data library's JSON Lines cache, under a name made of the
library's hash, the prelude and the externals, so a process after the first reads one file
instead of parsing (the figures are in the commit that added this), and reads what calling a
function means to the passes (Calls) instead of working it out from their facts and bodies. A
damaged file is rebuilt.

Paths are relative to the library folder (`pbrlib/genglsl/lib/mx_fresnel.glsl`): they are in
every node's `where`, and the pickle does not depend on where the library lies.
"""
import os
import re
from collections import namedtuple

from ..digest import sha256
from ..errors import ShaderGenError
from ..fingerprint import library_files
from ..library import Library, cache_dir, collection_paused, read_source, write_atomically
from . import cachefile, ir, pickling
from .check import check_expression, check_modules, flat_items, library_symbols
from .externals import ENVIRONMENT_MACROS, environment_macros
from .facts import early_exit_at_zero_weight, facts, prepared_state, reads_constant, uses_derivatives
from .generated import check_generated
from .instantiate import maker
from .kept import Kept
from .passes import sections
from .statements import Memo

__all__ = ["CodeLibrary", "PRELUDE", "PRELUDE_PATH"]

PRELUDE = "prelude.glsl"  # the prelude's path among the modules (no library file is at the top)
PRELUDE_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "prelude.glsl")
CACHE_FORMAT = b"shadergen-code-8"
# an identifier as the libraries' sources spell one (comments and strings included: only ever more);
# compiled where a library is built (re's cache), not by every process that imports this module
_SOURCE_IDENTIFIER = r"(?a)\b[A-Za-z_]\w*"


def _running_ir() -> bytes:
    """The IR classes this process runs, as their source read now, at import: the pickle holds
    their instances. (The library's hash covers the generator's files as they are on disk when a
    Library loads; a process that imported older files before a release was unpacked would write
    its pickle under the new files' name.)"""
    with open(ir.__file__, "rb") as f:
        return sha256(f.read()).digest()


RUNNING_IR = _running_ir()
STATE_SIZE = 7  # the fields of CodeLibrary.state()
MAX_MEMO = 65536  # documents' own templates kept per library (their texts come from requests)
MAX_STAGES = 4096  # pixel stages' code and texts kept per library (code/stage.py), and vertex stages per process
MAX_STAGE_TEXT = 32 << 20  # characters of their texts (every TestSuite document's pixel stages: 14 MB)
# What a node implementation calling a library function by name needs to know of its definitions
# (nodes/base.py SourceFunctionImpl, the passes that read it): whether any takes derivatives, itself
# or in what it calls; whether every one is a lobe empty at zero weight; whether any answers the
# transmission context; the state its `_prepare` writes (code/facts.py). Worked out for every name
# when the cache is built and read with it: a cold process reads four fields per name, not the facts
# and bodies of every function they come from (116 functions' facts and 17 bodies for carpaint).
# Most names (277 of 318) answer no to all four (PLAIN, as a name with no definition does): the
# cache holds the others.
Calls = namedtuple("Calls", "uses_derivatives empty_at_zero_weight handles_transmission prepared_state")
PLAIN = Calls(False, False, False, None)


class CodeLibrary:
    """The typed IR of a library's code, with its symbol table (see the module's doc), and every
    identifier its sources spell (`identifiers`, Identifiers): WGSL reads a uniform through its buffer wherever
    its name stands (`pu.name`), inside library functions too, so a uniform must not share a name
    with anything there."""
    __slots__ = ("root", "key", "modules", "symbols", "templates", "externals", "identifiers", "calls",
                 "indexed", "resolved", "typed", "parsed", "makers", "generated", "statements", "stages")

    def __init__(self, root: str, state: tuple):
        self.root = root
        self.key, self.modules, self.symbols, self.templates, self.externals, identifiers, self.calls = state
        self.identifiers = Identifiers(identifiers)
        self.indexed = None  # (library_items, id(item) -> its place among them), made when first asked
        self.resolved = None  # Resolved: the resolutions, read from their file when first asked
        self.typed: dict = {}  # (template, placeholder types) -> typed expression (check.check_expression)
        self.parsed: dict[str, ir.Expr] = {}  # templates of documents' own inline expressions
        self.makers: dict = {}  # (template, input types) -> its maker (code/instantiate.py)
        self.generated = ({}, {})  # what typing generated code works out per library (code/generated.py)
        self.statements = Memo()  # main's statements, typed once per shape (code/statements.py)
        self.stages = Kept(MAX_STAGES, MAX_STAGE_TEXT)  # pixel stages' code and text, per structure (code/stage.py)

    @classmethod
    def load(cls, library: Library, externals: dict[str, str]) -> "CodeLibrary":
        """The code of `library`, from the cache when it holds it. `externals`: name -> IR type of
        every variable the generator declares that library code reads (the environment and light
        uniforms)."""
        key = cache_key(library, externals)
        path = os.path.join(cache_dir(), f"code-{key[:24]}.pickle")

        def written() -> tuple[tuple, bytes]:
            state = build(library, externals, key)
            return state, write_cache(path, state, cachefile.library_items(state[1]))
        with collection_paused():
            state = read_cache(path, key, lambda: written()[1])
            if state is None:
                state = written()[0]
        return cls(library.root, state)

    def state(self) -> tuple:
        """What the cache holds (equal for equal libraries, whatever order they were read in)."""
        return (self.key, self.modules, self.symbols, self.templates, self.externals, self.identifiers.table,
                self.calls)

    # -- lookups -----------------------------------------------------------------------------------
    def module(self, path: str) -> ir.Module:
        """A source file's module; `path` absolute or relative to the library folder."""
        module = self.modules.get(path)  # the generator asks by the relative paths files_for gives
        if module is None:
            module = self.modules.get(self.relative(path))
        if module is None:
            raise ShaderGenError("missing_source", f"'{path}' is not a source file of the library", path)
        return module

    def functions(self, name: str) -> list[ir.Function]:
        """Every overload of a library function (none: an empty list)."""
        return list(self.symbols.functions.get(name, {}).values())

    def items(self) -> tuple[list, dict[int, int]]:
        """The library's items (cachefile.library_items) and id(item) -> its place among them."""
        if self.indexed is None:
            items = cachefile.library_items(self.modules)
            self.indexed = items, {id(item): n for n, item in enumerate(items)}
        return self.indexed

    def resolution(self, function, decisions: tuple) -> tuple[tuple, int] | None:
        """A library function's sections resolved for `decisions` (code/passes/sections.py's
        resolve), as the cache holds them (resolutions_of); None for anything else."""
        place = self.items()[1].get(id(function))
        return None if place is None else self.read_resolutions().table.get((place, decisions))

    def read_resolutions(self) -> "Resolved":
        """The resolutions, read the first time a stage asks (only a shader with sections needs
        them: most of the standard library's have none) from their file beside the code's, which
        the first process to ask writes (a damaged one is written again)."""
        if self.resolved is None:
            items = self.items()[0]
            path = os.path.join(cache_dir(), f"resolutions-{self.key[:24]}.pickle")

            def written() -> tuple[dict, bytes]:
                table = resolutions_of(self.modules)
                return table, write_cache(path, (self.key, table), items + cachefile.copies_in(items, table))
            state = read_state(path, lambda state: items + cachefile.copies_in(items, state[1]),
                               lambda state: isinstance(state, tuple) and len(state) == 2 and state[0] == self.key,
                               lambda: written()[1])
            table = state[1] if state is not None else written()[0]
            self.resolved = Resolved(table, cachefile.copies_in(items, table))
        return self.resolved

    def calls_of(self, name: str) -> Calls:
        """What calling the library function `name` means to the passes (Calls)."""
        return self.calls.get(name, PLAIN)

    def struct(self, name: str) -> ir.Struct | None:
        return self._item(name, ir.Struct)

    def constant(self, name: str) -> ir.Constant | None:
        return self._item(name, ir.Constant)

    def _item(self, name: str, kind: type):
        found = self.symbols.items.get(name)
        return found if isinstance(found, kind) else None

    def files_for(self, path: str) -> tuple[str, ...]:
        """A source file and the files it includes, dependencies first, each once (paths
        relative to the library folder)."""
        order: list[str] = []

        def visit(relative: str) -> None:
            if relative not in order:
                for inc in self.module(relative).includes:
                    visit(inc)
                order.append(relative)
        visit(self.relative(path))
        return tuple(order)

    def relative(self, path: str) -> str:
        return os.path.relpath(os.path.realpath(path), self.root) if os.path.isabs(path) else os.path.normpath(path)

    def check_generated(self, functions, blocks, externals: dict[str, str], shared=frozenset()) -> None:
        """Types the generator's own code against the library's (code/generated.py); `shared`:
        ids of statements typed before (code/statements.py)."""
        check_generated(self, functions, blocks, externals, shared)

    def template(self, expression_text: str, where: str = "inline expression") -> ir.Expr:
        """The untyped template of an inline expression (`{{input}}` an ir.Placeholder)."""
        text = expression_text.strip()
        found = self.templates.get(text) or self.parsed.get(text)
        if found is None:
            from .parse import parse_expression  # (a process that reads its library from the cache parses little)
            found = parse_expression(text, where)
            if len(self.parsed) < MAX_MEMO:
                self.parsed[text] = found
        return found

    def expression(self, expression_text: str, placeholder_types: dict[str, str],
                   where: str = "inline expression") -> ir.Expr:
        """The template instantiated for its inputs' IR types, typed (shared: build new nodes
        rather than change it)."""
        return check_expression(self.template(expression_text, where), placeholder_types, self)

    def instance(self, expression_text: str, values: dict[str, ir.Expr], where: str = "inline expression") -> ir.Expr:
        """An inline expression with typed `values` in its placeholders: typed and compiled once
        per (template, input types) (code/instantiate.py), made per call."""
        template = self.template(expression_text, where)
        types = tuple(sorted((n, v.type) for n, v in values.items()))
        found = self.makers.get((template, types))
        if found is None:
            found = maker(check_expression(template, dict(types), self))
            if len(self.makers) < MAX_MEMO:
                self.makers[(template, types)] = found
        return found(values)


def cache_key(library: Library, externals: dict[str, str]) -> str:
    h = sha256(CACHE_FORMAT + b"\0" + RUNNING_IR + b"\0" + library.content_hash.encode() + b"\0")
    with open(PRELUDE_PATH, "rb") as f:  # a package file the generator's fingerprint (.py files) leaves out
        h.update(f.read() + b"\0")
    h.update(repr(sorted(externals.items())).encode())
    return h.hexdigest()


def source_files(root: str) -> list[str]:
    """The library's shader sources: `*.glsl` files in a `genglsl` folder, relative to the root."""
    return [os.path.relpath(p, root) for p in library_files(root)
            if p.endswith(".glsl") and "genglsl" in os.path.relpath(p, root).split(os.sep)]


def inline_sources(library: Library) -> list[tuple[str, str]]:
    """(expression text, where) of every inline implementation, in file and document order."""
    out = []
    for root in sorted(library.roots, key=lambda r: r.source or ""):
        relative = os.path.relpath(root.source, library.root) if root.source else "?"
        for elem in root.children:
            if elem.category != "implementation":
                continue
            if elem.get("sourcecode") is not None:
                out.append((elem.get("sourcecode").strip(), f"{relative}: {elem.name}"))
            elif (elem.get("file") or "").endswith(".inline"):
                path = os.path.normpath(os.path.join(os.path.dirname(root.source), elem.get("file")))
                out.append((read_source(path).strip(), os.path.relpath(path, library.root)))
    return out


def build(library: Library, externals: dict[str, str], key: str) -> tuple:
    """The cache's state: parsed and checked modules, the symbol table, the inline templates."""
    root = library.root
    from .parse import parse_expression, parse_module  # (only where the cache is built: 1 ms of a cold start)
    modules = {PRELUDE: parse_module(PRELUDE, read_source(PRELUDE_PATH))}
    identifiers = set()
    for relative in sorted(source_files(root)):
        text = read_source(os.path.join(root, relative))
        modules[relative] = parse_module(relative, text)
        identifiers.update(re.findall(_SOURCE_IDENTIFIER, text))
    symbols = library_symbols(check_modules(modules, externals, (PRELUDE,)))
    symbols.items = top_level_items(modules)
    templates = {}
    for text, where in inline_sources(library):
        if text not in templates:
            templates[text] = parse_expression(text, where)
    for module in modules.values():  # read now, they are pickled with the items: a cold process reads none
        for item in flat_items(module.items):
            facts(item)
    # WGSL spells a library name that is one of its reserved words `<name>_` (targets/wgsl)
    identifiers = identifiers | {f"{n}_" for n in identifiers}
    by_initial: dict[str, list[str]] = {}
    for name in sorted(identifiers):  # (sorted: a set's order depends on how it was filled)
        by_initial.setdefault(name[0], []).append(name)
    state = (key, modules, symbols, cachefile.Apart(templates), dict(sorted(externals.items())),
             cachefile.Apart({initial: tuple(names) for initial, names in by_initial.items()}))
    return state + (calls_by_name(CodeLibrary(root, state + ({},))),)


class Identifiers:
    """Every identifier the library's sources spell, asked for by `name in`; read from the cache
    by initial, when a name with that initial is first asked about: a structural uniform's name
    (`u_n3_base`, the one question a request asks) needs those starting with `u`, not the five
    thousand others."""
    __slots__ = ("table", "read")

    def __init__(self, table: cachefile.Apart):
        self.table = table  # initial -> its identifiers (a tuple), in the cache's table
        self.read: dict[str, frozenset] = {}

    def __contains__(self, name: str) -> bool:
        initial = name[:1]
        names = self.read.get(initial)
        if names is None:
            names = self.read[initial] = frozenset(self.table.get(initial) or ())
        return name in names


class Resolved:
    """The library's functions with their sections resolved (resolutions_of): `table`, (place,
    decisions) -> (items, count); `copies`, the items of the resolutions, whose places follow the
    library's items (targets/printed.py prints them once)."""
    __slots__ = ("table", "copies")

    def __init__(self, table: dict, copies: list):
        self.table, self.copies = table, copies


def resolutions_of(modules: dict) -> dict:
    """(place among library_items, decisions) -> (items, sections resolved): every library function
    with sections, resolved (code/passes/sections.py) for every set of decisions a stage can make
    of its macros (it decides no macro but the environment's, code/externals.py), with its facts
    read; those that resolve no section are left out (the pass keeps the function). A cold process
    reads a stage's copies, their facts and their printed lines instead of reading, rebuilding,
    walking and printing each body (carpaint: 21)."""
    out = {}
    decided_options = [environment_macros(e) for e in (None, *ENVIRONMENT_MACROS)]
    for place, item in enumerate(cachefile.library_items(modules)):
        mentioned = sections.macros_in(item) if isinstance(item, ir.Function) else ()
        for decisions in sections.decisions_of(mentioned, decided_options) if mentioned else ():
            resolved, count = sections.resolve(item, decisions)
            if count:
                out[(place, decisions)] = resolved, count
                for copy in resolved:
                    facts(copy)  # (pickled with it)
    return out


def calls_by_name(code: CodeLibrary) -> dict[str, Calls]:
    """Calls of the library's function names that are not PLAIN, by name (sorted: the cache's bytes)."""
    out = {}
    for name in sorted(code.symbols.functions):
        definitions = code.functions(name)
        calls = Calls(any(uses_derivatives(f) for f in definitions),
                      all(early_exit_at_zero_weight(f) for f in definitions),
                      any(reads_constant(f, "CLOSURE_TYPE_TRANSMISSION") for f in definitions),
                      prepared_state(definitions[0], code))
        if calls != PLAIN:
            out[name] = calls
    return out


def top_level_items(modules: dict[str, ir.Module]) -> dict[str, ir.Item]:
    """Structs, constants, globals by name; a function's key defined twice is an error of the source."""
    items: dict[str, ir.Item] = {}
    keys: dict[str, ir.Function] = {}
    for path in modules:
        for item in flat_items(modules[path].items):
            if isinstance(item, ir.Function):
                if item.key in keys and keys[item.key] is not item:
                    first = keys[item.key].where
                    raise ShaderGenError("invalid_source", f"{item.where[0]}:{item.where[1]}:{item.where[2]}: "
                                         f"{item.key} is defined again (first at {first[0]}:{first[1]})",
                                         item.where[0])
                keys[item.key] = item
            elif isinstance(item, (ir.Struct, ir.Constant, ir.Global)):
                items.setdefault(item.name, item)
    return items


def read_cache(path: str, key: str, rebuild) -> tuple | None:
    """The cached state, or None (missing, damaged, or another key's)."""
    return read_state(path, lambda state: cachefile.library_items(state[1]),
                      lambda state: isinstance(state, tuple) and len(state) == STATE_SIZE and state[0] == key, rebuild)


def read_state(path: str, items_of, valid, rebuild) -> object | None:
    """What cachefile.dumps wrote into `path` (`items_of` and `rebuild`: cachefile.load's), where
    `valid(state)`; None where the file is missing, damaged, or not `valid` (another library's)."""
    try:
        state = cachefile.load(path, items_of, rebuild)
    except (OSError, pickling.UnpicklingError, EOFError, AttributeError, ValueError, TypeError, IndexError):
        return None
    return state if valid(state) else None


def write_cache(path: str, state, items: list) -> bytes:
    """`state` as cachefile.dumps writes it (`items`: the places of references), written to `path`
    (a read-only home is not fatal: the next process builds it again); its bytes."""
    data = cachefile.dumps(state, items)
    try:
        write_atomically(path, data)
    except OSError:
        pass
    return data
