#!/usr/bin/env python3
"""USD scenes from the field (issue 21): what share of their materials generate and draw.

Every .usda, .usdc, .usd and .usdz file under the folders given is read as `shadergen generate
--all` reads it (one record per UsdShadeMaterial) and each material that generates is drawn as
`shadergen render --element` draws it (GL, specialized, the sphere). A file is read in a child
process of its own, so a crash or a hang in usd-core costs that file alone (its materials are
then refused as `crash` or `timeout`). Prints each refused material with its code, the refusals
by code, and one summary line; textures a scene names but does not ship are counted (the
renderer draws the image node's default instead), not refused.

  .venv/bin/python bench/usd_field.py DIR... [--size 64] [--timeout 120] [--json out.json]
"""
import argparse
import collections
import json
import os
import subprocess
import sys
from pathlib import Path

USD_SUFFIXES = (".usda", ".usdc", ".usd", ".usdz")


def scene_files(folders: list[str]) -> list[str]:
    found = []
    for folder in folders:
        if os.path.isfile(folder):
            found.append(folder)
            continue
        for root, _, names in os.walk(folder):
            found.extend(os.path.join(root, n) for n in names if n.lower().endswith(USD_SUFFIXES))
    return sorted(found)


def measure_file(path: str, size: int) -> list[dict]:
    """One row per material of one file: its element, `generated`, `drawn`, the refusal's code
    and message, and how many textures were missing where it drew."""
    from shadergen.api import Generator
    from shadergen.render import Renderer
    from shadergen.render.errors import RenderError

    gen, renderer, rows = Generator(), None, []
    for record in gen.records(Path(path), all=True, interface="specialized", environment="fis", lights=False):
        row = {"file": path, "element": record.get("element"), "generated": "error" not in record, "drawn": False}
        if "error" in record:
            row.update(code=record["error"]["code"], message=record["error"]["message"])
            rows.append(row)
            continue
        renderer = renderer or Renderer(search_paths=[])
        try:
            result = renderer.render(record, size=size, document_dir=os.path.dirname(os.path.abspath(path)))
        except RenderError as exc:
            row.update(code=exc.code, message=exc.message)
        else:
            row.update(drawn=True, missing_textures=sum(": not found" in w for w in result.warnings))
        rows.append(row)
    return rows


def measure_in_child(path: str, size: int, timeout: float) -> list[dict]:
    command = [sys.executable, os.path.abspath(__file__), "--one", path, "--size", str(size)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return [{"file": path, "element": None, "generated": False, "drawn": False, "code": "timeout",
                 "message": f"no answer in {timeout:g} s"}]
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if done.returncode != 0 or not lines:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        return [{"file": path, "element": None, "generated": False, "drawn": False, "code": "crash",
                 "message": f"exit {done.returncode}: {last}"}]
    return [json.loads(line) for line in lines]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folders", nargs="*")
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per file")
    parser.add_argument("--json", help="write every row to this file")
    parser.add_argument("--one", help=argparse.SUPPRESS)  # the child: one file, rows as JSON lines
    args = parser.parse_args()
    if args.one:
        for row in measure_file(args.one, args.size):
            print(json.dumps(row))
        return
    files = scene_files(args.folders)
    rows = [row for path in files for row in measure_in_child(path, args.size, args.timeout)]
    # a file-level refusal stands for its materials as one; a file without materials is none
    materials = [r for r in rows if r["element"] is not None or r["code"] != "no_renderable_element"]
    refusals = collections.Counter(r["code"] for r in materials if not r["drawn"])
    for r in materials:
        if not r["drawn"]:
            print(f"{r['file']} {r['element']}: {r['code']}: {r['message'][:160]}")
    for code, count in refusals.most_common():
        print(f"  {code}: {count}")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    n = len(materials)
    generated = sum(r["generated"] for r in materials)
    drawn = sum(r["drawn"] for r in materials)
    missing = sum(r.get("missing_textures", 0) > 0 for r in materials)
    empty = sum(r["element"] is None and r["code"] == "no_renderable_element" for r in rows)
    pct = (lambda k: f"{100 * k / n:.0f}%") if n else (lambda k: "-")
    print(f"usd_field: {n} materials in {len(files)} files | generated {pct(generated)} | drawn {pct(drawn)} | "
          f"drawn without some texture {missing} | files without a material {empty}")


if __name__ == "__main__":
    main()
