"""Values of nodes computed in Python, for folding: what a node gives when its inputs are constants.

Each evaluator follows the node's definition in the standard (and so what our implementations
compute): componentwise on vectors and colours, a float second operand applying to every
component. Results are rounded to float32 as a GPU holds them; a result that is not finite (or an
operation GLSL leaves undefined) is not folded. Matrices are not evaluated.
"""
import math
import struct

from .types import INT32_RANGE

VECTOR_SIZES = {"float": 1, "color3": 3, "color4": 4, "vector2": 2, "vector3": 3, "vector4": 4}


class NotFoldable(Exception):
    pass


def f32(x: float) -> float:
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        raise NotFoldable from None


def componentwise(fn, *args):
    sizes = {len(a) for a in args if isinstance(a, tuple)}
    if not sizes:
        return fn(*args)
    if len(sizes) > 1:
        raise NotFoldable
    n = sizes.pop()
    return tuple(fn(*(a[i] if isinstance(a, tuple) else a for a in args)) for i in range(n))


def _mix(bg, fg, t):
    return componentwise(lambda b, f, w: b * (1.0 - w) + f * w, bg, fg, t)


def _round(x):
    """The library's roundEven(): a value halfway between two integers to the even one (as
    Python's round)."""
    return float(round(x))


def _glsl_mod(x, y):
    return x - y * math.floor(x / y)


def _smoothstep(low, high, x):
    def one(lo, hi, v):
        if v >= hi:
            return 1.0
        if v <= lo:
            return 0.0
        t = min(max((v - lo) / (hi - lo), 0.0), 1.0)
        return t * t * (3.0 - 2.0 * t)
    return componentwise(one, low, high, x)


def _components(v) -> tuple:
    return v if isinstance(v, tuple) else (v,)


def _dot(a, b) -> float:
    return sum(x * y for x, y in zip(_components(a), _components(b), strict=True))


def _normalize(v):
    length = math.sqrt(_dot(v, v))
    return componentwise(lambda x: x / length, v)


def _convert(v, out_type: str):
    """convert: scalars broadcast, narrowing drops trailing components, widening to four adds 1
    (colour alpha, w) and to three adds 0."""
    if out_type in ("float", "integer", "boolean"):
        scalar = _components(v)[0]
        return {"float": float, "integer": int, "boolean": bool}[out_type](scalar)
    n = VECTOR_SIZES[out_type]
    if not isinstance(v, tuple):
        return tuple(float(v) for _ in range(n))
    if len(v) >= n:
        return v[:n]
    if len(v) == 2:
        return v + ((0.0,) if n == 3 else (0.0, 1.0))
    return v + (1.0,)


def _switch(inputs):
    which = inputs["which"]
    for k in range(1, 11):
        if which < k:
            return inputs.get(f"in{k}")
    return None


# The PBR library's parameter conversions, as libraries/pbrlib/genglsl/mx_pbr_utility.glsl computes
# them, each step rounded to float32.
PBR_EPS = f32(1.0e-8)  # MX_EPS


def _clamp(x: float, low: float, high: float) -> float:
    return min(max(x, low), high)


def _roughness_anisotropy(roughness: float, anisotropy: float) -> tuple:
    alpha = _clamp(f32(roughness * roughness), PBR_EPS, 1.0)
    if anisotropy > 0.0:
        aspect = f32(math.sqrt(f32(1.0 - _clamp(anisotropy, 0.0, 0.98))))
        return (min(f32(alpha / aspect), 1.0), f32(alpha * aspect))
    return (alpha, alpha)


def _roughness_dual(roughness: tuple) -> tuple:
    x, y = roughness
    return tuple(_clamp(f32(r * r), PBR_EPS, 1.0) for r in (x, x if y < 0.0 else y))


def _artistic_ior(reflectivity: tuple, edge_color: tuple) -> dict:
    """(n, k) per channel (Gulbrandsen 2014), as mx_artistic_ior() computes them."""
    ior, extinction = [], []
    for reflect, edge in zip(reflectivity, edge_color, strict=True):
        r = _clamp(reflect, 0.0, 0.99)
        sr = f32(math.sqrt(r))
        from_edge = f32(f32(1.0 - r) / f32(1.0 + r))
        from_facing = f32(f32(1.0 + sr) / f32(1.0 - sr))
        n = f32(from_facing * f32(1.0 - edge) + from_edge * edge)
        k2 = f32(f32(f32(f32(n + 1.0) * f32(n + 1.0)) * r - f32(f32(n - 1.0) * f32(n - 1.0))) / f32(1.0 - r))
        ior.append(n)
        extinction.append(f32(math.sqrt(max(k2, 0.0))))
    return {"ior": tuple(ior), "extinction": tuple(extinction)}


