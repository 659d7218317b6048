"""Documents whose names are hostile to shading languages, and the check that their shaders compile.

A case is a MaterialX document or a USD layer whose every name (nodes, node graphs, their inputs
and outputs, a document's own node definitions, materials, shaders, geometric properties, prims)
is drawn from: Unicode letters, names starting with a digit, reserved words and built-in names
of GLSL, ESSL and WGSL, the targets' and libraries' own names, names that collide once cleaned
(`a-b`, `a_b`, `a.b`) and long names. Names are drawn from a seeded generator, so a seed and a
count give the same cases everywhere.

    from name_cases import name_cases, ShaderChecker
    for case in name_cases(seed=21, count=50):     # case.document (bytes), case.format ("mtlx" | "usda")
        records = ...                              # generate every element, every target
        problems = checker.problems(records)       # [] when every record generated and compiled

Used by tests/core/test_name_fuzz.py, tests/faults/test_name_faults.py and `bench/fuzz.py --kind
names`, whose kinds are (count, seed -> (label, body)) and (client, body -> answer): here
`http_cases` and `post_case`, the answer judged by `judge_answer` (a compile failure is no HTTP
status, so the contract's judge alone would not see it).
"""
import importlib
import os
import random
import shutil
import subprocess
import tempfile
import threading
from dataclasses import dataclass
from xml.sax.saxutils import quoteattr

CONTENT_TYPES = {"mtlx": "application/xml", "usda": "model/vnd.usda"}
TARGETS = ("glsl", "essl", "wgsl")
INTERFACES = ("complete", "specialized")
# targets checked by a module of their own: `errors(label -> (stage, source)) -> label -> message`
# (MSL's read alone here: its cross-check against naga needs the WGSL, tests/core/test_cfamily_targets.py)
CHECK_MODULES = {"hlsl": "shadergen.targets.hlsl.check", "slang": "shadergen.targets.slang.check",
                 "msl": "shadergen.targets.msl.check"}

UNICODE = ["Ω材質", "é", "Жёлтый", "名前", "ñandú", "σ", "Über", "ℕ", "ǅx", "مادة", "गुण", "Ωmega"]
# keywords, reserved words, built-in functions and types of GLSL/ESSL and WGSL, and what the
# targets and libraries name themselves
RESERVED = ["main", "texture", "sample", "mix", "dot", "normalize", "float", "vec3", "in", "out", "uniform", "input",
            "fn", "let", "var", "loop", "struct", "select", "f32", "vec3f", "textureSample", "mat4x4f", "override",
            "enable", "gl_Position", "gl_FragCoord", "__x", "_", "mx_image_color3", "mx_srgb_texture_to_lin_rec709",
            "M_PI", "u_time", "u_envRadiance", "i_position", "i_texcoord_0", "vd", "pu", "vin", "N", "V", "L",
            "closureData", "BSDF", "ClosureData", "LightData", "sampler", "x_sampler", "common", "partition",
            "active", "self", "type", "position", "result", "vertexMain", "fragmentMain", "sampleLightSource",
            "hPositionWorld", "surfaceshader", "inverseSqrt", "atan2", "saturate", "bitcast", "asm", "goto"]
COLLIDING = ["a-b", "a_b", "a.b", "a__b", "a_-b", "a-_b", "Ω", "_u03A9", "u03A9", "x1", "x", "x_1"]
WORDS = ["base", "coat", "tint", "Ωx", "main", "a"]


def random_name(rng: random.Random) -> str:
    kind = rng.randrange(5)
    if kind == 0:
        return rng.choice(UNICODE) + rng.choice(["", "", str(rng.randrange(10))])
    if kind == 1:
        return f"{rng.randrange(100)}{rng.choice(WORDS)}"
    if kind == 2:
        return rng.choice(RESERVED)
    if kind == 3:
        return rng.choice(COLLIDING)
    return rng.choice(WORDS) * rng.randint(40, 300)  # 40 to 1,800 characters


@dataclass
class NameCase:
    label: str
    document: bytes
    format: str  # "mtlx" or "usda"


