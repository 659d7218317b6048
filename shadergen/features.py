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
any other is dropped, with an `#else` side taking its place (code/passes/sections.py, on the IR).
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

from .code.externals import ENVIRONMENT_MACROS
from .errors import ShaderGenError
from .graph import Graph, Input, Node

PREFIX = "MX_FEATURE_"
ENVIRONMENTS = tuple(ENVIRONMENT_MACROS)  # the ways of environment lighting (code/externals.py)
LIGHTS_FEATURE = "LIGHTS"  # closure code for lights: needed by shaders with a light loop
TRANSMISSION_FEATURE = "TRANSMISSION"  # closure code for the transmission context: needed by surfaces writing it
COMPARE = {"==": operator.eq, "!=": operator.ne, "<=": operator.le, ">=": operator.ge, "<": operator.lt, ">": operator.gt}


def node_features(node: Node, declarations) -> set[str]:
    """The features a node needs, from its source's declarations: (feature, input, comparison,
    value) each, as the parser reads them (code/parse.py, ir.Module.features)."""
    needed = set()
    for feature, input_name, comparison, literal in declarations:
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
