"""Generation-time features of the libraries: code a shader keeps only when one of its nodes needs it.

The PBR library serves every combination of its nodes' settings through run-time branches (a thin
film over any Fresnel model, refraction, rough diffuse, ...). Where a setting is a constant of the
shader, the branches it never takes are dead code, but the compiler still parses and optimises
them. So library sources mark such code as a section of a feature:

    #ifdef MX_FEATURE_THIN_FILM
        if (mx_fresnel_has_thinfilm(fd))
            return mx_fresnel_airy(cosTheta, fd);
    #endif

and a node's own source file declares when its calls need the feature:

    #pragma shadergen feature THIN_FILM unless thinfilm_thickness == 0
    #pragma shadergen feature FRESNEL_DIELECTRIC

The first is needed unless the input is a constant of the shader (neither connected nor a uniform)
whose value satisfies the comparison; the second whenever the node is in the shader. A shader's
features are those of all its nodes (dynamic implementations may add their own); the generator
resolves the sections before a target sees the text: a needed section stays (its directives go),
any other is dropped, with an `#else` side taking its place. `#pragma shadergen` lines are removed.
Other preprocessor conditionals are left to the compiler, except a compiler macro the caller has
decided: a shader generated for one way of environment lighting (ENVIRONMENTS) has the
MX_ENV_PREFILTER and MX_ENV_HYBRID conditionals resolved too, so the other ways' code is not in it
at all.

Two features are the shading contexts' rather than a closure node's: LIGHTS (MX_FEATURE_LIGHTS, the
closures' code for the REFLECTION context of a light) is in every shader generated with a light
loop, and in none generated for scenes without lights (Graph.lights), such as thumbnails lit by
the environment; TRANSMISSION (the code for the TRANSMISSION context) is needed by a surface that
writes that context (one with a transmitting lobe, passes/closures.py).
"""
import operator
import re
from functools import lru_cache

from .errors import ShaderGenError
from .graph import Graph, Input, Node

PREFIX = "MX_FEATURE_"
DECLARATION = re.compile(r"^\s*#\s*pragma\s+shadergen\s+feature\s+(\w+)(?:\s+unless\s+(\w+)\s*(==|!=|<=|>=|<|>)\s*(\S+))?\s*$",
                         re.M)
PRAGMA = re.compile(r"^\s*#\s*pragma\s+shadergen\b")
CONDITIONAL = re.compile(r"^\s*#\s*(ifdef|ifndef|if|else|elif|endif)\b\s*(\w*)")
# Ways of environment lighting, each with the compiler macros a renderer defines for it: filtered
# importance sampling; a prefiltered map, one lookup; that lookup corrected by a few samples.
ENVIRONMENT_MACROS = {"fis": (), "prefilter": ("MX_ENV_PREFILTER",), "hybrid": ("MX_ENV_PREFILTER", "MX_ENV_HYBRID")}
ENVIRONMENTS = tuple(ENVIRONMENT_MACROS)
LIGHTS_FEATURE = "LIGHTS"  # closure code for lights: needed by shaders with a light loop
TRANSMISSION_FEATURE = "TRANSMISSION"  # closure code for the transmission context: needed by surfaces writing it
COMPARE = {"==": operator.eq, "!=": operator.ne, "<=": operator.le, ">=": operator.ge, "<": operator.lt, ">": operator.gt}


@lru_cache(maxsize=1024)
def declarations(source: str) -> tuple[tuple[str, str | None, str | None, str | None], ...]:
    """(feature, input, comparison, value) of each `#pragma shadergen feature` line of a source."""
    return tuple(m.groups() for m in DECLARATION.finditer(source))


def node_features(node: Node, source: str) -> set[str]:
    """The features a node implemented by `source` needs, from the source's declarations."""
    needed = set()
    for feature, input_name, comparison, literal in declarations(source):
        if input_name is None or not _holds(node, input_name, comparison, literal):
            needed.add(feature)
    return needed


def _holds(node: Node, input_name: str, comparison: str, literal: str) -> bool:
    """Whether the input is a constant whose value satisfies the comparison (unknown: False)."""
    inp: Input | None = node.inputs.get(input_name)
    if inp is None:
        raise ShaderGenError("invalid_implementation", f"a feature declaration names unknown input '{input_name}'",
                             node.path)
    if not inp.is_constant():
        return False
    value, wanted = inp.value, _literal(literal)
    if isinstance(wanted, float):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return False
        return COMPARE[comparison](float(value), wanted)
    return COMPARE[comparison](value, wanted) if comparison in ("==", "!=") else False


def _literal(text: str):
    if text in ("true", "false"):
        return text == "true"
    try:
        return float(text)
    except ValueError:
        return text


def graph_features(graph: Graph) -> set[str]:
    """Every feature the nodes of a graph need, those of its shared nodegraph functions included."""
    needed: set[str] = set()
    for node in graph.nodes:
        needed |= node.impl.features(node)
        function = getattr(node.impl, "function", None)
        if hasattr(function, "graph"):
            needed |= graph_features(function.graph)
    return needed


def environment_macros(environment: str | None) -> frozenset[tuple[str, bool]]:
    """The compiler macros a shader for `environment` (ENVIRONMENTS, None: either) has decided."""
    if environment is None:
        return frozenset()
    defined = ENVIRONMENT_MACROS[environment]
    return frozenset((macro, macro in defined) for macros in ENVIRONMENT_MACROS.values() for macro in macros)


@lru_cache(maxsize=4096)
def resolve(text: str, features: frozenset[str] | None, macros: frozenset[tuple[str, bool]] = frozenset()) -> str:
    """The text with its feature sections resolved for `features` (see the module's doc); None
    keeps every section (a stage whose nodes were not asked). `macros`: (compiler macro, defined)
    pairs resolved like features."""
    decided = dict(macros)
    out: list[str] = []
    # one entry per open conditional: None for the compiler's own, else whether its side is kept
    stack: list[bool | None] = []
    for line in text.split("\n"):
        if "#" not in line:  # most lines: neither a conditional nor a pragma
            if False not in stack:
                out.append(line)
            continue
        m = CONDITIONAL.match(line)
        if m and m.group(1) in ("ifdef", "ifndef") and (m.group(2).startswith(PREFIX) or m.group(2) in decided):
            macro = m.group(2)
            defined = decided[macro] if macro in decided else features is None or macro[len(PREFIX):] in features
            stack.append(defined == (m.group(1) == "ifdef"))
            continue
        if m and m.group(1) in ("if", "ifdef", "ifndef"):
            stack.append(None)
        elif m and m.group(1) in ("else", "elif") and stack and stack[-1] is not None:
            if m.group(1) == "elif":
                raise ShaderGenError("invalid_implementation", "#elif in a feature section", line.strip())
            stack[-1] = not stack[-1]
            continue
        elif m and m.group(1) == "endif" and stack:
            if stack.pop() is not None:
                continue
        if False not in stack and not PRAGMA.match(line):
            out.append(line)
    return "\n".join(out)
