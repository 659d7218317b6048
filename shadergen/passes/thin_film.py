"""The seed's `thinfilmbxdf` (section 4.2) is a modifier, not a lobe: it "adds an iridescent thin
film layer over a microfacet base BSDF". The 1.39 lobes carry a film themselves
(`thinfilm_thickness`, `thinfilm_ior` on dielectric_bsdf, conductor_bsdf and
generalized_schlick_bsdf), so the film's thickness and ior are given to every such lobe under its
`base`, and the film node gives way to its base. It runs after nodegraph expansion, so the lobes
inside the seed's own nodes (dielectricbrdf, conductorbrdf, ...) are reached.

- A lobe that sets its own film (an authored or connected `thinfilm_thickness`) keeps it, and the
  walk stops at another thinfilmbxdf: the film nearest to a lobe is the one it gets.
- The lobes read the film's binding itself: its value, its connection, or its uniform (a public
  thickness becomes one uniform every lobe under the film reads).
- A film that reaches no microfacet lobe changes nothing, with a warning; without a base it scatters
  nothing (the seed requires one), also with a warning.
"""
from ..graph import Graph, Input, Node, Socket
from .closures import closure_tree
from .edit import pass_through, readers
from .order import topological_order

FILM = "thinfilmbxdf"
LOBE_INPUTS = {"thickness": "thinfilm_thickness", "ior": "thinfilm_ior"}  # the film's input -> the lobe's


def push_thin_films(graph: Graph) -> int:
    """Returns how many lobes took a film."""
    films = [n for n in graph.nodes if n.category == FILM]
    if not films:
        return 0
    count = 0
    for film in films:
        lobes = [n for n in closure_tree(film.inputs["base"], stop=lambda n: n.category == FILM)
                 if LOBE_INPUTS["thickness"] in n.inputs and not has_own_film(n)]
        if film.inputs["base"].connection is None:
            graph.warnings.append(f"{film.path}: {FILM} has no base BSDF; it scatters nothing")
        elif not lobes:
            graph.warnings.append(f"{film.path}: no microfacet lobe under {FILM} takes its film; it changes nothing")
        for lobe in lobes:
            for film_input, lobe_input in LOBE_INPUTS.items():
                give_binding(film.inputs[film_input], lobe.inputs[lobe_input], graph)
        count += len(lobes)
    reading = readers(graph)
    for film in films:
        pass_through(graph, film, film.inputs["base"], reading)
        for name in LOBE_INPUTS:
            retire(film.inputs[name], graph)
    graph.nodes = topological_order(graph.outputs)
    return count


def has_own_film(lobe: Node) -> bool:
    thickness = lobe.inputs[LOBE_INPUTS["thickness"]]
    return thickness.authored or thickness.connection is not None or thickness.socket is not None


def give_binding(source: Input, inp: Input, graph: Graph) -> None:
    """`inp` reads what `source` reads from now on."""
    if inp.public:  # a document lobe's own uniform, which the film now overrides
        inp.public = False
        graph.interface.remove(inp)
    inp.unbind_socket()
    inp.connection, inp.value, inp.path, inp.parameter = source.connection, source.value, source.path, None
    if source.public:
        shared_uniform(source, graph)
    if source.socket is not None:
        inp.bind_socket(source.socket)


def shared_uniform(inp: Input, graph: Graph) -> Socket:
    """A public input turned into a uniform several inputs read (as expansion does for a body)."""
    socket = Socket(inp.name, inp.type, inp.value, inp.path, dict(inp.meta), origin=inp, public=True,
                    default=inp.default)
    graph.interface[graph.interface.index(inp)] = socket
    inp.public = False
    inp.bind_socket(socket)
    return socket


def retire(inp: Input, graph: Graph) -> None:
    """The film node is gone: its input reads nothing and is no uniform of its own."""
    if inp.public:  # no lobe took it
        inp.public = False
        graph.interface.remove(inp)
    inp.unbind_socket()
