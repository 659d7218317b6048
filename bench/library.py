#!/usr/bin/env python3
"""A library of materials thumbnailed (issue 23, item 5): as many compiles as topologies.

Builds --materials documents from the corpus's shading models (standard_surface, open_pbr_surface,
gltf_pbr, UsdPreviewSurface), each with random values and random node names, untextured or with
its base colour from a corpus texture, and measures in one run, each on the same library:

- the reference's per-material process (../shared/oracle/mx_refrender.py, one process per
  material, as a pipeline without our service runs it) on --reference-sample of them, in slices
  drawn before, between and after our runs, so that the machine's drift reaches both sides;
- our batch command line (`shadergen render --batch`, one process);
- our service (`shadergen serve`) with 1, 2 and 3 local render workers routed by topology, 3 with
  the shared queue (routing that ignores topology), and --celery-workers Celery workers on a
  redis-server, each sent the library as one POST /v1/thumbnails/batch.

Per run: materials per second, programs compiled and reused (the program-cache hit rate), and
time per material against 1.3 frames plus its share of the compiles (the batch CLI's mean frame of
a reused program, and its mean program cost: compile and link plus the first draw's excess over a
steady frame, when llvmpipe compiles the machine code). Writes the table and a plot
to docs/library.md and docs/library.png when --docs is given. Its last line:
`library: N materials | T topologies | C compiles | ... | x.x times the reference's throughput`.

  .venv/bin/python bench/library.py [--materials 500] [--size 128] [--reference-sample 8]
"""
import argparse
import json
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "tests" / "service"))

from service_testing import RedisServer, Server, stop, wait_until  # noqa: E402

ORACLE_PY = Path(os.environ.get("ORACLE_VENV", Path.home() / ".cache" / "mx-oracle" / "venv")) / "bin" / "python"
TEXTURES = ("wood_color.jpg", "brick_base_gray.jpg", "cloth.jpg", "grid.png")
REFERENCE = "reference (process per material)"
REFERENCE_FRAMES = 3  # the oracle times the median of these; one is the material's own
REFERENCE_TIMING = re.compile(r"compile\+link ([\d.]+)s\s+frame\(.*?\) median ([\d.]+) ms")
# shading model -> (its colour input, its float inputs with their ranges)
MODELS = {
    "standard_surface": ("base_color", {"metalness": (0, 1), "specular_roughness": (0.05, 0.9), "coat": (0, 1)}),
    "open_pbr_surface": ("base_color", {"base_metalness": (0, 1), "specular_roughness": (0.05, 0.9),
                                        "coat_weight": (0, 1)}),
    "gltf_pbr": ("base_color", {"metallic": (0, 1), "roughness": (0.05, 0.9)}),
    "UsdPreviewSurface": ("diffuseColor", {"metallic": (0, 1), "roughness": (0.05, 0.9)}),
}


def name(rng: random.Random) -> str:
    return "".join(rng.choice("abcdefghijklmnopqrstuvwxyz") for _ in range(6)) + f"_{rng.randrange(10 ** 6)}"


def material(rng: random.Random, model: str, textured: bool, images: Path) -> str:
    colour, floats = MODELS[model]
    shader, mat, image = name(rng), name(rng), name(rng)
    values = "".join(f'    <input name="{k}" type="float" value="{rng.uniform(*r):.4f}" />\n' for k, r in floats.items())
    if textured:
        texture = f'  <image name="{image}" type="color3"><input name="file" type="filename" ' \
                  f'value="{images / rng.choice(TEXTURES)}" /></image>\n'
        colour_input = f'    <input name="{colour}" type="color3" nodename="{image}" />\n'
    else:
        texture = ""
        rgb = ", ".join(f"{rng.random():.4f}" for _ in range(3))
        colour_input = f'    <input name="{colour}" type="color3" value="{rgb}" />\n'
    return (f'<?xml version="1.0"?>\n<materialx version="1.39">\n{texture}'
            f'  <{model} name="{shader}" type="surfaceshader">\n{colour_input}{values}  </{model}>\n'
            f'  <surfacematerial name="{mat}" type="material">\n'
            f'    <input name="surfaceshader" type="surfaceshader" nodename="{shader}" />\n'
            f'  </surfacematerial>\n</materialx>\n')


