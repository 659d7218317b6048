"""The surface node: where closures meet light (seed 3.5, 4.5).

The BSDF graph connected to a surface is evaluated once per shading context, each time with a
`closureData` describing it: once per active light (reflection), once for the environment
(indirect), once for the view direction (transmission); the EDF graph once for emission. Data
nodes feeding the closures are computed once, before. A context whose closure input is
unconnected is not written at all.
"""
from ..shader import PIXEL, Variable
from ..targets.glsl import LIGHT_DATA_MEMBERS
from .base import NodeImpl, SourceFunctionImpl, register
from .geometric import Normal, Position

LIGHT_TYPES = (("point_light", 1), ("directional_light", 2), ("spot_light", 3))  # LightData.type ids
ENVIRONMENT_UNIFORMS = (
    ("u_envMatrix", "matrix44"), ("u_envRadiance", "filename"), ("u_envLightIntensity", "float"),
    ("u_envRadianceMips", "integer"), ("u_envRadianceSamples", "integer"), ("u_envIrradiance", "filename"),
    ("u_refractionTwoSided", "boolean"), ("u_viewPosition", "vector3"),
)


def light_functions(ctx) -> list[tuple[int, str]]:
    """(type id, function) of every light shader the libraries implement for this target."""
    found = []
    for node, type_id in LIGHT_TYPES:
        nodedef = ctx.scope.nodedef(f"ND_{node}")
        impl_elem = ctx.scope.implementation(nodedef, ctx.target) if nodedef is not None else None
        if impl_elem is not None and impl_elem.get("file"):
            impl = SourceFunctionImpl(impl_elem)
            ctx.emit_source_file(impl.path)
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
    ctx.used_types.add("LightData")
    ctx.private_uniform("u_numActiveLightSources", "integer")
    ctx.add_variable(PIXEL, "PrivateUniforms", Variable("u_lightData", "LightData"))
    for name, type_name in LIGHT_DATA_MEMBERS:
        ctx.add_variable(PIXEL, "LightData", Variable(name, type_name))
    # the ids the dispatch compares `type` against, for renderers binding a light rig
    ids = {node: type_id for node, type_id in LIGHT_TYPES if type_id in {t for t, _ in lights}}
    ctx.pixel.blocks["LightData"].variables["type"].ui = {"enum": list(ids), "enumvalues": list(ids.values())}
    w = ctx.pixel.functions
    with w.block("int numActiveLightSources()"):
        w.line("return min(u_numActiveLightSources, MAX_LIGHT_SOURCES);")
    w.line()
    with w.block("void sampleLightSource(LightData light, vec3 position, out lightshader result)"):
        w.line("result.intensity = vec3(0.0);")
        w.line("result.direction = vec3(0.0);")
        for i, (type_id, function) in enumerate(lights):
            w.line(f"{'if' if i == 0 else 'else if'} (light.type == {type_id})")
            w.line(f"    {function}(light, position, result);")
    w.line()
    ctx.used_types.add("lightshader")
    return True


@register("IM_surface_genglsl")
class Surface(NodeImpl):
    def emit_function_definition(self, node, ctx):
        for name, type_name in ENVIRONMENT_UNIFORMS:
            ctx.private_uniform(name, type_name)
        self.lit = node.inputs["bsdf"].connection is not None and emit_light_support(ctx)

    def emit_function_call(self, node, ctx):
        out = next(iter(node.outputs.values()))
        result = ctx.output_name(out)
        w = ctx.body
        bsdf, edf = node.inputs["bsdf"], node.inputs["edf"]
        w.line(f"surfaceshader {result} = surfaceshader(vec3(0.0), vec3(0.0));")
        with w.scope():
            position = Position.varying(ctx, "world")
            w.line(f"vec3 N = normalize({Normal.varying(ctx, 'world')});")
            w.line(f"vec3 V = normalize(u_viewPosition - {position});")
            w.line(f"vec3 P = {position};")
            w.line("vec3 L = vec3(0.0);")
            w.line("float occlusion = 1.0;")
            w.line(f"float surfaceOpacity = {ctx.value(node.inputs['opacity'])};")
            if bsdf.connection is not None:
                if self.lit:
                    with w.block("for (int activeLightIndex = 0; activeLightIndex < numActiveLightSources(); "
                                 "++activeLightIndex)"):
                        w.line("lightshader lightShader;")
                        w.line(f"sampleLightSource(u_lightData[activeLightIndex], {position}, lightShader);")
                        w.line("L = lightShader.direction;")
                        self.context(ctx, bsdf, "CLOSURE_TYPE_REFLECTION",
                                     f"{result}.color += lightShader.intensity * {{}}.response;")
                with w.scope("environment"):
                    self.context(ctx, bsdf, "CLOSURE_TYPE_INDIRECT", f"{result}.color += occlusion * {{}}.response;")
            if edf.connection is not None:
                with w.scope("emission"):
                    self.context(ctx, edf, "CLOSURE_TYPE_EMISSION", f"{result}.color += {{}};")
            if bsdf.connection is not None and node.facts.get("transmission", True):
                with w.scope("transmission, seen along the view direction"):
                    self.context(ctx, bsdf, "CLOSURE_TYPE_TRANSMISSION", f"{result}.color += {{}}.response;")
            w.line(f"{result}.color *= surfaceOpacity;")
            w.line(f"{result}.transparency = mix(vec3(1.0), {result}.transparency, surfaceOpacity);")

    @staticmethod
    def context(ctx, inp, closure_type: str, accumulate: str) -> None:
        ctx.body.line(f"ClosureData closureData = makeClosureData({closure_type}, L, V, N, P, occlusion);")
        value = ctx.emit_closures(inp, closure_type)
        ctx.body.line(accumulate.format(value))
