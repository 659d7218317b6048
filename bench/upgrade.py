#!/usr/bin/env python3
"""Document upgrades (issue 28, item 6): our upgrade of each old document against the reference's.

For every document older than 1.39 given (files or folders; default the corpus's TestSuite
documents of versions 1.22-1.38), the reference (the oracle venv's MaterialX, as a black box)
reads it and writes it back upgraded to 1.39. Then, for every renderable element of either and
every top-level node both share, our `specialized` record from the old document (our upgrade)
against our record from the reference's upgraded document: the same pixel source and the same
listing mean the two upgrades give the same graph, values included (specialized folds every value
into the code). With --render, each material is also drawn from the old document by the
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
from shadergen.document import parse_document, read_document  # noqa: E402
from shadergen.errors import ShaderGenError  # noqa: E402

SHARED = os.environ.get("SHADERGEN_SHARED", os.path.join(os.path.dirname(ROOT), "shared"))
CORPUS = os.path.join(SHARED, "corpus")
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
REFRENDER = os.path.join(SHARED, "oracle", "mx_refrender.py")
SHADERGEN = os.path.join(os.path.dirname(sys.executable), "shadergen")
WRITE_UPGRADED = ("import sys, MaterialX as mx\n"
                  "d = mx.createDocument(); mx.readFromXmlFile(d, sys.argv[1]); sys.stdout.write(mx.writeToXmlString(d))")
VERSION = re.compile(rb'<materialx[^>]*\sversion="(\d+)\.(\d+)', re.S)
NOT_NODES = ("nodedef", "nodegraph", "implementation", "typedef", "geominfo", "backdrop", "look", "collection",
             "propertyset", "variantset", "materialassign", "output", "input", "token")


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


def reference_upgrade(path: str) -> str:
    return subprocess.run([ORACLE_PY, "-c", WRITE_UPGRADED, path], capture_output=True, text=True, check=True,
                          timeout=120).stdout


def record(gen: Generator, doc, element: str) -> tuple:
    """What our generator makes of one element: (pixel source, listing) or (error code, message)."""
    try:
        rec = gen.prepare(doc, element=element, interface="specialized").emit()
    except ShaderGenError as e:
        return ("missing",) if e.code == "unknown_element" else ("error", e.code)
    return (rec["stages"]["pixel"], json.dumps(rec["blocks"]["pixel"], sort_keys=True))


def renderable(gen: Generator, doc) -> list[str]:
    return [p.element for p in gen.prepare_all(doc) if not isinstance(p, ShaderGenError)]


def top_level_nodes(doc) -> list[str]:
    return [e.name for e in doc.root.children if e.category not in NOT_NODES]


def describe(rec: tuple) -> str:
    return {"error": f"error {rec[-1]}", "missing": "no such element"}.get(rec[0], "code")


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
    rows, same, both_fail, total, psnrs = [], 0, 0, 0, []
    for path in old_documents(args.paths):
        version = ".".join(VERSION.search(open(path, "rb").read(4096)).groups()[i].decode() for i in (0, 1))
        ours = read_document(path)
        theirs = parse_document(reference_upgrade(path), base_dir=os.path.dirname(path))
        materials = renderable(gen, ours) + renderable(gen, theirs)
        shared = set(top_level_nodes(ours)) & set(top_level_nodes(theirs))
        for element in dict.fromkeys(materials + [n for n in top_level_nodes(ours) if n in shared]):
            a, b = record(gen, ours, element), record(gen, theirs, element)
            total += 1
            same += a == b
            both_fail += a == b and a[0] == "error"
            verdict = (("same" if a[0] != "error" else f"same ({describe(a)})") if a == b
                       else f"differs: ours {describe(a)}, the reference's {describe(b)}")
            image = ""
            if args.render and element in materials:
                with tempfile.TemporaryDirectory() as tmp:
                    r = render_psnr(path, element, args.size, tmp)
                image = "render failed" if r is None else f"sRGB PSNR {r[0]:.1f} dB, mean luminance {r[1]:.3f}x"
                psnrs += [r[0]] if r is not None else []
            rows.append((os.path.relpath(path, CORPUS) if path.startswith(CORPUS) else path, version, element,
                         verdict, image))
    print(f"| document | version | element | ours against the reference's upgrade |{' image |' if args.render else ''}")
    print(f"|---|---|---|---|{'---|' if args.render else ''}")
    for doc, version, element, verdict, image in rows:
        print(f"| {doc} | {version} | {element} | {verdict} |{f' {image} |' if args.render else ''}")
    summary = (f"upgrade: {same}/{total} elements the same as from the reference's upgrade "
               f"({both_fail} of them failing alike)")
    if psnrs:
        summary += f" | renders: min sRGB PSNR {min(psnrs):.1f} dB over {len(psnrs)}"
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