def build_library(folder: Path, count: int, seed: int, images: Path) -> list[Path]:
    rng = random.Random(seed)
    paths = []
    for i in range(count):
        model = rng.choice(list(MODELS))
        path = folder / f"{i:04d}_{name(rng)}.mtlx"
        path.write_text(material(rng, model, rng.random() < 0.5, images))
        paths.append(path)
    return paths


def reference(paths: list[Path], size: int, out: Path, shared: Path) -> dict:
    """The oracle's process per material: wall time, and its compile and frame times. The oracle
    draws REFERENCE_FRAMES frames to time a steady one, where a pipeline's process would draw one
    (as our batch does): the extra frames, at the median it reports, are taken off its wall time."""
    walls, compiles, frames = [], [], []
    for path in paths:
        started = time.perf_counter()
        run = subprocess.run([str(ORACLE_PY), str(shared / "oracle" / "mx_refrender.py"), str(path),
                              "-o", str(out / f"{path.stem}.png"), "--size", str(size),
                              "--repeat", str(REFERENCE_FRAMES)],
                             capture_output=True, text=True, cwd=shared / "corpus")
        wall = time.perf_counter() - started
        timing = REFERENCE_TIMING.search(run.stderr)
        if run.returncode == 0 and timing:
            compiles.append(float(timing.group(1)))
            frames.append(float(timing.group(2)) / 1e3)
            wall -= (REFERENCE_FRAMES - 1) * frames[-1]
        walls.append(wall)
    return {"walls": walls, "compiles": compiles, "frames": frames}


def reference_row(slices: list[dict]) -> dict:
    """The reference's row from its slices, drawn between our runs: a machine whose speed drifts
    over the run (this one did, by up to a third within one) then slows or speeds both sides alike."""
    walls = [w for part in slices for w in part["walls"]]
    compiles = [c for part in slices for c in part["compiles"]]
    frames = [f for part in slices for f in part["frames"]]
    return {"materials": len(walls), "seconds": sum(walls), "compiled": len(compiles), "reused": 0,
            "frame_s": statistics.median(frames) if frames else float("nan"),
            "compile_s": statistics.median(compiles) if compiles else float("nan"),
            "slices_s": [sum(part["walls"]) / len(part["walls"]) for part in slices if part["walls"]]}


def batch_cli(library: Path, size: int, out: Path) -> dict:
    started = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "shadergen.cli", "render", "--batch", str(library), "-o", str(out),
                          "--size", str(size)], capture_output=True, text=True, cwd=ROOT)
    seconds = time.perf_counter() - started
    summary = re.search(r"(\d+) materials: (\d+) thumbnails, (\d+) errors; (\d+) programs compiled, (\d+) reused",
                        run.stderr)
    if summary is None:
        raise SystemExit(f"the batch command failed: {run.stderr[-2000:]}")
    results = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()]
    frames = [r["timings_ms"]["frame"] / 1e3 for r in results if r.get("program_reused")]
    frame_s = statistics.fmean(frames) if frames else float("nan")
    # a program's cost is its compile and link, and the first draw's excess over a steady frame:
    # llvmpipe compiles the shader's machine code when the program first draws
    compiles = [(r["timings_ms"]["compile_link"] + r["timings_ms"]["first_frame"]) / 1e3 - frame_s
                for r in results if "png" in r and not r["program_reused"]]
    # means, not medians: the time per material it is held against is a mean too, and so carries
    # the same share of a busy machine's slow frames
    return {"materials": int(summary.group(1)), "errors": int(summary.group(3)), "seconds": seconds,
            "compiled": int(summary.group(4)), "reused": int(summary.group(5)), "frame_s": frame_s,
            "compile_s": statistics.fmean(compiles) if compiles else float("nan")}


def programs(client) -> dict[str, float]:
    text = client.get("/metrics").text
    return {m.group(1): float(m.group(2)) for m in re.finditer(r'shadergen_programs_total\{result="(\w+)"\} (\S+)', text)}


def service_batch(server: Server, paths: list[Path], size: int) -> dict:
    client = server.client
    before = programs(client)
    documents = [{"document": p.read_text(), "name": p.name} for p in paths]
    started = time.perf_counter()
    r = client.post("/v1/thumbnails/batch", json={"documents": documents, "size": size}, timeout=300)
    if r.status_code != 202:
        raise SystemExit(f"batch refused: {r.status_code} {r.text[:500]}")
    url = r.json()["status_url"]
    status = wait_until(lambda: (s := client.get(url).json())["state"] == "done" and s, 3600, "the batch", pause_s=0.25)
    seconds = time.perf_counter() - started
    after = programs(client)
    return {"materials": status["total"], "errors": status["failed"], "seconds": seconds,
            "compiled": after.get("compiled", 0) - before.get("compiled", 0),
            "reused": after.get("reused", 0) - before.get("reused", 0), "frame_s": float("nan"),
            "compile_s": float("nan")}