def name_cases(seed: int, count: int):
    """`count` cases, MaterialX and USD in turn, from `seed`."""
    rng = random.Random(seed)
    for i in range(count):
        if i % 2 == 0:
            yield NameCase(f"mtlx #{i}", mtlx_document(rng).encode(), "mtlx")
        else:
            yield NameCase(f"usda #{i}", usda_document(rng), "usda")


class Names:
    """Distinct draws where the document needs them (siblings of one scope)."""

    def __init__(self, rng: random.Random, valid=lambda name: True):
        self.rng, self.valid, self.taken = rng, valid, set()

    def __call__(self) -> str:
        for _ in range(100):
            name = random_name(self.rng)
            if name not in self.taken and self.valid(name):
                self.taken.add(name)
                return name
        name = f"fallback{len(self.taken)}"
        self.taken.add(name)
        return name


# -- MaterialX -----------------------------------------------------------------------------------
def mtlx_document(rng: random.Random) -> str:
    """A document defining its own node (nodedef and nodegraph, used three times alike so that it is
    written as a function), a node graph with interface inputs, a geometric property, a texture,
    and either a material on a surface shader or only graph outputs: every name drawn."""
    name = Names(rng, lambda n: "/" not in n)
    q = quoteattr
    category = f"fz_{rng.randrange(10**6)}"  # an XML element name: drawn names would not all parse
    nd, ng, g = name(), name(), name()
    p1, p2, nd_out = name(), name(), name()
    iface, gp_node, graph_out = name(), name(), name()
    uses = [name() for _ in range(3)]
    body1, body2 = name(), name()
    geomprop = random_name(rng)
    parts = [
        f'<nodedef name={q(nd)} node="{category}">'
        f'<input name={q(p1)} type="color3" value="0.5, 0.4, 0.3"/><input name={q(p2)} type="float" value="0.8"/>'
        f'<output name={q(nd_out)} type="color3"/></nodedef>',
        f'<nodegraph name={q(ng)} nodedef={q(nd)}>'
        f'<multiply name={q(body1)} type="color3"><input name="in1" type="color3" interfacename={q(p1)}/>'
        f'<input name="in2" type="float" interfacename={q(p2)}/></multiply>'
        f'<power name={q(body2)} type="color3"><input name="in1" type="color3" nodename={q(body1)}/>'
        f'<input name="in2" type="float" interfacename={q(p2)}/></power>'
        f'<output name={q(nd_out)} type="color3" nodename={q(body2)}/></nodegraph>',
    ]
    nodes = [f'<input name={q(iface)} type="color3" value="0.2, 0.6, 0.9"/>',
             f'<geompropvalue name={q(gp_node)} type="color3"><input name="geomprop" type="string" value={q(geomprop)}/>'
             f'<input name="default" type="color3" value="0.1, 0.1, 0.1"/></geompropvalue>']
    previous = gp_node
    for k, use in enumerate(uses):
        source = f'interfacename={q(iface)}' if k == 0 else f'nodename={q(previous)}'
        nodes.append(f'<{category} name={q(use)} type="color3"><input name={q(p1)} type="color3" {source}/>'
                     f'<input name={q(p2)} type="float" value="{0.5 + k / 4}"/></{category}>')
        previous = use
    image, last = name(), name()  # a texture: a filename uniform, in WGSL a texture and `<name>_sampler`
    nodes.append(f'<image name={q(image)} type="color3"><input name="file" type="filename" value="checker.png"/>'
                 '</image>')
    nodes.append(f'<add name={q(last)} type="color3"><input name="in1" type="color3" nodename={q(previous)}/>'
                 f'<input name="in2" type="color3" nodename={q(image)}/></add>')
    nodes.append(f'<output name={q(graph_out)} type="color3" nodename={q(last)}/>')
    parts.append(f'<nodegraph name={q(g)}>{"".join(nodes)}</nodegraph>')
    if rng.random() < 0.7:
        shader, material = name(), name()
        surface = rng.choice([("standard_surface", "base_color"), ("UsdPreviewSurface", "diffuseColor")])
        parts.append(f'<{surface[0]} name={q(shader)} type="surfaceshader">'
                     f'<input name="{surface[1]}" type="color3" nodegraph={q(g)} output={q(graph_out)}/></{surface[0]}>')
        parts.append(f'<surfacematerial name={q(material)} type="material">'
                     f'<input name="surfaceshader" type="surfaceshader" nodename={q(shader)}/></surfacematerial>')
    return '<?xml version="1.0" encoding="UTF-8"?>\n<materialx version="1.39">\n' + "\n".join(parts) + "\n</materialx>\n"


