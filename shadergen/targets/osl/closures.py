"""OSL's closure convention: BSDF, EDF and VDF nodes are OSL closures, values of the language that
the renderer integrates (no light loop, no environment, no evaluated lobes). Each closure node
becomes one `closure color` variable, written where the graph orders it:

- the lobes are the MaterialX closures OSL 1.13 declares in its `stdosl.h`
  (`oren_nayar_diffuse_bsdf`, `burley_diffuse_bsdf`, `translucent_bsdf`, `dielectric_bsdf`,
  `conductor_bsdf`, `generalized_schlick_bsdf`, `subsurface_bssrdf`, `sheen_bsdf`, `uniform_edf`,
  `anisotropic_vdf`), each scaled by its node's `weight`; the thin film the thin-film pass gave a
  microfacet lobe is its optional `thinfilm_thickness` and `thinfilm_ior` arguments;
- `layer` is OSL's `layer(top, base)`; `mix`, `add` and `multiply` are weighted sums and products
  of closures, which OSL has as operators;
- a surface is `opacity * (bsdf + edf) + (1 - opacity) * transparent_bsdf()`, a volume `vdf + edf`,
  an unlit surface (`surface_unlit`, a value converted to a surfaceshader) a `uniform_edf` of its
  colour beside its `transparent_bsdf()`.

What a stdosl.h closure lacks is mapped from the node's definition: `scatter_mode` picks which of
the reflection and transmission tints is kept; `subsurface_bsdf`'s mean free path `radius` is the
extinction of `subsurface_bssrdf` (transmission colour exp(-1 / radius) at depth 1); an
`absorption_vdf` is an `anisotropic_vdf` that scatters nothing; `anisotropic_vdf`'s absorption and
scattering are the extinction (their sum) and albedo (scattering over extinction); the emitters
that stdosl.h has no closure for are `uniform_edf` weighted by their radiance towards the viewer
(`-I`): `conical_edf` by its falloff between the cone angles, `generalized_schlick_edf` by its
Fresnel curve. `generalized_schlick_bsdf`'s `color82`, `oren_nayar_diffuse_bsdf`'s
`energy_compensation`, `sheen_bsdf`'s `mode` and the `retroreflective` flags have no argument in
stdosl.h and are left to the renderer. `chiang_hair_bsdf` is the hair closure later OSL releases
declare (the shader declares it where OSL 1.13's stdosl.h lacks it); each roughness vector2 is its
(longitudinal, azimuthal) pair. `measured_edf` has no closure: it is refused.
"""
from ...code import ir
from ...errors import ShaderGenError
from ...nodes.base import GraphFunctionImpl
from ..closures import ClosureConvention

CLOSURE = "BSDF"  # the IR type every closure variable is declared with (OSL: `closure color`)
# the outputs of the nodes this convention writes, and the IR type each is declared with
DECLARED = {"BSDF": CLOSURE, "EDF": CLOSURE, "VDF": CLOSURE, "surfaceshader": "surfaceshader",
            "volumeshader": "volumeshader", "lightshader": "lightshader", "material": "surfaceshader"}


def call(name: str, args: list, type_name: str = CLOSURE) -> ir.Call:
    return ir.Call(name, list(args), type=type_name, builtin=True)


def number(value: float) -> ir.Literal:
    return ir.Literal(float(value), None, type="float")


def string(text: str) -> ir.Literal:
    return ir.Literal(None, f'"{text}"', type="string")


def binary(op: str, left, right, type_name: str):
    return ir.Binary(op, left, right, type=type_name)


def component(value, name: str) -> ir.Expr:
    """A component of a vector; of a constructor, the argument itself."""
    if type(value) is ir.Construct and all(a.type == "float" for a in value.args):
        return value.args[0] if len(value.args) == 1 else value.args["xyzw".index(name)]
    return ir.Field(value, name, type="float", swizzle=True)


def vec3(value: float) -> ir.Expr:
    return ir.Construct("vec3", [number(value)], exact=True)


