"""`shadergen generate`: JSON Lines records on stdout, or stage files and listings under --out."""
import json
import os
import sys
from pathlib import Path

STAGE_SUFFIX = {"glsl": {"vertex": "vert", "pixel": "frag"}, "essl": {"vertex": "vert", "pixel": "frag"}}


def add_arguments(p) -> None:
    p.add_argument("documents", nargs="+", metavar="DOC.mtlx")
    p.add_argument("--target", default="glsl", help="glsl (desktop #version 400) or essl (#version 300 es)")
    p.add_argument("--element", help="name path of the element to generate (default: the first renderable)")
    p.add_argument("--all", action="store_true", help="every renderable element")
    p.add_argument("--interface", default="complete", help="complete | reduced")
    p.add_argument("--out", metavar="DIR", help="write <element>.<stage> files and <element>.json listings here")
    p.add_argument("--no-source", action="store_true", help="listings only")


def write_files(record: dict, out_dir: str) -> None:
    os.makedirs(out_dir, exist_ok=True)
    stem = (record["element"] or "shader").replace("/", "_")
    for stage, src in record["stages"].items():
        ext = STAGE_SUFFIX.get(record["target"], {}).get(stage, stage)
        with open(os.path.join(out_dir, f"{stem}.{ext}"), "w") as f:
            f.write(src)
    with open(os.path.join(out_dir, f"{stem}.json"), "w") as f:
        json.dump({k: v for k, v in record.items() if k != "stages"}, f, indent=1)


def run(args) -> int:
    from .api import default_generator
    from .errors import ShaderGenError

    ok = True
    try:
        gen = default_generator()
    except ShaderGenError as e:  # a broken library is reported like any other error
        print(json.dumps({"document": None, "element": None, "target": args.target, "error": e.to_dict()}))
        return 1
    for doc in args.documents:
        for rec in gen.records(Path(doc), target=args.target, element=args.element, all=args.all,
                               interface=args.interface):
            if "error" in rec:
                ok = False
            elif args.out:
                write_files(rec, args.out)
            if args.no_source and "stages" in rec:
                rec["stages"] = {k: None for k in rec["stages"]}
            sys.stdout.write(json.dumps(rec) + "\n")
    return 0 if ok else 1
