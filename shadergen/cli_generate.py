"""`shadergen generate`: JSON Lines records on stdout, or stage files and listings under --out."""
import json
import os
import sys

from .features import ENVIRONMENTS

STAGE_SUFFIX = {"vertex": "vert", "pixel": "frag"}
EXAMPLES = """examples:
  shadergen generate examples/marble_checker.mtlx                 # first renderable element, GLSL
  shadergen generate --all --target essl --out shaders/ a.mtlx b.mtlx
  cat doc.mtlx | shadergen generate -                             # the document on stdin

--out DIR writes DIR/<document>/<element>.<target>.vert, .frag and .json (the listings; vulkan also
.vert.spv and .frag.spv, the SPIR-V), so documents, elements and targets never overwrite each
other's files."""


def add_arguments(p) -> None:
    p.add_argument("documents", nargs="+", metavar="DOC.mtlx",
                   help="MaterialX documents; - reads one from stdin (its includes relative to the current folder)")
    p.add_argument("--target", default="glsl", help="glsl (desktop #version 400), essl (#version 300 es), wgsl (WebGPU), "
                                                      "vulkan (#version 450 for Vulkan, with each stage's SPIR-V), hlsl "
                                                      "(shader model 5+), slang, msl (Metal) or osl (OSL 1.13: one .osl "
                                                      "shader, compiled by oslc)")
    p.add_argument("--element", metavar="NAMEPATH",
                   help="name path of the element to generate (default: the first renderable element)")
    p.add_argument("--all", action="store_true", help="every renderable element instead of the first")
    p.add_argument("--interface", default="complete",
                   help="complete (every input a uniform), reduced (only interface inputs and textures) or "
                        "specialized (values folded into the code and whatever cannot contribute removed)")
    p.add_argument("--keep", default="", metavar="NODE/INPUT,...",
                   help="with --interface specialized: document inputs that stay live uniforms (and keep their lobes)")
    p.add_argument("--values", default="listing", choices=("listing", "source"),
                   help="listing (default: uniforms initialised to the nodedef's values, so materials that differ "
                        "only in values share one source; the document's values are in the listing) or source "
                        "(the document's values written into the initializers too)")
    p.add_argument("--names", default="structural", choices=("structural", "document"),
                   help="structural (default: the source names nodes and uniforms by the graph's structure, "
                        "u_n12_base_color, so materials that differ only in their node names share one source; "
                        "bind by the listing's paths) or document (the document's element names, for clients "
                        "that bind uniforms by name)")
    p.add_argument("--env-method", choices=ENVIRONMENTS, default=None,
                   help="write only this way of lighting by the environment: fis (filtered importance sampling), "
                        "prefilter (a prefiltered map) or hybrid (that map corrected by a few samples); default all, "
                        "chosen by a renderer's MX_ENV_PREFILTER and MX_ENV_HYBRID")
    p.add_argument("--no-lights", action="store_true",
                   help="for a renderer that draws no light rig (thumbnails): no light loop is written (less code "
                        "to compile); the record says \"lights\": false")
    add_cms_arguments(p)
    p.add_argument("--out", metavar="DIR", help="also write stage files and listings under DIR (see below)")
    p.add_argument("--no-source", action="store_true", help="records without stage source (listings only)")


def add_cms_arguments(p) -> None:
    """The colour management options `generate` and `render` share (shadergen/cms/)."""
    p.add_argument("--cms", choices=("builtin", "ocio"), default=None,
                   help="colour management system: builtin (default: the library's transforms to lin_rec709) or "
                        "ocio (OpenColorIO: any colour space of the config; default when a config is named)")
    p.add_argument("--ocio-config", metavar="PATH|ocio://NAME", default=None,
                   help="OCIO config for --cms ocio: a file, or one of OCIO's built-in configs such as "
                        "ocio://cg-config-v2.1.0_aces-v1.3_ocio-v2.3 (default: $SHADERGEN_OCIO_CONFIG, else "
                        "ocio://default, OCIO's CG config)")


def cms_options(args) -> dict:
    return {"cms": args.cms, "ocio_config": args.ocio_config}


class OutputFiles:
    """Stage files and listings under --out: one folder per document, files named by element and
    target. Two records of one run that would share a file (documents with the same name in
    different folders, elements whose paths differ only in '/' and '_') are refused, never
    overwritten."""

    def __init__(self, out_dir: str):
        self.out_dir = out_dir
        self.written: dict[str, str] = {}  # file -> the "document element" that wrote it

    def write(self, record: dict, document: str) -> dict | None:
        """Writes the record's files; returns an error record instead when they are taken."""
        name = os.path.splitext(os.path.basename(document))[0] if document != "-" else "stdin"
        folder = os.path.join(self.out_dir, name)
        stem = os.path.join(folder, f"{(record['element'] or 'shader').replace('/', '_')}.{record['target']}")
        files = {f"{stem}.{STAGE_SUFFIX.get(stage, stage) if record['target'] != 'osl' else 'osl'}": src
                 for stage, src in record["stages"].items() if src is not None}
        for stage, module in record.get("spirv", {}).items():  # vulkan: each stage's SPIR-V as it is
            import base64  # here: only a vulkan record needs it, and a cold process pays for each import
            files[f"{stem}.{STAGE_SUFFIX.get(stage, stage)}.spv"] = base64.b64decode(module)
        files[f"{stem}.json"] = json.dumps({k: v for k, v in record.items() if k not in ("stages", "spirv")}, indent=1)
        owner = f"{document} {record['element']}"
        taken = next((f for f in files if self.written.get(f, owner) != owner), None)
        if taken is not None:
            return {k: record[k] for k in ("document", "element", "target", "interface")} | {"error": {
                "code": "output_collision", "message": f"{taken} was already written for {self.written[taken]}",
                "where": taken}}
        os.makedirs(folder, exist_ok=True)
        for path, content in files.items():
            with open(path, "wb" if isinstance(content, bytes) else "w") as f:
                f.write(content)
            self.written[path] = owner
        return None


def keep_list(text: str) -> tuple[str, ...]:
    return tuple(p.strip() for p in text.split(",") if p.strip())


def run(args) -> int:
    from .api import DocumentFile, default_generator
    from .errors import ShaderGenError

    ok = True
    try:
        gen = default_generator()
    except ShaderGenError as e:  # a broken library is reported like any other error
        print(json.dumps({"document": None, "element": None, "target": args.target, "error": e.to_dict()}))
        return 1
    out = OutputFiles(args.out) if args.out else None
    for doc in args.documents:
        options = dict(target=args.target, element=args.element, all=args.all, interface=args.interface,
                       keep=keep_list(args.keep), values=args.values, environment=args.env_method,
                       lights=not args.no_lights, names=args.names, **cms_options(args))
        if doc == "-":
            records = gen.records(sys.stdin.buffer.read(), base_dir=os.getcwd(), **options)
        else:
            records = gen.records(DocumentFile(doc), **options)
        for rec in records:
            if "error" not in rec and out is not None:
                rec = out.write(rec, doc) or rec
            if "error" in rec:
                ok = False
            if args.no_source and "stages" in rec:
                rec["stages"] = {k: None for k in rec["stages"]}
            sys.stdout.write(json.dumps(rec) + "\n")
    return 0 if ok else 1