# The compositing nodes, as libraries/stdlib/genglsl/compositing_impl.mtlx computes them: a guarded
# division takes its guard's value (GLSL's select computes both sides, and keeps the guard's).
def _burn(b, f, w):
    return 0.0 if abs(f) < 1.0e-8 else b * (1.0 - w) + (1.0 - (1.0 - b) / f) * w


def _dodge(b, f, w):
    return 0.0 if abs(1.0 - f) < 1.0e-8 else b * (1.0 - w) + (b / (1.0 - f)) * w


def _overlay(b, f):
    return 1.0 - 2.0 * (1.0 - f) * (1.0 - b) if b >= 0.5 else 2.0 * f * b


def _unpremult(c: tuple) -> tuple:
    return c if c[3] == 0.0 else (c[0] / c[3], c[1] / c[3], c[2] / c[3], c[3])


def _disjointover(fg: tuple, bg: tuple, amount: float) -> tuple:
    coverage = fg[3] + bg[3]
    rgb = tuple(f + b for f, b in zip(fg[:3], bg[:3]))
    if coverage > 1.0:
        rgb = (0.0,) * 3 if abs(bg[3]) < 1.0e-8 else tuple(f + b * ((1.0 - fg[3]) / bg[3]) for f, b in zip(fg[:3], bg[:3]))
    return _mix(bg, rgb + (min(coverage, 1.0),), amount)


def _matte(fg: tuple, bg: tuple) -> tuple:
    return tuple(b * (1.0 - fg[3]) + f * fg[3] for f, b in zip(fg[:3], bg[:3])) + (fg[3] + bg[3] * (1.0 - fg[3]),)


def _scaled(c: tuple, k: float) -> tuple:
    return tuple(x * k for x in c)


def _composite(category: str, i: dict):
    """The alpha compositing operators on color4: what is mixed over bg by `mix`."""
    fg, bg = i["fg"], i["bg"]
    over = {"in": lambda: _scaled(fg, bg[3]), "mask": lambda: _scaled(bg, fg[3]),
            "out": lambda: _scaled(fg, 1.0 - bg[3]),
            "over": lambda: tuple(f + b * (1.0 - fg[3]) for f, b in zip(fg, bg)), "matte": lambda: _matte(fg, bg)}
    return _mix(bg, over[category](), i["mix"])


COMPOSITES = ("in", "mask", "out", "over", "matte")

MULTIPLE_OUTPUTS = {"artistic_ior": lambda i: _artistic_ior(i["reflectivity"], i["edge_color"])}

# Evaluators other modules register for the nodes they make (cms/ocio.py: its transform nodes,
# computed by OCIO's CPU processor): category -> fn(inputs, output type) -> value.
REGISTERED: dict = {}
CONDITIONS = {"ifgreater": lambda a, b: a > b, "ifgreatereq": lambda a, b: a >= b, "ifequal": lambda a, b: a == b}

UNARY = {
    "absval": abs, "floor": math.floor, "ceil": math.ceil, "sqrt": math.sqrt, "exp": math.exp, "ln": math.log,
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": math.asin, "acos": math.acos,
    "sign": lambda x: (x > 0) - (x < 0), "round": _round,
    "fract": lambda x: x - math.floor(x),
}
BINARY = {
    "add": lambda a, b: a + b, "subtract": lambda a, b: a - b, "multiply": lambda a, b: a * b,
    "divide": lambda a, b: a / b, "modulo": _glsl_mod, "power": math.pow, "min": min, "max": max,
}


