"""The surface node: where closures meet light (seed 3.5, 4.5).

The BSDF graph connected to a surface is evaluated once per shading context, each time with a
`closureData` describing it: once per active light (reflection), once for the environment
(indirect), once for the view direction (transmission); the EDF graph once for emission. Data
nodes feeding the closures are computed once, before. A context whose closure input is
unconnected is not written at all.
"""
from ..code.externals import ENVIRONMENT_UNIFORMS
from ..features import TRANSMISSION_FEATURE
from ..shader import PIXEL, Variable
from .base import NodeImpl, implementation_for, register
from .geometric import Normal, Position

LIGHT_TYPES = (("point_light", 1), ("directional_light", 2), ("spot_light", 3))  # LightData.type ids

def light_functions(ctx) -> list[tuple[int, str]]:
    """(type id, function) of every light shader the libraries implement for this target."""
    found = []
    for node, type_id in LIGHT_TYPES:
        nodedef = ctx.scope.nodedef(f"ND_{node}")
        impl_elem = ctx.scope.implementation(nodedef, ctx.target.library) if nodedef is not None else None
        if impl_elem is not None and impl_elem.get("file"):
            impl = implementation_for(impl_elem, ctx.scope.library)
            ctx.emit_modules(impl.files)
            found.append((type_id, impl.function))
    return found


def emit_light_support(ctx) -> bool:
    """LightData, the light array and sampleLightSource(), once per shader. False without lights."""
    if "lights" not in ctx.memo:
        ctx.memo["lights"] = _emit_light_support(ctx)
    return ctx.memo["lights"]


def _emit_light_support(ctx) -> bool:
    lights = light_functions(ctx)
    if not lights:
        return False
    ctx.private_uniform("u_numActiveLightSources", "integer")
    ctx.add_variable(PIXEL, "PrivateUniforms", Variable("u_lightData", "LightData"))
    ctx.target.closures.emit_light_dispatch(ctx, lights)
    # the ids the dispatch compares `type` against, for renderers binding a light rig
    ids = {node: type_id for node, type_id in LIGHT_TYPES if type_id in {t for t, _ in lights}}
    ctx.pixel.blocks["LightData"].variables["type"].ui = {"enum": list(ids), "enumvalues": list(ids.values())}
    return True


@register("IM_surface")
class Surface(NodeImpl):
    """Which shading contexts a surface needs is decided here, from the finished graph: the light
    loop (unless the shader is generated for a scene without lights: Graph.lights) and the
    environment when a BSDF is connected, transmission only when a lobe under it
    transmits (passes/closures.py), emission when an EDF is connected. The target's closure
    convention writes them (targets/closures.py)."""

    def features(self, node) -> set[str]:
        """TRANSMISSION (the closures' code for the transmission context) where this surface writes
        that context."""
        return {TRANSMISSION_FEATURE} if self._transmits(node) else set()

    @staticmethod
    def _transmits(node) -> bool:
        return node.inputs["bsdf"].connection is not None and node.facts.get("transmission", True)

    def emit_function_definition(self, node, ctx):
        if ctx.target.closures.values:  # the renderer integrates the closures: no lights, no environment
            self.lit = False
            return
        for name, type_name in ENVIRONMENT_UNIFORMS:
            ctx.private_uniform(name, type_name)
        self.lit = node.inputs["bsdf"].connection is not None and ctx.lights and emit_light_support(ctx)

    def emit_function_call(self, node, ctx):
        bsdf, edf = node.inputs["bsdf"], node.inputs["edf"]
        contexts = []
        if bsdf.connection is not None:
            contexts += [("reflection", bsdf)] if self.lit else []
            contexts.append(("indirect", bsdf))
        if edf.connection is not None:
            contexts.append(("emission", edf))
        if self._transmits(node):
            contexts.append(("transmission", bsdf))
        out = next(iter(node.outputs.values()))
        ctx.output_name(out)
        ctx.target.closures.emit_surface(ctx, ctx.vars[id(out)].name, ctx.value(node.inputs["opacity"]),
                                         Position.varying(ctx, "world"), Normal.varying(ctx, "world"), contexts)
