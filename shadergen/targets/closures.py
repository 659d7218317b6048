"""The hardware targets' closure convention, in the IR: how a surface shader evaluates its BSDF and
EDF graphs (seed 3.5, 4.5), shared by every target whose closures are functions filling a
`BSDF` through a shading context (GLSL, ESSL, WGSL; OSL's closures are values of the language
and have a convention of their own).

A closure function takes a `ClosureData` first: the context it is called for (reflection under
one light, the environment, emission, transmission along the view direction) with the light and
view directions, the normal, the position and the occlusion. The surface declares one per context
and accumulates what each returns; lights are sampled by `sampleLightSource`, which dispatches on
the light's type id to the light shaders the libraries implement.
"""
from ..code import build, ir
from ..shader import PIXEL, Variable

LIGHT_DATA_MEMBERS = (("type", "integer"), ("position", "vector3"), ("direction", "vector3"), ("color", "color3"),
                      ("intensity", "float"), ("decay_rate", "float"), ("inner_angle", "float"),
                      ("outer_angle", "float"))
CONTEXTS = {"reflection": "CLOSURE_TYPE_REFLECTION", "indirect": "CLOSURE_TYPE_INDIRECT",
            "emission": "CLOSURE_TYPE_EMISSION", "transmission": "CLOSURE_TYPE_TRANSMISSION"}
COMMENTS = {"indirect": "environment", "emission": "emission",
            "transmission": "transmission, seen along the view direction"}


def local(name: str, type: str) -> ir.Name:
    return build.name(name, "local", type)


def constant(name: str) -> ir.Name:
    return build.name(name, "global", "int")


class ClosureConvention:
    values = False  # closures are functions of a shading context here, not values of the language

    def claims(self, node) -> bool:
        """Whether the convention writes `node` itself (emit_closure) where the graph orders it:
        none here, the surface evaluates its closures per context."""
        return False

    def arguments(self) -> list[ir.Expr]:
        """What a closure function takes before its inputs: the shading context."""
        return [local("closureData", "ClosureData")]

    def emit_surface(self, ctx, result: str, opacity: ir.Expr, position: ir.Expr, normal: ir.Expr,
                     contexts: list[tuple[str, object]]) -> None:
        """A surface shader: its closure inputs evaluated once per shading context, in order.
        `contexts`: (context, closure input), the context one of "reflection" (once per light),
        "indirect" (the environment), "emission", "transmission"."""
        b = ctx.body
        shader = b.declare("surfaceshader", result, build.construct(
            "surfaceshader", build.construct("vec3", build.number(0.0)), build.construct("vec3", build.number(0.0))))
        color = build.field(shader, "color")
        with b.scope():
            n = b.declare("vec3", "N", build.call("normalize", normal))
            v = b.declare("vec3", "V", build.call("normalize", build.binary(
                "-", build.name("u_viewPosition", "uniform", "vec3"), position)))
            p = b.declare("vec3", "P", position)
            light = b.declare("vec3", "L", build.construct("vec3", build.number(0.0)))
            occlusion = b.declare("float", "occlusion", build.number(1.0))
            surface_opacity = b.declare("float", "surfaceOpacity", opacity)
            frame = (light, v, n, p, occlusion)
            point: list[ir.Expr] = []

            def point_arguments() -> list[ir.Expr]:  # the closure data lobes are prepared with
                if not point:
                    b.comment("lobes prepared once per shading point, before any light")
                    point.append(b.declare("ClosureData", "pointData", build.construct(
                        "ClosureData", constant("CLOSURE_TYPE_DEFAULT"), *frame)))
                return point

            for inp in {id(inp): inp for context, inp in contexts if context != "emission"}.values():
                ctx.emit_lobes(inp, point_arguments)
            for context, inp in contexts:
                if context == "reflection":
                    with b.count_loop("activeLightIndex", build.call("numActiveLightSources")):
                        light_shader = b.declare("lightshader", "lightShader")
                        data = build.index(build.name("u_lightData", "uniform", "LightData[]"),
                                           local("activeLightIndex", "int"))
                        b.call("sampleLightSource", data, position, light_shader)
                        b.assign(light, build.field(light_shader, "direction"))
                        bsdf = self._context(ctx, inp, context, frame)
                        b.assign(color, build.binary("*", build.field(light_shader, "intensity"),
                                                     build.field(bsdf, "response")), "+=")
                    continue
                with b.scope(COMMENTS[context]):
                    value = self._context(ctx, inp, context, frame)
                    if context == "emission":
                        b.assign(color, value, "+=")
                    elif context == "indirect":
                        b.assign(color, build.binary("*", occlusion, build.field(value, "response")), "+=")
                    else:
                        b.assign(color, build.field(value, "response"), "+=")
            b.assign(color, surface_opacity, "*=")
            transparency = build.field(shader, "transparency")
            b.assign(transparency, build.call("mix", build.construct("vec3", build.number(1.0)), transparency,
                                              surface_opacity))

    def _context(self, ctx, inp, context: str, frame) -> ir.Expr:
        ctx.body.declare("ClosureData", "closureData",
                         build.construct("ClosureData", constant(CONTEXTS[context]), *frame))
        return ctx.emit_closures(inp, context)

    def emit_light_dispatch(self, ctx, lights: list[tuple[int, str]]) -> None:
        """LightData members, numActiveLightSources() and sampleLightSource() calling each light
        shader by its type id."""
        ctx.used_types.update(("LightData", "lightshader"))
        for name, type_name in LIGHT_DATA_MEMBERS:
            ctx.add_variable(PIXEL, "LightData", Variable(name, type_name))
        count = build.Builder()
        count.ret(build.call("min", build.name("u_numActiveLightSources", "uniform", "int"),
                             build.name("MAX_LIGHT_SOURCES", "global", "int")))
        ctx.add_function(build.function("int", "numActiveLightSources", [], count.block()))
        sample = build.Builder()
        light, position, result = (build.name(n, "param", t) for n, t in
                                   (("light", "LightData"), ("position", "vec3"), ("result", "lightshader")))
        zero = build.construct("vec3", build.number(0.0))
        sample.assign(build.field(result, "intensity"), zero)
        sample.assign(build.field(result, "direction"), zero)
        with sample.chain() as chain:
            for type_id, function in lights:
                with chain.clause(build.binary("==", build.field(light, "type"), build.integer(type_id))):
                    sample.call(function, light, position, result)
        ctx.add_function(build.function("void", "sampleLightSource", [
            ("in", "LightData", "light"), ("in", "vec3", "position"), ("out", "lightshader", "result")],
            sample.block()))