def is_zero(value) -> bool:
    """Whether `value` is a literal 0 (or a vector of literal 0s)."""
    if type(value) is ir.Literal:
        return value.value == 0
    if type(value) is ir.Construct and value.type in ("float", "vec3"):
        return all(is_zero(a) for a in value.args)
    return False


def is_one(value) -> bool:
    return type(value) is ir.Literal and value.value == 1


def one_minus(weight):
    """`1 - weight`, folded for a literal."""
    if type(weight) is ir.Literal:
        return number(1.0 - float(weight.value))
    return binary("-", number(1.0), weight, "float")


def scaled(weight, closure):
    """`weight * closure`, without a weight of 1; None (no closure) for none or a weight of 0."""
    if closure is None or is_zero(weight):
        return None
    if weight.type == "vec3":  # (OSL weights a closure by a color, not by a vector)
        weight = call("color", [weight], "vec3")
    return closure if is_one(weight) else binary("*", weight, closure, CLOSURE)


def summed(*closures):
    """The sum of the closures that are there; None for none."""
    present = [c for c in closures if c is not None]
    if not present:
        return None
    total = present[0]
    for c in present[1:]:
        total = binary("+", total, c, CLOSURE)
    return total


class OslClosureConvention(ClosureConvention):
    values = True  # closure nodes are emitted once, as values (emit_closure), not per shading context

    def claims(self, node) -> bool:
        """Every node whose output is a closure or a shader made of them (surface, volume, material)."""
        return any(o.type in DECLARED for o in node.outputs.values())

    def arguments(self) -> list[ir.Expr]:
        return []  # no shading context: a function of closures takes its inputs alone

    def output_closure(self, ctx, name: str) -> bool:
        return ctx.pixel.blocks["Outputs"].variables[name].type != "color4"  # a shader or closure, as it is

    # -- closure nodes -----------------------------------------------------------------------------
    def emit_closure(self, ctx, node) -> None:
        """The closure of one claimed node (`closure_<category>` below), as a `closure color`
        variable; a nodegraph of closures written as a function is called as one."""
        emit = getattr(self, "closure_" + node.category, None)
        if emit is None:
            if isinstance(node.impl, GraphFunctionImpl):  # a nodegraph written once as a function
                node.impl.emit_function_call(node, ctx)
                return
            raise ShaderGenError("unsupported_node", f"OSL 1.13 has no closure for a '{node.category}' node", node.path)
        value = emit(ctx, node, lambda name: ctx.value(node.inputs[name]))
        out = next(iter(node.outputs.values()))
        declared = DECLARED[out.type]
        if type(value) is ir.Name:  # another closure as it is (a surface of a BSDF alone): no copy
            ctx.vars[id(out)] = ir.replace(value, type=declared)
            return
        value = ir.Literal(0, "0", type=declared) if value is None else ir.replace(value, type=declared)
        ctx.vars[id(out)] = ctx.body.declare(declared, ctx.namer(f"{ctx.names.node(node)}_{out.name}"), value)

    def closure_input(self, ctx, node, name: str):
        """A closure input's value; None where nothing is connected (no closure)."""
        inp = node.inputs.get(name)
        if inp is None or (inp.connection is None and inp.socket is None and not inp.public):
            return None
        return ctx.value(inp)

    @staticmethod
    def frame(v) -> tuple:
        """N and the tangent a microfacet lobe takes, and its roughness along each."""
        roughness = v("roughness")
        return v("normal"), v("tangent"), component(roughness, "x"), component(roughness, "y")

    @staticmethod
    def tints(v, tint) -> tuple:
        """(reflection tint, transmission tint) of a lobe's `scatter_mode` (R 0, T 1, RT 2)."""
        mode = v("scatter_mode")
        if type(mode) is ir.Literal:
            return (vec3(0.0) if mode.value == 1 else tint), (vec3(0.0) if mode.value == 0 else tint)
        reflect = ir.Select(binary("!=", mode, ir.Literal(1, None, type="int"), "bool"), tint, vec3(0.0), type="vec3")
        transmit = ir.Select(binary("!=", mode, ir.Literal(0, None, type="int"), "bool"), tint, vec3(0.0), type="vec3")
        return reflect, transmit

    @staticmethod
    def film(v) -> list:
        """The optional thin-film arguments, where the lobe may have a film."""
        thickness = v("thinfilm_thickness")
        if is_zero(thickness):
            return []
        return [string("thinfilm_thickness"), thickness, string("thinfilm_ior"), v("thinfilm_ior")]

    def closure_oren_nayar_diffuse_bsdf(self, ctx, node, v):
        return scaled(v("weight"), call("oren_nayar_diffuse_bsdf", [v("normal"), v("color"), v("roughness")]))

    def closure_chiang_hair_bsdf(self, ctx, node, v):
        lobes = [v(f"roughness_{lobe}") for lobe in ("R", "TT", "TRT")]
        return call("chiang_hair_bsdf", [v("normal"), v("curve_direction"), v("tint_R"), v("tint_TT"), v("tint_TRT"),
                                         v("ior"), *(component(r, "x") for r in lobes),
                                         *(component(r, "y") for r in lobes), v("cuticle_angle"),
                                         v("absorption_coefficient")])

    def closure_burley_diffuse_bsdf(self, ctx, node, v):
        return scaled(v("weight"), call("burley_diffuse_bsdf", [v("normal"), v("color"), v("roughness")]))

    def closure_translucent_bsdf(self, ctx, node, v):
        return scaled(v("weight"), call("translucent_bsdf", [v("normal"), v("color")]))

    def closure_sheen_bsdf(self, ctx, node, v):
        return scaled(v("weight"), call("sheen_bsdf", [v("normal"), v("color"), v("roughness")]))

    def closure_dielectric_bsdf(self, ctx, node, v):
        n, t, rx, ry = self.frame(v)
        reflect, transmit = self.tints(v, v("tint"))
        return scaled(v("weight"), call("dielectric_bsdf", [n, t, reflect, transmit, rx, ry, v("ior"), string("ggx")]
                                        + self.film(v)))

    def closure_conductor_bsdf(self, ctx, node, v):
        n, t, rx, ry = self.frame(v)
        return scaled(v("weight"), call("conductor_bsdf", [n, t, rx, ry, v("ior"), v("extinction"), string("ggx")]
                                        + self.film(v)))

    def closure_generalized_schlick_bsdf(self, ctx, node, v):
        n, t, rx, ry = self.frame(v)
        reflect, transmit = self.tints(v, vec3(1.0))
        return scaled(v("weight"), call("generalized_schlick_bsdf", [
            n, t, reflect, transmit, rx, ry, v("color0"), v("color90"), v("exponent"), string("ggx")] + self.film(v)))

    def closure_subsurface_bsdf(self, ctx, node, v):
        # mean free path r per channel: extinction 1 / r, so white light keeps exp(-1 / r) at depth 1
        path = binary("+", v("radius"), number(1e-6), "vec3")
        colour = call("exp", [binary("/", number(-1.0), path, "vec3")], "vec3")
        return scaled(v("weight"), call("subsurface_bssrdf", [v("normal"), v("color"), number(1.0), colour,
                                                              v("anisotropy")]))

    def closure_uniform_edf(self, ctx, node, v):
        return call("uniform_edf", [v("color")])

    def closure_conical_edf(self, ctx, node, v):
        # the radiance towards the viewer: full inside the inner cone, fading to 0 at the outer one
        facing = call("dot", [call("normalize", [v("normal")], "vec3"), ir.Unary("-", ir.Name("I", "builtin", type="vec3"),
                                                                                   type="vec3")], "float")
        inner = call("cos", [call("radians", [v("inner_angle")], "float")], "float")
        outer = call("cos", [call("radians", [call("max", [v("outer_angle"), v("inner_angle")], "float")], "float")],
                     "float")
        falloff = call("smoothstep", [outer, inner, facing], "float")
        return call("uniform_edf", [binary("*", falloff, v("color"), "vec3")])

    def closure_generalized_schlick_edf(self, ctx, node, v):
        base = self.closure_input(ctx, node, "base")
        if base is None:
            return None
        facing = call("abs", [call("dot", [ir.Name("N", "builtin", type="vec3"),
                                           ir.Unary("-", ir.Name("I", "builtin", type="vec3"), type="vec3")], "float")],
                      "float")
        curve = call("pow", [binary("-", number(1.0), facing, "float"), v("exponent")], "float")
        return scaled(call("mix", [v("color0"), v("color90"), curve], "vec3"), base)

    def closure_absorption_vdf(self, ctx, node, v):
        return call("anisotropic_vdf", [vec3(0.0), v("absorption"), number(0.0)])

    def closure_anisotropic_vdf(self, ctx, node, v):
        extinction = binary("+", v("absorption"), v("scattering"), "vec3")
        albedo = binary("/", v("scattering"), extinction, "vec3")  # (OSL's division by 0 gives 0)
        return call("anisotropic_vdf", [albedo, extinction, v("anisotropy")])

    def closure_layer(self, ctx, node, v):
        top, base = self.closure_input(ctx, node, "top"), self.closure_input(ctx, node, "base")
        if top is None or base is None:
            return top if base is None else base
        return call("layer", [top, base])

    def closure_mix(self, ctx, node, v):
        weight = v("mix")
        fg, bg = self.closure_input(ctx, node, "fg"), self.closure_input(ctx, node, "bg")
        return summed(scaled(weight, fg), scaled(one_minus(weight), bg))

    def closure_add(self, ctx, node, v):
        return summed(self.closure_input(ctx, node, "in1"), self.closure_input(ctx, node, "in2"))

    def closure_multiply(self, ctx, node, v):
        return scaled(v("in2"), self.closure_input(ctx, node, "in1"))

    # -- shaders -----------------------------------------------------------------------------------
    @staticmethod
    def cutout(opacity, surface):
        """`opacity * surface + (1 - opacity) * transparent_bsdf()`: what a surface lets through
        is OSL's straight transmission."""
        if is_one(opacity):
            return surface
        return summed(scaled(opacity, surface),
                      scaled(one_minus(opacity), call("transparent_bsdf", [])))

    def closure_surface(self, ctx, node, v):
        bsdf, edf = self.closure_input(ctx, node, "bsdf"), self.closure_input(ctx, node, "edf")
        return self.cutout(v("opacity"), summed(bsdf, edf))

    def closure_surface_unlit(self, ctx, node, v):
        emitted = call("uniform_edf", [binary("*", v("emission"), v("emission_color"), "vec3")])
        transmitted = scaled(binary("*", v("transmission"), v("transmission_color"), "vec3"),
                             call("transparent_bsdf", []))
        return self.cutout(v("opacity"), summed(emitted, transmitted))

    def closure_convert(self, ctx, node, v):
        """A value as an unlit surface emitting it (a fourth component is the opacity)."""
        value = v("in")
        t = value.type
        if t in ("int", "bool"):
            value, t = ir.Convert("float", value), "float"
        if t == "float":
            return call("uniform_edf", [ir.Construct("vec3", [value])])
        if t == "vec2":
            return call("uniform_edf", [ir.Construct("vec3", [value, number(0.0)])])
        if t == "vec4":
            rgb = ir.Field(value, "xyz", type="vec3", swizzle=True)
            return self.cutout(component(value, "w"), call("uniform_edf", [rgb]))
        return call("uniform_edf", [value])

    def closure_dot(self, ctx, node, v):
        return self.closure_input(ctx, node, "in")

    def closure_surfacematerial(self, ctx, node, v):
        return self.closure_input(ctx, node, "surfaceshader")

    def closure_volumematerial(self, ctx, node, v):
        return self.closure_input(ctx, node, "volumeshader")

    def closure_volume(self, ctx, node, v):
        return summed(self.closure_input(ctx, node, "vdf"), self.closure_input(ctx, node, "edf"))

    def closure_light(self, ctx, node, v):
        """A light: its EDF scaled by intensity * 2^exposure."""
        scale = binary("*", v("intensity"), call("exp2", [v("exposure")], "float"), "float")
        return scaled(scale, self.closure_input(ctx, node, "edf"))