def local_service(tmp: Path, paths: list[Path], size: int, render_workers: int, routing: str, images: Path) -> dict:
    server = Server(tmp, workers=2, render_workers=render_workers,
                    env={"SHADERGEN_RENDER_ROUTING": routing, "SHADERGEN_TEXTURE_ROOTS": str(images),
                         "SHADERGEN_BATCH_CONCURRENCY": str(2 * render_workers),
                         "SHADERGEN_RENDER_QUEUE_SIZE": "64"})
    try:
        wait_until(lambda: server.client.get("/readyz").status_code == 200, 120, "readiness")
        return service_batch(server, paths, size)
    finally:
        server.close()


def celery_service(tmp: Path, paths: list[Path], size: int, workers: int, images: Path) -> dict:
    redis_server = RedisServer(tmp)
    env = {"SHADERGEN_BROKER": redis_server.url, "SHADERGEN_CACHE": redis_server.url,
           "SHADERGEN_TEXTURE_ROOTS": str(images), "SHADERGEN_BATCH_CONCURRENCY": str(2 * workers),
           "SHADERGEN_RENDER_QUEUE_SIZE": "64"}
    server = Server(tmp, workers=2, env=env)
    procs = []
    try:
        for i in range(workers):
            log = open(tmp / f"worker{i}.log", "wb")
            procs.append(subprocess.Popen([sys.executable, "-m", "shadergen.cli", "worker", "--concurrency", "1",
                                           "--name", f"bench{i}"],
                                          cwd=ROOT, env=server.env, stdout=log, stderr=subprocess.STDOUT))
        wait_until(lambda: server.client.get("/readyz").status_code == 200, 120, "a Celery worker")
        return service_batch(server, paths, size)
    finally:
        for proc in procs:
            stop(proc)
        server.close()
        stop(redis_server.proc)


