#!/usr/bin/env python3
"""Document upgrades (issue 28, item 6): our upgrade of each old document against the reference's.

For every document older than 1.39 given (files or folders; default the corpus's TestSuite
documents of versions 1.22-1.38), the reference's generator (../shared/oracle/mx_oracle.py, a black
box that upgrades the document as it reads it) lists every renderable element's public uniforms in
`complete`; ours lists the same elements from our upgrade of the same file. The two listings must
hold the same element paths with the same types and values: an input our upgrade moved, renamed,
dropped or gave another value shows as a difference (uniforms without a path, and closure-typed
sockets the reference lists, are not compared). With --render, each material is also drawn from the old document by the
reference's renderer (../shared/oracle/mx_refrender.py) and by `shadergen render` under the
environment the reference saved: PSNR of the sRGB-encoded images, and our mean luminance over
the reference's (a document that renders black is 0x).

  .venv/bin/python bench/upgrade.py [DOC_OR_DIR ...] [--render] [--size 128]
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from shadergen.api import Generator  # noqa: E402
from shadergen.document import read_document  # noqa: E402
from shadergen.errors import ShaderGenError  # noqa: E402

SHARED = os.environ.get("SHADERGEN_SHARED", os.path.join(os.path.dirname(ROOT), "shared"))
CORPUS = os.path.join(SHARED, "corpus")
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
REFRENDER = os.path.join(SHARED, "oracle", "mx_refrender.py")
SHADERGEN = os.path.join(os.path.dirname(sys.executable), "shadergen")
ORACLE = os.path.join(SHARED, "oracle", "mx_oracle.py")
CLOSURES = {"surfaceshader", "displacementshader", "volumeshader", "lightshader", "material", "BSDF", "EDF", "VDF"}
VERSION = re.compile(rb'<materialx[^>]*\sversion="(\d+)\.(\d+)', re.S)


def old_documents(paths: list[str]) -> list[str]:
    found = []
    for p in paths:
        files = [p] if os.path.isfile(p) else sorted(glob.glob(os.path.join(p, "**", "*.mtlx"), recursive=True))
        for f in files:
            with open(f, "rb") as fh:
                m = VERSION.search(fh.read(4096))
            if m and (int(m.group(1)), int(m.group(2))) < (1, 39):
                found.append(f)
    return found


def interface(blocks: dict) -> dict:
    """A listing's public uniforms by element path: (type, value); under None, how many have no path
    (the reference leaves the path of an input nobody authored empty, where we name it)."""
    uniforms = [u for stage in blocks.values() for u in stage.get("PublicUniforms", []) if u["type"] not in CLOSURES]
    listed = {u["path"]: (u["type"], u["value"]) for u in uniforms if u.get("path")}
    listed[None] = sum(not u.get("path") for u in uniforms)
    return listed


def reference_interfaces(path: str) -> dict:
    """The reference's listing of each renderable element of the document (its upgrade, as read);
    None when the oracle fails on the document."""
    run = subprocess.run([ORACLE_PY, ORACLE, path, "--all", "--no-source", "--interface", "complete"],
                         capture_output=True, text=True, timeout=300, cwd=CORPUS)
    records = [json.loads(line) for line in run.stdout.splitlines() if line.strip().startswith("{")]
    if run.returncode != 0 and not records:
        return None
    return {r["element"]: (("error", r["error"]) if r.get("error") else interface(r["blocks"])) for r in records}


def our_interfaces(gen: Generator, path: str) -> dict:
    found = {}
    for prepared in gen.prepare_all(read_document(path)):
        if isinstance(prepared, ShaderGenError):
            continue
        try:
            found[prepared.element] = interface(prepared.emit()["blocks"])
        except ShaderGenError as e:
            found[prepared.element] = ("error", e.code)
    return found


def same_value(a, b) -> bool:
    a, b = (number(v) for v in (a, b))
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(a - b) <= 1e-5 * max(1.0, abs(a), abs(b))
    return a == b


def number(v):
    """The oracle writes an integer geomprop's index as text ('0')."""
    try:
        return float(v) if isinstance(v, str) else v
    except ValueError:
        return v


