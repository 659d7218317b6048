"""The passes that turn a built graph into the finished graph emission walks, in their order.

Each pass is a function of its own module and returns how many edits it made; the record carries
the counts (`"passes": {...}`), so a caller sees what was skipped and why. Emission never builds,
expands or changes the graph.
"""
from collections import namedtuple

from ..graph import Graph, GraphBuilder, Node, Output
from .closures import prune_closures
from .elide import elide_passthrough_nodes
from .expand import expand_nodegraphs
from .fold import fold_constants
from .functions import share_functions
from .interface import bind_interface, choose_implementations, publish_textures
from .order import assign_scopes, topological_order
from .thin_film import push_thin_films
from .thin_surface import share_one_sided_bsdf


class Options(namedtuple("Options", "interface keep values environment lights texture_width",
                         defaults=("complete", frozenset(), "listing", None, True, None))):
    """interface: complete | reduced | specialized. keep: document inputs that stay live in
    `specialized`. values: listing (uniforms initialised to nodedef values) or source (to the
    document's). environment: fis | prefilter | hybrid writes only that way of environment
    lighting. lights: False for a drawing without a light rig (a thumbnail): no light loop.
    texture_width: OSL's texture() filter width (None: OIIO's own footprint; api.prepare_all)."""
    __slots__ = ()

    @property
    def values_in_source(self) -> bool:
        return self.values == "source" or self.interface == "specialized"  # specialized folds values anyway


def prepare(builder: GraphBuilder, outputs: dict[str, Output], root: Node | None,
            options: Options = Options()) -> Graph:
    graph = Graph([], outputs, root, builder.warnings, interface_mode=options.interface,
                  values_in_source=options.values_in_source, environment=options.environment, lights=options.lights,
                  texture_width=options.texture_width)

    def run(name: str, edit) -> None:
        graph.passes[name] = edit()

    run("elide", lambda: elide_passthrough_nodes(graph.outputs))
    graph.nodes = topological_order(graph.outputs)
    choose_implementations(graph.nodes, builder.scope.library)
    run("interface", lambda: bind_interface(graph, options.interface, options.keep))
    run("thin_surface", lambda: share_one_sided_bsdf(graph))
    run("expand", lambda: expand_nodegraphs(graph, builder))
    run("thin_film", lambda: push_thin_films(graph))
    run("fold", lambda: fold_constants(graph, builder))
    choose_implementations(graph.nodes, builder.scope.library)
    run("prune_closures", lambda: prune_closures(graph))
    run("textures", lambda: publish_textures(graph))
    run("functions", lambda: share_functions(graph, uniform_flow))
    run("scopes", lambda: assign_scopes(graph.nodes, uniform_flow))
    return graph


def uniform_flow(node: Node) -> bool:
    """Nodes that take screen-space derivatives (or sample textures) stay out of branches."""
    return node.impl.uses_derivatives or any(i.type == "filename" for i in node.inputs.values())