# -- USD -------------------------------------------------------------------------------------------
def usda_document(rng: random.Random) -> bytes:
    """A layer of one or two materials (prim and input names drawn, where usd-core allows them),
    each a UsdPreviewSurface whose roughness is a primvar (its name drawn) scaled inside a NodeGraph
    by the graph's interface input, whose colour is an input of the material's interface and whose
    emission a texture."""
    from pxr import Sdf, Usd, UsdShade

    valid = Sdf.Path.IsValidIdentifier
    stage = Usd.Stage.CreateInMemory()
    root = Names(rng, valid)()
    looks = Names(rng, valid)
    for _ in range(rng.randint(1, 2)):
        material_path = f"/{root}/{looks()}"
        material = UsdShade.Material.Define(stage, material_path)
        inside = Names(rng, valid)
        surface = UsdShade.Shader.Define(stage, f"{material_path}/{inside()}")
        surface.CreateIdAttr("UsdPreviewSurface")
        graph_path = f"{material_path}/{inside()}"
        graph = UsdShade.NodeGraph.Define(stage, graph_path)
        members = Names(rng, valid)
        reader = UsdShade.Shader.Define(stage, f"{graph_path}/{members()}")
        reader.CreateIdAttr("UsdPrimvarReader_float")
        reader.CreateInput("varname", Sdf.ValueTypeNames.Token).Set(random_name(rng))
        scale = UsdShade.Shader.Define(stage, f"{graph_path}/{members()}")
        scale.CreateIdAttr("ND_multiply_float")
        interface = graph.CreateInput(Names(rng, valid)(), Sdf.ValueTypeNames.Float)
        interface.Set(0.5)
        scale.CreateInput("in1", Sdf.ValueTypeNames.Float).ConnectToSource(reader.ConnectableAPI(), "result")
        scale.CreateInput("in2", Sdf.ValueTypeNames.Float).ConnectToSource(interface)
        out = graph.CreateOutput(Names(rng, valid)(), Sdf.ValueTypeNames.Float)
        out.ConnectToSource(scale.ConnectableAPI(), "out")
        surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).ConnectToSource(out)
        tint = material.CreateInput(Names(rng, valid)(), Sdf.ValueTypeNames.Color3f)
        tint.Set((0.3, 0.5, 0.7))
        surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(tint)
        texture = UsdShade.Shader.Define(stage, f"{material_path}/{inside()}")
        texture.CreateIdAttr("UsdUVTexture")
        texture.CreateInput("file", Sdf.ValueTypeNames.Asset).Set("checker.png")
        surface.CreateInput("emissiveColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(texture.ConnectableAPI(), "rgb")
        material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    return stage.GetRootLayer().ExportToString().encode()


# -- the check -------------------------------------------------------------------------------------
class ShaderChecker:
    """Each target's own checker over generated records: glslangValidator for GLSL and ESSL (one
    run for many shaders), `wgsl_errors` (name -> source => name -> message: wgpu creating the
    modules, see shadergen/render/wgpu_device.py) for WGSL."""

    def __init__(self, glslang: str, wgsl_errors):
        self.glslang = glslang
        self.wgsl_errors = wgsl_errors
        self.wgsl_lock = threading.Lock()  # one validator child, one module at a time

    def problems(self, labelled_records) -> list[str]:
        """[(label, record)] -> a line per record that is an error or whose source a checker rejects."""
        found, glsl, wgsl, others = [], {}, {}, {}
        for label, record in labelled_records:
            if "error" in record:
                found.append(f"{label}: {record['error']}")
                continue
            for stage, source in record["stages"].items():
                name = f"{label} {record['target']} {record['interface']} {record['element']} {stage}"
                if record["target"] in CHECK_MODULES:
                    others.setdefault(record["target"], {})[name] = (stage, source)
                else:
                    (wgsl if record["target"] == "wgsl" else glsl)[name] = (stage, source)
        found += self._glslang(glsl)
        for target, shaders in others.items():
            rejected = importlib.import_module(CHECK_MODULES[target]).errors(shaders)
            found += [f"{name}: {message[:600]}" for name, message in rejected.items()]
        if wgsl:
            with self.wgsl_lock:
                rejected = self.wgsl_errors({name: source for name, (_, source) in wgsl.items()})
            found += [f"{name}: {message[:600]}" for name, message in rejected.items()]
        return found

    def _glslang(self, shaders: dict[str, tuple[str, str]]) -> list[str]:
        if not shaders:
            return []
        with tempfile.TemporaryDirectory() as folder:
            paths = {}
            for k, (name, (stage, source)) in enumerate(shaders.items()):
                path = os.path.join(folder, f"s{k}.{'vert' if stage == 'vertex' else 'frag'}")
                with open(path, "w", encoding="utf-8") as f:
                    f.write(source)
                paths[path] = name
            run = subprocess.run([self.glslang, *paths], capture_output=True, text=True, errors="replace")
        if run.returncode == 0:
            return []
        failed, current = {}, None
        for line in run.stdout.splitlines():
            if line in paths:
                current = line
            elif current and line.startswith("ERROR"):
                failed.setdefault(current, []).append(line)
        if not failed:
            return [f"glslangValidator exited {run.returncode}: {run.stdout[-600:]}"]
        return [f"{paths[p]}: {' | '.join(lines[:3])[:600]}" for p, lines in failed.items()]


def generate_records(gen, case: NameCase, targets=TARGETS, interfaces=INTERFACES):
    """(label, record) of every renderable element of the case in each target and interface, by
    the library API (what the CLI and the service's generator processes call)."""
    for target in targets:
        for interface in interfaces:
            # document names: the hostile names must reach the source (structural names keep them out)
            for record in gen.records(case.document, target=target, interface=interface, all=True,
                                      document_format=case.format, names="document"):
                yield case.label, record


# -- over HTTP, for bench/fuzz.py ------------------------------------------------------------------
@dataclass
class NameAnswer:
    status_code: int  # the first status other than 200 among the case's answers, else 200
    problems: list[str]


def http_cases(count: int, seed: int):
    """(label, case) pairs, as bench/fuzz.py's kinds yield them."""
    for case in name_cases(seed, count):
        yield case.label, case


_CHECKER: ShaderChecker | None = None
# made once for all of bench/fuzz.py's client threads: two checkers would be two locks over the
# one WGSL validator child, whose pipe two threads then wrote at once (the run hung)
_CHECKER_MADE = threading.Lock()


def post_case(client, case: NameCase, timeout_s: float = 120) -> NameAnswer:
    """The case sent to /v1/generate for every target and interface (the service answers the first
    element); every answer must be a 200 whose record compiles."""
    global _CHECKER
    with _CHECKER_MADE:
        if _CHECKER is None:
            from shadergen.render.wgpu_device import wgsl_errors
            _CHECKER = ShaderChecker(shutil.which("glslangValidator") or "glslangValidator", wgsl_errors)
    status, problems, records = 200, [], []
    for target in TARGETS:
        for interface in INTERFACES:
            r = client.post("/v1/generate", params={"target": target, "interface": interface, "names": "document"},
                            content=case.document, headers={"content-type": CONTENT_TYPES[case.format]},
                            timeout=timeout_s)
            if r.status_code != 200:
                status = r.status_code if status == 200 else status
                problems.append(f"{target} {interface}: {r.status_code} {r.text[:300]}")
                continue
            records.append((case.label, r.json()))
    return NameAnswer(status, problems + _CHECKER.problems(records))


def judge_answer(answer: NameAnswer) -> str | None:
    """Why a case failed (None when every answer generated and compiled)."""
    return "; ".join(answer.problems)[:2000] or None