def _evaluate(category: str, i: dict, out_type: str):
    if category in REGISTERED:
        return REGISTERED[category](i, out_type)
    if category in UNARY:
        return componentwise(UNARY[category], i["in"])
    if category in BINARY:
        return componentwise(BINARY[category], i["in1"], i["in2"])
    if category == "atan2":
        return componentwise(math.atan2, i["iny"], i["inx"])
    if category == "clamp":
        return componentwise(lambda x, lo, hi: min(max(x, lo), hi), i["in"], i["low"], i["high"])
    if category == "invert":
        return componentwise(lambda x, amount: amount - x, i["in"], i["amount"])
    if category in ("mix", "dot"):
        return _mix(i["bg"], i["fg"], i["mix"]) if category == "mix" else i["in"]
    if category == "remap":
        return componentwise(lambda x, il, ih, ol, oh: ol + (x - il) * (oh - ol) / (ih - il),
                             i["in"], i["inlow"], i["inhigh"], i["outlow"], i["outhigh"])
    if category == "smoothstep":
        return _smoothstep(i["low"], i["high"], i["in"])
    if category in ("plus", "minus", "difference", "screen"):
        blend = {"plus": lambda b, f: b + f, "minus": lambda b, f: b - f, "difference": lambda b, f: abs(b - f),
                 "screen": lambda b, f: 1.0 - (1.0 - f) * (1.0 - b)}[category]
        return _mix(i["bg"], componentwise(blend, i["bg"], i["fg"]), i["mix"])
    if category == "burn":
        return componentwise(_burn, i["bg"], i["fg"], i["mix"])
    if category == "dodge":
        return componentwise(_dodge, i["bg"], i["fg"], i["mix"])
    if category == "overlay":
        return _mix(i["bg"], componentwise(_overlay, i["bg"], i["fg"]), i["mix"])
    if category in COMPOSITES:
        return _composite(category, i)
    if category == "disjointover":
        return _disjointover(i["fg"], i["bg"], i["mix"])
    if category == "premult":
        c = i["in"]
        return _scaled(c[:3], c[3]) + (c[3],)
    if category == "unpremult":
        return _unpremult(i["in"])
    if category == "inside":
        return componentwise(lambda x, m: x * m, i["in"], i["mask"])
    if category == "outside":
        return componentwise(lambda x, m: x * (1.0 - m), i["in"], i["mask"])
    if category in CONDITIONS:
        taken = CONDITIONS[category](i["value1"], i["value2"])
        return taken if out_type == "boolean" else (i["in1"] if taken else i["in2"])
    if category == "switch":
        return _switch(i)
    if category in ("and", "or", "xor", "not"):
        return {"and": lambda: i["in1"] and i["in2"], "or": lambda: i["in1"] or i["in2"],
                "xor": lambda: i["in1"] != i["in2"], "not": lambda: not i["in"]}[category]()
    if category in ("maxcomponent", "mincomponent"):
        return (max if category == "maxcomponent" else min)(i["in"])
    if category == "magnitude":
        return math.sqrt(_dot(i["in"], i["in"]))
    if category == "distance":
        d = componentwise(lambda a, b: a - b, i["in1"], i["in2"])
        return math.sqrt(_dot(d, d))
    if category == "dotproduct":
        return _dot(i["in1"], i["in2"])
    if category == "normalize":
        return _normalize(i["in"])
    if category == "crossproduct":
        (ax, ay, az), (bx, by, bz) = i["in1"], i["in2"]
        return (ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx)
    if category == "convert":
        return _convert(i["in"], out_type)
    if category == "extract":
        return _components(i["in"])[int(i["index"])]
    if category in ("combine2", "combine3", "combine4"):
        return tuple(c for k in range(1, int(category[-1]) + 1) for c in _components(i[f"in{k}"]))
    if category == "roughness_anisotropy":
        return _roughness_anisotropy(i["roughness"], i["anisotropy"])
    if category == "roughness_dual":
        return _roughness_dual(i["roughness"])
    if category == "luminance":
        rgb = _components(i["in"])
        y = _dot(rgb[:3], i["lumacoeffs"])
        return (y, y, y) if len(rgb) == 3 else (y, y, y, rgb[3])
    raise NotFoldable


def _typed(value, type_name: str):
    """The value as the output type holds it (float32 components); NotFoldable when it is not finite."""
    if type_name == "integer":
        if int(value) not in INT32_RANGE:  # the GPU's int wraps; computed there, not here
            raise NotFoldable
        return int(value)
    if type_name == "boolean":
        return bool(value)
    if type_name not in VECTOR_SIZES or value is None:
        raise NotFoldable
    if isinstance(value, tuple) != (type_name != "float"):
        raise NotFoldable
    comps = tuple(f32(float(c)) for c in _components(value))
    if not all(math.isfinite(c) for c in comps):
        raise NotFoldable
    comps = tuple(shortest_float32(c) for c in comps)
    return comps if isinstance(value, tuple) else comps[0]


def evaluate_outputs(category: str, inputs: dict, outputs: list[tuple[str, str]]) -> dict:
    """{output name: value} of a node from constant inputs: separate2/3/4 give one component per
    output, every other node its one output. NotFoldable when this node cannot be computed here."""
    try:
        if category in ("separate2", "separate3", "separate4"):
            comps = _components(inputs["in"])
            return {name: _typed(comps[k], t) for k, (name, t) in enumerate(outputs)}
        if category in MULTIPLE_OUTPUTS:
            values = MULTIPLE_OUTPUTS[category](inputs)
            return {name: _typed(values[name], t) for name, t in outputs}
        if len(outputs) != 1:
            raise NotFoldable
        (name, t), = outputs
        return {name: _typed(_evaluate(category, inputs, t), t)}
    except (ValueError, ZeroDivisionError, OverflowError, TypeError, KeyError, IndexError):
        raise NotFoldable from None


def shortest_float32(x: float) -> float:
    """The shortest decimal that is the same float32: folded literals stay readable."""
    for digits in range(1, 10):
        candidate = float(f"{x:.{digits}g}")
        if f32(candidate) == x:
            return candidate
    return x
