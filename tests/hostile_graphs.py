"""Documents that are small to send but large once nodegraphs are expanded: each use of a nodegraph
implementation gets its own copy of the body, so nesting multiplies. Used by the tests of the
expansion limit and by bench/expansion.py.

    nested_definitions(depth)   ND_level<k>'s nodegraph calls <level{k-1}> `fanout` times: fanout**depth uses
    nested_nodegraphs(depth)    the same shape written as document nodegraphs connected by `nodegraph=`
    wide_definition(uses)       one small definition, used `uses` times in a chain
    wide_nodegraph(uses)        one document nodegraph whose output `uses` nodes read
    layered_material(layers)    for contrast, a legitimate large material: standard_surfaces mixed in a tree
"""

HEAD = '<?xml version="1.0"?>\n<materialx version="1.39">\n'
TAIL = '</materialx>\n'


def _definition(level: int, body: str) -> str:
    return (f'<nodedef name="ND_level{level}" node="level{level}">'
            f'<input name="in" type="float" value="0.5"/><output name="out" type="float"/></nodedef>\n'
            f'<nodegraph name="NG_level{level}" nodedef="ND_level{level}">{body}</nodegraph>\n')


def _sum_of(category: str, fanout: int, feed: str) -> str:
    """`fanout` nodes of `category` reading `feed`, added up; the graph's output is the sum."""
    nodes = "".join(f'<{category} name="c{i}" type="float"><input name="in" type="float" {feed}/></{category}>'
                    for i in range(fanout))
    total, adds = "c0", ""
    for i in range(1, fanout):
        adds += (f'<add name="s{i}" type="float"><input name="in1" type="float" nodename="{total}"/>'
                 f'<input name="in2" type="float" nodename="c{i}"/></add>')
        total = f"s{i}"
    return nodes + adds + f'<output name="out" type="float" nodename="{total}"/>'


LEAF_BODY = ('<multiply name="m" type="float"><input name="in1" type="float" interfacename="in"/>'
             '<input name="in2" type="float" value="0.75"/></multiply><output name="out" type="float" nodename="m"/>')


def nested_definitions(depth: int, fanout: int = 2) -> str:
    """Custom nodedefs whose nodegraphs each call the definition below `fanout` times; the
    document uses the top one once. Expanded: fanout**depth copies of the leaf body."""
    defs = _definition(0, LEAF_BODY)
    for level in range(1, depth + 1):
        defs += _definition(level, _sum_of(f"level{level - 1}", fanout, 'interfacename="in"'))
    return (HEAD + defs + f'<level{depth} name="top" type="float"><input name="in" type="float" value="0.25"/>'
            f'</level{depth}>\n<output name="result" type="float" nodename="top"/>\n' + TAIL)


def nested_nodegraphs(depth: int, fanout: int = 2) -> str:
    """Document nodegraphs NG_k whose `fanout` nodes each read NG_{k-1}'s output (`nodegraph=`).
    A connection to a graph's output is one upstream node however many read it: nothing expands."""
    graphs = ('<nodegraph name="NG0"><multiply name="m" type="float"><input name="in1" type="float" value="0.5"/>'
              '<input name="in2" type="float" value="0.75"/></multiply>'
              '<output name="out" type="float" nodename="m"/></nodegraph>\n')
    for level in range(1, depth + 1):
        body = _sum_of("sin", fanout, f'nodegraph="NG{level - 1}" output="out"')
        graphs += f'<nodegraph name="NG{level}">{body}</nodegraph>\n'
    return (HEAD + graphs + f'<output name="result" type="float" nodegraph="NG{depth}" output="out"/>\n' + TAIL)


def wide_definition(uses: int) -> str:
    """One custom nodedef (a two-node nodegraph) used `uses` times, each use reading the last."""
    body = ('<multiply name="m" type="float"><input name="in1" type="float" interfacename="in"/>'
            '<input name="in2" type="float" value="0.75"/></multiply>'
            '<add name="a" type="float"><input name="in1" type="float" nodename="m"/>'
            '<input name="in2" type="float" value="0.125"/></add><output name="out" type="float" nodename="a"/>')
    chain = "".join(f'<w name="w{i}" type="float"><input name="in" type="float" nodename="w{i - 1}"/></w>\n'
                    for i in range(1, uses))
    return (HEAD + '<nodedef name="ND_w" node="w"><input name="in" type="float" value="0.5"/>'
            '<output name="out" type="float"/></nodedef>\n'
            f'<nodegraph name="NG_w" nodedef="ND_w">{body}</nodegraph>\n'
            '<w name="w0" type="float"/>\n' + chain
            + f'<output name="result" type="float" nodename="w{uses - 1}"/>\n' + TAIL)


def wide_nodegraph(uses: int) -> str:
    """One document nodegraph whose output `uses` nodes read, summed in a chain."""
    graph = ('<nodegraph name="NG_shared"><multiply name="m" type="float"><input name="in1" type="float" value="0.5"/>'
             '<input name="in2" type="float" value="0.75"/></multiply>'
             '<output name="out" type="float" nodename="m"/></nodegraph>\n')
    chain = "".join(f'<add name="a{i}" type="float"><input name="in1" type="float" nodename="a{i - 1}"/>'
                    f'<input name="in2" type="float" nodegraph="NG_shared" output="out"/></add>\n'
                    for i in range(1, uses))
    return (HEAD + graph + '<sin name="a0" type="float"><input name="in" type="float" nodegraph="NG_shared"/></sin>\n'
            + chain + f'<output name="result" type="float" nodename="a{uses - 1}"/>\n' + TAIL)


def layered_material(layers: int) -> str:
    """`layers` standard_surface shaders (each a nodegraph of the library) mixed pairwise into
    one material: far larger than any real material, and nothing in it is hostile."""
    shaders = "".join(
        f'<standard_surface name="s{i}" type="surfaceshader">'
        f'<input name="base_color" type="color3" value="{i / layers:.3f}, 0.5, 0.25"/>'
        f'<input name="specular_roughness" type="float" value="{0.1 + 0.8 * i / layers:.3f}"/></standard_surface>\n'
        for i in range(layers))
    mixes, level = "", [f"s{i}" for i in range(layers)]
    while len(level) > 1:
        paired = []
        for fg, bg in zip(level[::2], level[1::2]):
            name = f"mix{len(mixes.splitlines())}"
            mixes += (f'<mix name="{name}" type="surfaceshader"><input name="fg" type="surfaceshader" nodename="{fg}"/>'
                      f'<input name="bg" type="surfaceshader" nodename="{bg}"/>'
                      f'<input name="mix" type="float" value="0.5"/></mix>\n')
            paired.append(name)
        level = paired + level[len(paired) * 2:]
    return (HEAD + shaders + mixes + '<surfacematerial name="Layered" type="material">'
            f'<input name="surfaceshader" type="surfaceshader" nodename="{level[0]}"/></surfacematerial>\n' + TAIL)