def per_material(row: dict, topologies: int) -> tuple[float, float]:
    """(seconds per material, its goal: 1.3 x one frame plus its share of the compiles)."""
    seconds = row["seconds"] / row["materials"]
    goal = 1.3 * row["frame_s"] + row["compile_s"] * topologies / row["materials"]
    return seconds, goal


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--materials", type=int, default=500)
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--seed", type=int, default=23)
    parser.add_argument("--reference-sample", type=int, default=8, help="materials the reference's process draws")
    parser.add_argument("--celery-workers", type=int, default=2, help="0: no Celery run")
    parser.add_argument("--docs", action="store_true", help="write docs/library.md and docs/library.png")
    parser.add_argument("--shared", type=Path, default=ROOT.parent / "shared",
                        help="the folder of the corpus and the oracle (default: beside the checkout)")
    args = parser.parse_args()
    # the materials name their textures by real path: the service reads a name as written and wants
    # it inside its (real) texture roots, so one written through a link (a linked shared folder) is refused
    images = (args.shared / "corpus" / "resources" / "Images").resolve()
    # every run compiles for itself: Mesa's disk cache would hand a later run the programs of an earlier one
    os.environ["MESA_SHADER_CACHE_DISABLE"] = "true"
    tmp = Path(tempfile.mkdtemp(prefix="shadergen-library-"))
    library = tmp / "library"
    library.mkdir()
    paths = build_library(library, args.materials, args.seed, images)
    # the topologies: shading model x textured, as the source of each decides
    topologies = len({(re.search(r"<(\w+) name=\"\w+\" type=\"surfaceshader\"", p.read_text()).group(1),
                       "<image" in p.read_text()) for p in paths})
    runs = {"ours: batch CLI": lambda run_dir: batch_cli(library, args.size, run_dir)}

    def cli_costs() -> dict:  # the frame and program cost the service rows are held against
        return {key: rows["ours: batch CLI"][key] for key in ("frame_s", "compile_s")}

    for workers, routing in ((1, "topology"), (2, "topology"), (3, "topology"), (3, "shared")):
        runs[f"ours: service, {workers} local render workers, {routing} routing"] = (
            lambda run_dir, workers=workers, routing=routing:
            dict(local_service(run_dir, paths, args.size, workers, routing, images), **cli_costs()))
    if args.celery_workers:
        runs[f"ours: service, {args.celery_workers} Celery workers"] = (
            lambda run_dir: dict(celery_service(run_dir, paths, args.size, args.celery_workers, images),
                                 **cli_costs()))
    # the reference's sample in slices, one before each of our runs and one after the last (each
    # slice every k-th of the sample, so that every slice mixes the shading models)
    sample = paths[:: max(1, len(paths) // args.reference_sample)][: args.reference_sample]
    slices = [sample[i:: len(runs) + 1] for i in range(len(runs) + 1)]
    (tmp / "reference").mkdir()
    rows = {REFERENCE: None}
    reference_slices = []
    for k, (label, run) in enumerate(runs.items()):
        reference_slices.append(reference(slices[k], args.size, tmp / "reference", args.shared))
        run_dir = tmp / f"run{k}"
        run_dir.mkdir()
        rows[label] = run(run_dir)
        print(f"{label}:", rows[label], flush=True)
    reference_slices.append(reference(slices[-1], args.size, tmp / "reference", args.shared))
    rows[REFERENCE] = reference_row(reference_slices)
    print("reference:", rows[REFERENCE], flush=True)
    table = report(rows, topologies, args)
    print(table)
    if args.docs:
        write_docs(rows, table, args)
    ref = rows[REFERENCE]
    ref_rate = ref["materials"] / ref["seconds"]
    best = max((r for k, r in rows.items() if k.startswith("ours")), key=lambda r: r["materials"] / r["seconds"])
    cli = rows["ours: batch CLI"]
    parts = [f"{args.materials} materials", f"{topologies} topologies", f"{cli['compiled']} compiles"]
    parts += [f"{k.removeprefix('ours: ')} {r['materials'] / r['seconds']:.1f}/s, hit rate "
              f"{r['reused'] / max(1, r['compiled'] + r['reused']):.0%}" for k, r in rows.items() if k.startswith("ours")]
    parts.append(f"{best['materials'] / best['seconds'] / ref_rate:.1f} times the reference's throughput")
    print("library: " + " | ".join(parts))


def report(rows: dict, topologies: int, args) -> str:
    ref = rows[REFERENCE]
    ref_rate = ref["materials"] / ref["seconds"]
    drift = ", ".join(f"{seconds:.2f}" for seconds in ref["slices_s"])
    lines = [f"{args.materials} materials ({topologies} topologies), {args.size} px, seed {args.seed}; the "
             f"reference's sample drawn in slices before, between and after our runs (s/material: {drift})", "",
             "| run | materials | errors | materials/s | x reference | compiled | reused | hit rate | s/material | "
             "goal s/material |", "|---|---|---|---|---|---|---|---|---|---|"]
    for label, r in rows.items():
        rate = r["materials"] / r["seconds"]
        seconds, goal = per_material(r, topologies if label.startswith("ours") else r["materials"])
        hit = r["reused"] / max(1, r["compiled"] + r["reused"])
        lines.append(f"| {label} | {r['materials']} | {r.get('errors', 0)} | {rate:.2f} | {rate / ref_rate:.1f} | "
                     f"{r['compiled']:.0f} | {r['reused']:.0f} | {hit:.0%} | {seconds:.3f} | {goal:.3f} |")
    return "\n".join(lines)


def write_docs(rows: dict, table: str, args) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    docs = ROOT / "docs"
    labels = [k.removeprefix("ours: ") for k in rows]
    rates = [r["materials"] / r["seconds"] for r in rows.values()]
    fig, ax = plt.subplots(figsize=(8, 0.6 * len(rows) + 1.2))
    ax.barh(labels, rates, color=["grey"] + ["tab:blue"] * (len(rows) - 1))
    ax.set_xlabel("materials per second")
    ax.set_title(f"{args.materials}-material library, {args.size} px thumbnails")
    ax.invert_yaxis()
    fig.tight_layout()
    fig.savefig(docs / "library.png", dpi=100)
    (docs / "library.md").write_text("# A library thumbnailed (bench/library.py)\n\n" + table +
                                     "\n\n![materials per second](library.png)\n")


if __name__ == "__main__":
    main()
