"""The MSL cross-check. No Metal compiler runs on Linux; naga (on PATH) translates our validated WGSL
of the same material to MSL, and ours must declare what naga's declares: the same entry points
(kind and name), uniform buffers (parameter, struct, and every member's name, type and byte
offset), textures and samplers (naga keeps only those its entry point reaches: each must be ours), vertex inputs (`[[attribute(i)]]`) and the vertex data between the
stages (`[[user(loc<i>)]]`, by location, name and type), and the same members in each struct both
declare. (tint, the other translator on these machines, is built without its MSL writer here.)

A small reader of MSL declarations does it: it reads naga's output and ours, third-party and
finished text, in this checker only; the generator never reads what it wrote. naga spells names
its own way (`metal::` prefixes, a `_` after a name ending in a digit or a reserved word, `_pad`
members, `packed_float3` for WGSL's 12-byte vec3 where a member follows in its 16 bytes): the
comparison undoes those spellings, never the layout.

    errors({label: (stage, msl)}, wgsl={label: wgsl})  ->  {label: message}

Without a WGSL counterpart a shader is read alone: its entry point and declarations must parse.
"""
import os
import re
import shutil
import subprocess
import tempfile

from ..checking import Unavailable

ENTRY = {"vertex": ("vertex", "vertexMain"), "pixel": ("fragment", "fragmentMain")}
_COMMENT = re.compile(r"//[^\n]*")
_STRUCT = re.compile(r"\bstruct\s+(\w+)\s*\{([^{}]*)\}\s*;")
_MEMBER = re.compile(r"^(.*?)\s*\b(\w+)\s*(\[[^\]]*\])?\s*(\[\[.*\]\])?$", re.S)
_ENTRY = re.compile(r"\b(vertex|fragment)\s+([\w<>:,\s]+?)\s+(\w+)\s*\(")
# size and alignment of MSL types (Metal Shading Language Specification, table 2.3 and 2.4)
SIZES = {"float": (4, 4), "int": (4, 4), "uint": (4, 4), "bool": (1, 1), "char": (1, 1), "float2": (8, 8),
         "float3": (16, 16), "packed_float3": (12, 4), "float4": (16, 16), "int2": (8, 8), "int3": (16, 16),
         "int4": (16, 16), "float2x2": (16, 8), "float3x3": (48, 16), "float4x4": (64, 16)}


def naga() -> str:
    """naga's command line (no Debian package has it: `cargo install naga-cli` with a current Rust)."""
    path = shutil.which("naga")
    if path is None:
        raise Unavailable("naga", "cargo install naga-cli")
    return path


def naga_msl(wgsl: str) -> str:
    with tempfile.TemporaryDirectory() as folder:
        source, target = os.path.join(folder, "in.wgsl"), os.path.join(folder, "out.metal")
        with open(source, "w", encoding="utf-8") as f:
            f.write(wgsl)
        run = subprocess.run([naga(), source, target], capture_output=True, text=True)
        if run.returncode != 0:
            raise ValueError(f"naga refused the WGSL: {run.stderr.strip()[-300:]}")
        with open(target, encoding="utf-8") as f:
            return f.read()