def compare(ours, theirs) -> str:
    """'same', or what differs between two element listings (or their errors)."""
    if ours is None or theirs is None:
        return f"differs: {'ours' if ours is None else 'the reference'} has no such element"
    if isinstance(ours, tuple) or isinstance(theirs, tuple):
        return "same (both fail)" if isinstance(ours, tuple) and isinstance(theirs, tuple) else \
            f"differs: ours {ours[1] if isinstance(ours, tuple) else 'generates'}, " \
            f"the reference's {theirs[1] if isinstance(theirs, tuple) else 'generates'}"
    paths_ours, paths_theirs = set(ours) - {None}, set(theirs) - {None}
    only_ours, only_theirs = sorted(paths_ours - paths_theirs), sorted(paths_theirs - paths_ours)
    values = sorted(p for p in paths_ours & paths_theirs
                    if ours[p][0] != theirs[p][0] or not same_value(ours[p][1], theirs[p][1]))
    unnamed = theirs[None] - ours[None]  # inputs the reference lists without a path, and we with one
    if not (only_theirs or values) and len(only_ours) <= unnamed:
        return f"same ({len(paths_theirs)} inputs by path" + (f", {len(only_ours)} more that only we name)" if only_ours else ")")
    return "differs: " + "; ".join(f"{what} {', '.join(paths[:4])}{' ...' if len(paths) > 4 else ''}"
                                   for what, paths in (("only ours", only_ours), ("only the reference's", only_theirs),
                                                       ("values", values)) if paths)


def srgb(linear):
    import numpy as np
    x = np.clip(linear, 0.0, 1.0)
    return np.where(x <= 0.0031308, x * 12.92, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def render_psnr(doc: str, element: str, size: int, tmp: str) -> tuple[float, float] | None:
    """Both renderers under the same environment (the reference's, saved and read back by ours):
    PSNR of the two sRGB-encoded images (what a thumbnail shows; highlights past 1 clip), and the
    ratio of our mean linear luminance to the reference's (a black render is 0)."""
    import numpy as np
    ours, ref, env = os.path.join(tmp, "ours.npy"), os.path.join(tmp, "ref.npy"), os.path.join(tmp, "env")
    for cmd in ([ORACLE_PY, REFRENDER, doc, "--material", element, "-o", os.path.join(tmp, "ref.png"),
                 "--npy", ref, "--size", str(size), "--save-env", env],
                [SHADERGEN, "render", doc, "--element", element, "-o", os.path.join(tmp, "ours.png"),
                 "--npy", ours, "--size", str(size), "--search-path", CORPUS,
                 "--env", os.path.join(env, "radiance.hdr"), "--irr", os.path.join(env, "irradiance.hdr")]):
        if subprocess.run(cmd, capture_output=True, timeout=600, cwd=CORPUS).returncode != 0:
            return None
    a, b = (np.nan_to_num(np.load(p)[..., :3].astype(np.float64)) for p in (ours, ref))
    mse = float(np.mean((srgb(a) - srgb(b)) ** 2))
    luminance = np.array([0.2126, 0.7152, 0.0722])
    return (99.0 if mse == 0 else 10 * np.log10(1.0 / mse)), float((a @ luminance).mean() / max((b @ luminance).mean(), 1e-9))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("paths", nargs="*", default=[os.path.join(CORPUS, "resources", "Materials", "TestSuite")])
    ap.add_argument("--render", action="store_true", help="also draw materials, ours against the reference's")
    ap.add_argument("--size", type=int, default=128)
    args = ap.parse_args()
    gen = Generator()
    rows, same, total, psnrs = [], 0, 0, []
    for path in old_documents(args.paths):
        version = ".".join(VERSION.search(open(path, "rb").read(4096)).groups()[i].decode() for i in (0, 1))
        ours, theirs = our_interfaces(gen, path), reference_interfaces(path)
        if not ours and not theirs:
            why = "the reference's generator fails on it" if theirs is None else "no renderable element in either"
            rows.append((os.path.relpath(path, CORPUS) if path.startswith(CORPUS) else path, version, "-",
                         f"{why}; ours: none", ""))
            continue
        theirs = theirs or {}
        for element in dict.fromkeys(list(theirs) + list(ours)):
            verdict = compare(ours.get(element), theirs.get(element))
            total += 1
            same += verdict.startswith("same")
            image = ""
            if args.render and isinstance(ours.get(element), dict):
                with tempfile.TemporaryDirectory() as tmp:
                    r = render_psnr(path, element, args.size, tmp)
                image = "render failed" if r is None else f"sRGB PSNR {r[0]:.1f} dB, mean luminance {r[1]:.3f}x"
                psnrs += [r[0]] if r is not None else []
            rows.append((os.path.relpath(path, CORPUS) if path.startswith(CORPUS) else path, version, element,
                         verdict, image))
    print(f"| document | version | element | our listing against the reference's |{' image |' if args.render else ''}")
    print(f"|---|---|---|---|{'---|' if args.render else ''}")
    for doc, version, element, verdict, image in rows:
        print(f"| {doc} | {version} | {element} | {verdict} |{f' {image} |' if args.render else ''}")
    summary = f"upgrade: {same}/{total} elements list the same inputs and values as the reference's upgrade"
    if psnrs:
        summary += f" | renders: min sRGB PSNR {min(psnrs):.1f} dB over {len(psnrs)}"
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