class Declarations:
    """The structs and entry points of an MSL text; `constants` the integer constants (array sizes)."""

    def __init__(self, text: str):
        text = _COMMENT.sub("", text).replace("metal::", "")
        self.structs = {name: [m for m in map(member, body.split(";")) if m] for name, body in _STRUCT.findall(text)}
        # naga wraps an array in a struct of one member `inner` (`type_11 u_lightData;`): the array's element
        self.arrays = {name: members[0][0] for name, members in self.structs.items()
                       if len(members) == 1 and members[0][1] == "inner" and members[0][2]}
        self.constants = {n: int(v) for n, v in re.findall(r"\b(?:constant|const)\s+(?:int|uint)\s+(\w+)\s*=\s*(\d+)", text)}
        self.entries = {}
        for match in _ENTRY.finditer(text):
            params = balanced(text, match.end() - 1)
            self.entries[match.group(3)] = (match.group(1), [m for m in map(member, split_top(params)) if m])

    def type(self, t: str) -> str:
        """A member's type as compared: unpacked, naga's array wrapper read as its element."""
        return unpacked(self.arrays.get(t, t))

    def size(self, t: str, count: str | None) -> tuple[int, int]:
        if t in SIZES:
            size, align = SIZES[t]
        elif t in self.structs:
            size, align = self.layout(t)[1:]
        else:
            raise ValueError(f"no size known for {t}")
        if count:
            n = count.strip("[]")
            size *= int(n) if n.isdigit() else self.constants.get(n, 1)
        return size, align

    def layout(self, struct: str):
        """[(name, type, offset)] of a struct's members (padding left out), its size and alignment."""
        out, offset, widest = [], 0, 1
        for t, name, count, _ in self.structs[struct]:
            size, align = self.size(t, count)
            offset = -(-offset // align) * align
            if not (name.startswith("_pad") or name.startswith("pad_")):
                out.append((plain(name), self.type(t), offset))
            offset += size
            widest = max(widest, align)
        return out, -(-offset // widest) * widest, widest


def member(text: str):
    text = " ".join(text.split())
    if not text:
        return None
    m = _MEMBER.match(text)
    if m is None or not m.group(1):
        return None
    t = m.group(1).replace("constant ", "").replace("const ", "").strip()
    return t, m.group(2), m.group(3), m.group(4) or ""


def balanced(text: str, start: int) -> str:
    """The text inside the parentheses opening at `start`."""
    depth = 0
    for i in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return text[start + 1:i]
    raise ValueError("unbalanced parentheses")


def split_top(text: str) -> list[str]:
    parts, depth, last = [], 0, 0
    for i, c in enumerate(text):
        depth += {"(": 1, "<": 1, "[": 1, ")": -1, ">": -1, "]": -1}.get(c, 0)
        if c == "," and depth == 0:
            parts.append(text[last:i])
            last = i + 1
    return parts + [text[last:]]


def plain(name: str) -> str:
    """A name without naga's `_` suffix (digits at a name's end, reserved words)."""
    return name.rstrip("_")


def unpacked(t: str) -> str:
    return t.removeprefix("packed_")


def attribute(attrs: str, kind: str) -> int | None:
    m = re.search(kind + r"\((\d+)\)", attrs)
    return int(m.group(1)) if m else None


def compare(stage: str, ours: Declarations, theirs: Declarations) -> list[str]:
    kind, entry = ENTRY[stage]
    problems = []
    if ours.entries.get(entry, (None,))[0] != kind or theirs.entries.get(entry, (None,))[0] != kind:
        return [f"entry point: ours {ours.entries.get(entry, ('none',))[0]} {entry}, naga's "
                f"{theirs.entries.get(entry, ('none',))[0]}"]
    our_params, their_params = ours.entries[entry][1], theirs.entries[entry][1]

    def buffers(decl, params):
        return {plain(n): t.rstrip("&").strip() for t, n, _, a in params if t.endswith("&")}

    def textures(decl, params):
        return sorted((t.split("<")[0], plain(n)) for t, n, _, _ in params if t.startswith(("texture2d", "sampler")))

    # naga passes only the resources its entry point reaches: each of them must be ours, alike
    ob, tb = buffers(ours, our_params), buffers(theirs, their_params)
    if any(ob.get(name) != struct for name, struct in tb.items()):
        problems.append(f"uniform buffers: ours {ob}, naga's {tb}")
    for struct in set(ob.values()) & set(tb.values()):
        if ours.layout(struct)[0] != theirs.layout(struct)[0]:
            problems.append(f"{struct} members (name, type, offset): ours {ours.layout(struct)[0]}, "
                            f"naga's {theirs.layout(struct)[0]}")
    if not set(textures(theirs, their_params)) <= set(textures(ours, our_params)):
        problems.append(f"textures: ours {textures(ours, our_params)}, naga's {textures(theirs, their_params)}")
    # stage inputs: ours a struct [[stage_in]]; naga's its `<entry>Input`
    inputs = "AppData" if stage == "vertex" else "VertexData"
    where = "attribute" if stage == "vertex" else "user\\(loc(?:n)?"

    def located(members, pattern):
        found = []
        for t, n, _, attrs in members:
            m = re.search(pattern + r"(\d+)", attrs) if stage == "pixel" else re.search(r"attribute\((\d+)\)", attrs)
            if m:
                found.append((int(m.group(1)), plain(n), unpacked(t)))
        return sorted(found)

    ours_in = located(ours.structs.get(inputs, []), where)
    theirs_in = located(theirs.structs.get(f"{entry}Input", []), where)
    if ours_in != theirs_in:
        problems.append(f"stage inputs (location, name, type): ours {ours_in}, naga's {theirs_in}")
    if stage == "vertex":
        ours_out = located_user(ours.structs.get("VertexData", []))
        theirs_out = located_user(theirs.structs.get(f"{entry}Output", []))
        if ours_out != theirs_out:
            problems.append(f"vertex data out (location, name, type): ours {ours_out}, naga's {theirs_out}")
    for struct in set(ours.structs) & set(theirs.structs) - {"VertexData", "PixelStage"}:
        a = [(plain(n), ours.type(t)) for t, n, _, _ in ours.structs[struct] if not n.startswith(("_pad", "pad_"))]
        b = [(plain(n), theirs.type(t)) for t, n, _, _ in theirs.structs[struct] if not n.startswith(("_pad", "pad_"))]
        if a != b:
            problems.append(f"struct {struct}: ours {a}, naga's {b}")
    return problems


def located_user(members) -> list:
    found = []
    for t, n, _, attrs in members:
        m = re.search(r"user\(locn?(\d+)\)", attrs)
        if m:
            found.append((int(m.group(1)), plain(n), unpacked(t)))
    return sorted(found)


def errors(shaders: dict[str, tuple[str, str]], wgsl: dict[str, str] | None = None) -> dict[str, str]:
    """label -> (stage, MSL source) in (and, in `wgsl`, label -> the same stage's WGSL); label ->
    message for each shader whose declarations differ from naga's (or do not read) out."""
    found = {}
    for label, (stage, source) in shaders.items():
        try:
            ours = Declarations(source)
            kind, entry = ENTRY[stage]
            if ours.entries.get(entry, (None,))[0] != kind:
                found[label] = f"no {kind} entry point {entry}"
                continue
            if wgsl and label in wgsl:
                problems = compare(stage, ours, Declarations(naga_msl(wgsl[label])))
                if problems:
                    found[label] = "; ".join(problems)[:1500]
        except ValueError as exc:
            found[label] = str(exc)
    return found
