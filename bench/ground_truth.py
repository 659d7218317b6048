#!/usr/bin/env python3
"""Accuracy against ground truth (issue 26): every Examples material path-traced by OSL's
`testrender` in our thumbnail scene (tools/ground_truth_scene.py), and the error of every
real-time image of it against that.

The ground truth of a material is our OSL for it (`generate --target osl`, specialized: the
document's values folded in) as the sphere's surface, lit by the procedural sky as infinitely
distant light, rendered to convergence: at twice the side, each 2 x 2 block averaged, samples per
sub-pixel quadrupled from --start-samples until the render's noise, estimated against the same
pixels at a quarter of its samples (gts.nested_noise_psnr), is under --converged-db (PSNR over the
sphere, sRGB, peak 1), or --max-samples.
It is cached by the OSL as the scene runs it (scene_form), the scene and the map (--cache, default
~/.cache/shadergen/ground_truth/); a cached truth short of --converged-db is converged on from its
last render by a run with more --max-samples. With --truths-only a run only path-traces (a long,
niced run ahead of a quiet measuring one).

Against it, at --size: our GL thumbnail (`complete` and `specialized`) with `fis`, `prefilter` and
`hybrid` environment lighting at bench/accuracy_time.py's points, our WGSL on wgpu (fis, its
sample counts), and the reference's shader on our renderer (the oracle's record, fis): PSNR over
the sphere's pixels with accuracy_time's measure (clipped, sRGB-encoded, peak 1), and the steady
frame time. The scene's own checks come first: a white Lambertian in a constant white environment
(must give 1), a mirror sphere against the environment computed directly, and our GL image of an
Oren-Nayar diffuse against testrender's of the same closure (orientation and the map convention).

    .venv/bin/python bench/ground_truth.py [--size 128] [--filter NAME] [--table docs/ground_truth.md]
        [--plot docs/ground_truth.png]
"""
import argparse
import glob
import math
import os
import statistics
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.join(ROOT, "tools"))

from accuracy import SHARED  # noqa: E402
from accuracy_time import SAMPLE_COUNTS, fmt, label, points, psnr, records  # noqa: E402
import ground_truth_scene as gts  # noqa: E402
from shadergen.render.inputs import ENV_SAMPLES  # noqa: E402 - a thumbnail's FIS samples

EXAMPLES = "resources/Materials/Examples/StandardSurface"
GOAL_DB = 35.0
DIFFUSE_CHECK = '''<?xml version="1.0"?>
<materialx version="1.39">
  <oren_nayar_diffuse_bsdf name="diffuse" type="BSDF"><input name="color" type="color3" value="0.8, 0.8, 0.8"/></oren_nayar_diffuse_bsdf>
  <surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="diffuse"/></surface>
  <surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/></surfacematerial>
</materialx>
'''
# A smooth glass sphere holding an amber medium (OpenPBR's transmission_color over transmission_depth):
# testrender 1.13 ignores media, so its truth is computed directly (gts.glass_sphere_image).
GLASS_CHECK = '''<?xml version="1.0"?>
<materialx version="1.39">
  <open_pbr_surface name="glass" type="surfaceshader">
    <input name="base_weight" type="float" value="0"/>
    <input name="specular_roughness" type="float" value="0"/>
    <input name="specular_ior" type="float" value="1.5"/>
    <input name="transmission_weight" type="float" value="1"/>
    <input name="transmission_color" type="color3" value="{color}"/>
    <input name="transmission_depth" type="float" value="{depth}"/>
  </open_pbr_surface>
  <surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="glass"/></surfacematerial>
</materialx>
'''
AMBER = (0.9, 0.55, 0.15)
# The cause of each material below GOAL_DB or below the reference, with the evidence, measured by
# hand from the cached truths of 256 samples per pixel (ours and the reference's GL images at fis
# 256, 128x128, against the truth: PSNR, the mean per channel and the signed error per N.V band
# over the sphere).
CAUSES = {
    "standard_surface_brick_procedural": (
        "texture footprint, in the main: the truth is each pixel's area (2x2 sub-pixels of many samples, each texture "
        "read at its ray's footprint), ours one point per pixel whose MIP-filtered inputs enter a non-linear graph (a "
        "mask mixes mortar and brick and divides the roughness): the base colour alone (an emission variant) is 29.8 dB"
        " from the truth at 128 px (mortar red +15-25 %, blue -20-33 %), 42.0 dB at 512 px averaged 4x4. Of the 7 % "
        "more light, part was the truth's: testrender's dPdv points south, the thumbnail's bitangent north, so the "
        "normal map tilted the other way along v (the truth 4-8 % darker in the middle and lower bands); now -dPdv "
        "(gts.THUMBNAIL_BITANGENT): ours at 512 averaged 4x4 35.9 -> 38.7 dB. The rest, ours 3 % brighter at 512/4, "
        "most at grazing angles and in the mortar, is testrender's single-scattering GGX: with specular_roughness 0.5 "
        "ours is within 1 % of the truth, with 1.0 (the mortar's: roughness_amount / mask, clamped) 5 % brighter, as "
        "layer_coat_r1 in docs/furnace_truth.md (testrender 0.959, ours 1.000); without specular within 0.5 %"),
    "standard_surface_thin_film": (
        "testrender limitation: it ignores thin films (see furnace_truth); ours with thin_film_thickness 0 is 38.6 dB "
        "from the truth, ours with the 550 nm film 18.2 dB (the reference's too): the truth is the film-less glass"),
    "standard_surface_velvet": (
        "fixed here: our sheen's environment term was the irradiance at N times the lobe's albedo, not the lobe's "
        "directions (25.8 dB, the reference's too: the sky-facing rim too bright, the ground-facing one too dark); now "
        "the lobe sampled (mx_sheen_environment). The prefiltered way's one lookup keeps the irradiance"),
    "standard_surface_wood_tiled": (
        "the scene's (u, v) were testrender's own before (35.4 dB); the thumbnail sphere's now (scene_form)"),
    "standard_surface_brass_tiled": (
        "the scene's (u, v) were testrender's own before (38.0 dB); the thumbnail sphere's now (scene_form)"),
    "standard_surface_glass": (
        "fixed here: the transmission applied the interface's Fresnel twice; before (067970f) ours was 35.7 dB from "
        "that graph's truth and 32.2 dB from this one (fis 256)"),
}
# Pixels within this many of the silhouette are not compared: testrender's pixel filter blends them
# with the sky, our thumbnail draws them uncovered or covered by a tessellated sphere.
SILHOUETTE_INSET = 2.0


def truth_rgba(rgb: np.ndarray) -> np.ndarray:
    """The ground truth as RGBA, alpha the sphere's pixels SILHOUETTE_INSET inside its silhouette
    (accuracy_time.psnr's mask)."""
    return np.concatenate([rgb, gts.sphere_mask(rgb.shape[0], SILHOUETTE_INSET)[..., None].astype("f8")], -1)


def converge(render, side: int, args, done: dict | None = None) -> dict:
    """Quadruples the samples until the estimated noise is under args.converged_db; render(side,
    samples). testrender takes aa x aa samples: aa doubles, so that each render's first quarter is
    the one before it (the noise's estimate needs that), from an even aa of at least
    args.start_samples, estimated against aa / 2; or on from `done`, a truth converged this way
    before (its render the next one's first quarter)."""
    mask = gts.sphere_mask(side, SILHOUETTE_INSET)
    start = time.perf_counter()
    if done is None:
        aa = max(2, math.ceil(math.sqrt(args.start_samples)))
        aa += aa % 2
        coarse, before = gts.pixel_mean(render(2 * side, (aa // 2) ** 2)), 0.0
    else:
        aa = 2 * math.isqrt(done["samples"] // 4)
        coarse, before = done["rgb"], done["seconds"]
    while True:
        fine = gts.pixel_mean(render(2 * side, aa * aa))
        noise_db = gts.nested_noise_psnr(coarse, fine, mask)
        if noise_db >= args.converged_db or aa * aa >= args.max_samples:
            # the four sub-pixels per output pixel: 4 aa^2 samples per output pixel
            return {"rgb": fine, "samples": 4 * aa * aa, "noise_db": noise_db,
                    "seconds": before + time.perf_counter() - start}
        coarse, aa = fine, 2 * aa


def truth_key(args, *parts: str) -> str:
    """The cache key of a truth of `parts` (what testrender reads and how it is run) at args.size,
    rendered by this scene (its code's bytes): not the samples, which a later run may add to."""
    return gts.digest(*parts, str(args.size), open(gts.__file__, "rb").read())


def cached_truth(key: str, render, side: int, args) -> dict:
    """The truth cached under `key` where it is converged (or has --max-samples), else converged
    on from the cached one (or from the start) and cached."""
    path = os.path.join(args.cache, f"{key}.npz")
    done = None
    try:
        with np.load(path) as f:
            done = {"rgb": f["rgb"], "samples": int(f["samples"]), "noise_db": float(f["noise_db"]),
                    "seconds": float(f["seconds"])}
    except (OSError, ValueError, KeyError, EOFError):
        pass
    if done is not None and (done["noise_db"] >= args.converged_db or done["samples"] >= 4 * args.max_samples):
        return {**done, "cached": True}
    result = converge(render, side, args, done)
    os.makedirs(args.cache, exist_ok=True)
    tmp = path + f".{os.getpid()}.npz"
    np.savez(tmp, **{k: v for k, v in result.items()})
    os.replace(tmp, path)
    return {**result, "cached": False}


def scene_form(source: str) -> str:
    """Our OSL as testrender can run it in the thumbnail scene. testrender 1.13 aborts on a
    transform from "object" space (SimpleRaytracer::get_matrix reads the object matrix its spheres
    do not have; gdb backtrace from standard_surface_marble_solid's `transform("object", P)`); the
    scene's sphere is the unit sphere at the origin, so object space is common (world) space there.
    Its sphere's (u, v) are not the thumbnail sphere's: the texture coordinates (the OSL target's
    spelling of a texcoord, OslTarget.geometry) are the thumbnail sphere's at P instead
    (gts.THUMBNAIL_U, THUMBNAIL_V), and so is the bitangent (its dPdv points the other way:
    gts.THUMBNAIL_BITANGENT)."""
    u, v = gts.THUMBNAIL_U, gts.THUMBNAIL_V
    return (source.replace('transform("object", ', 'transform("common", ')
            .replace("vector2(u, v)", f"vector2({u}, {v})").replace("vector(u, v, 0.0)", f"vector({u}, {v}, 0.0)")
            .replace("normalize(dPdv)", f"normalize({gts.THUMBNAIL_BITANGENT})"))


def material_truth(document: str, world: gts.Scene, env_key: str, args) -> dict:
    """The ground truth of the document's first renderable element, or {"error": message}."""
    from shadergen.api import generate_file

    record = generate_file(document, target="osl", interface="specialized")[0]
    if "error" in record:
        return {"error": f"OSL target: {record['error']['message']}", "element": record.get("element")}
    source = scene_form(record["stages"]["pixel"])
    name = f"material_{gts.digest(source)}"
    if (message := world.add_surface(source, name)) is not None:
        return {"error": f"oslc: {message.splitlines()[0]}", "element": record.get("element")}
    output = world.closure_output(name)
    if output is None:
        return {"error": "the OSL shader has no closure output", "element": record.get("element")}
    # the scene as it renders, less the temporary folder it lies in
    xml_probe = gts.scene_xml(world.material_group(name, output), *world.environment()).replace(world.folder, "")
    # what testrender reads and how it is run: the shader as the scene runs it, not the record's hash,
    # which moves with every library and generator file (fingerprint.py) while the OSL stays the same
    key = truth_key(args, source, xml_probe, env_key)

    def render(side, samples):
        return world.render_material(name, output, side, samples, cwd=os.path.dirname(document))

    return {**cached_truth(key, render, args.size, args), "element": record.get("element")}


def scene_checks(world: gts.Scene, renderer, args) -> tuple[list[str], dict]:
    """The scene against answers known without testrender's materials; and the converged
    testrender image of the Oren-Nayar check (a scene shader of the same closure as DIFFUSE_CHECK)."""
    from shadergen.api import Generator

    lines = [f"testrender's cold build (scripts/osl.sh): {gts.build_time()}"]
    side = 32
    furnace = world.render("white_lambert", side, 64, constant=1.0)
    mask = gts.sphere_mask(side)
    lines.append(f"white furnace (white Lambertian, constant white environment, {side}x{side}, 64 spp): "
                 f"mean {furnace[mask].mean():.4f} (expected 1)")
    mirror = world.render("mirror", args.size, 16)
    direct = gts.mirror_image(world.radiance, args.size)
    lines.append(f"mirror sphere against the environment computed directly: "
                 f"{gts.psnr_viewed(mirror, direct, gts.sphere_mask(args.size, SILHOUETTE_INSET)):.1f} dB over the sphere")
    key = truth_key(args, "white_lambert 0.8", world.radiance.tobytes())
    truth = cached_truth(key, lambda s, n: world.render("white_lambert", s, n,
                                                        surface_params={"albedo": "color 0.8 0.8 0.8"}),
                         args.size, args)
    gl = renderer.render(Generator().prepare(DIFFUSE_CHECK).emit(), size=args.size, env_samples=1024).rgba
    rgb = truth["rgb"]
    exact = gts.lambert_image(world.radiance, args.size, 0.8)
    inner = gts.sphere_mask(args.size, SILHOUETTE_INSET)
    lines.append(f"Oren-Nayar diffuse 0.8 (roughness 0: Lambert) by direct quadrature of the map's irradiance: "
                 f"testrender {gts.psnr_viewed(rgb, exact, inner):.1f} dB from it, our GL "
                 f"{gts.psnr_viewed(gl, exact, inner):.1f} dB, our irradiance map (order-2 spherical harmonics) "
                 f"x 0.8 read at the normals {gts.psnr_viewed(0.8 * gts.lookup(world.irradiance, gts.sphere_normals(args.size)), exact, inner):.1f} dB")
    lines.append(f"Oren-Nayar diffuse 0.8: our GL (fis 1024) against testrender ({truth['samples']} spp, noise "
                 f"{truth['noise_db']:.1f} dB): {psnr(gl, truth_rgba(rgb)):.1f} dB; against it mirrored left-right "
                 f"{psnr(gl, truth_rgba(rgb[:, ::-1])):.1f} dB, upside down {psnr(gl, truth_rgba(rgb[::-1])):.1f} dB")
    return lines, truth


def glass_checks(world: gts.Scene, renderer, args) -> list[str]:
    """Our GL glass sphere, clear and amber (depth 1), against the sphere computed directly (every
    internal path; testrender 1.13 ignores media). Our media take the transmittance along the
    refracted chord of the unit sphere our refraction assumes (mx_vdf.glsl)."""
    from shadergen.api import Generator

    side, inner = args.size, gts.sphere_mask(args.size, SILHOUETTE_INSET)

    def ours(color, depth):
        document = GLASS_CHECK.format(color=", ".join(f"{c:g}" for c in color), depth=f"{depth:g}")
        return renderer.render(Generator().prepare(document).emit(), size=side, env_samples=64).rgba[..., :3]

    def mean(image):
        return "/".join(f"{c:.3f}" for c in image[inner].mean(0))

    clear_truth = gts.glass_sphere_image(world.radiance, side, 1.5)
    clear = ours((1.0, 1.0, 1.0), 0.0)
    amber_truth = gts.glass_sphere_image(world.radiance, side, 1.5, -np.log(np.asarray(AMBER)))
    amber = ours(AMBER, 1.0)
    return [f"smooth glass sphere (open_pbr_surface, ior 1.5, transmission 1) against the sphere computed directly "
            f"(every internal path): clear {gts.psnr_viewed(clear, clear_truth, inner):.1f} dB, mean ours {mean(clear)} "
            f"exact {mean(clear_truth)}; transmission_color {'/'.join(f'{c:g}' for c in AMBER)} at depth 1: "
            f"{gts.psnr_viewed(amber, amber_truth, inner):.1f} dB, mean ours {mean(amber)} exact {mean(amber_truth)}"]


def measure(document: str, truth: np.ndarray, renderers: dict, args) -> list[dict]:
    """Every real-time image of the document against the truth: (shader, interface, method,
    samples, frame_ms, psnr)."""
    from shadergen.api import generate_file

    reference_done = False
    rows = []
    options = dict(size=args.size, document_dir=os.path.dirname(document), frames=args.frames)
    for interface in ("complete", "specialized"):
        shaders = records(document, interface)
        for method, samples in points("ours"):
            result = renderers["gl"].render(shaders[("ours", method)], env_method=method, env_samples=samples, **options)
            rows.append({"shader": "ours GL", "interface": interface, "method": method, "samples": samples,
                         "frame_ms": result.timings_ms["frame"], "psnr": psnr(result.rgba, truth)})
        if not reference_done:
            for method, samples in points("reference"):
                result = renderers["gl"].render(shaders[("reference", "fis")], env_samples=samples, **options)
                rows.append({"shader": "reference GL", "interface": "complete", "method": method, "samples": samples,
                             "frame_ms": result.timings_ms["frame"], "psnr": psnr(result.rgba, truth)})
            reference_done = True
    wgsl = generate_file(document, target="wgsl", interface="specialized")[0]
    if "error" not in wgsl:
        for samples in SAMPLE_COUNTS:
            result = renderers["wgpu"].render(wgsl, env_samples=samples, **options)
            rows.append({"shader": "ours WGSL", "interface": "specialized", "method": "fis", "samples": samples,
                         "frame_ms": result.timings_ms["frame"], "psnr": psnr(result.rgba, truth)})
    return rows


def summary(material: dict) -> dict:
    """Per material: our best and the reference's best PSNR, and both at the reference's 16 samples."""
    rows = material["rows"]
    ours = [r for r in rows if r["shader"].startswith("ours")]
    reference = [r for r in rows if r["shader"] == "reference GL"]
    ref16 = next((r for r in reference if r["samples"] == 16), None)
    in_budget = [r for r in ours if ref16 and r["frame_ms"] <= ref16["frame_ms"]]
    thumbnail = next((r for r in ours if r["shader"] == "ours GL" and r["interface"] == "specialized"
                      and r["method"] == "fis" and r["samples"] == ENV_SAMPLES), None)
    return {"ours_best": max(r["psnr"] for r in ours), "reference_best": max(r["psnr"] for r in reference),
            "ref16": ref16["psnr"] if ref16 else float("nan"),
            "ours_in_budget": max((r["psnr"] for r in in_budget), default=float("nan")),
            "thumbnail": thumbnail["psnr"] if thumbnail else float("nan")}


def summary_line(materials: list[dict]) -> str:
    measured = [summary(m) for m in materials if "rows" in m]
    ours = [s["ours_best"] for s in measured]
    reference = [s["reference_best"] for s in measured]

    def stats(values):
        return f"min {fmt(min(values))} dB median {fmt(statistics.median(values))} dB" if values else "min - median -"

    below = sum(v < GOAL_DB for v in ours)
    return (f"ground truth: {len(measured)} materials | ours {stats(ours)} | reference {stats(reference)} | "
            f"ours below {GOAL_DB:.0f} dB: {below} | no ground truth: {len(materials) - len(measured)} of {len(materials)}")


def write_table(path: str, checks: list[str], materials: list[dict], args, last_line: str) -> None:
    lines = ["# Accuracy against ground truth (OSL testrender)", "",
             f"Written by `bench/ground_truth.py` ({args.size}x{args.size}). The ground truth is our OSL "
             "(`generate --target osl`, specialized) path-traced by OSL 1.13's testrender in the thumbnail scene "
             "(tools/ground_truth_scene.py); PSNR over the sphere's pixels, clipped to [0, 1], sRGB-encoded, peak 1.",
             "", "## Scene checks", ""] + [f"- {c}" for c in checks] + ["", "## Materials", "",
             "| material | truth spp | truth noise dB | ours best dB | ours <= ref-16 time dB | reference 16 dB | "
             f"reference best dB | ours thumbnail (specialized fis {ENV_SAMPLES}) dB | note |",
             "|---|---|---|---|---|---|---|---|---|"]
    for m in materials:
        if "error" in m:
            lines.append(f"| {m['name']} | - | - | - | - | - | - | - | {m['error'][:160]} |")
            continue
        s = summary(m)
        lines.append(f"| {m['name']} | {m['truth']['samples']} | {fmt(m['truth']['noise_db'])} | "
                     f"{fmt(s['ours_best'])} | {fmt(s['ours_in_budget'])} | {fmt(s['ref16'])} | "
                     f"{fmt(s['reference_best'])} | {fmt(s['thumbnail'])} | "
                     f"{m.get('cause') or CAUSES.get(m['name'], '')} |")
    measured = [m for m in materials if "rows" in m]
    if measured:
        lines += ["", "## Every point", "", "| material | shader | interface | point | frame ms | PSNR dB |",
                  "|---|---|---|---|---|---|"]
        for m in measured:
            for r in m["rows"]:
                lines.append(f"| {m['name']} | {r['shader']} | {r['interface']} | {label(r['method'], r['samples'])} | "
                             f"{fmt(r['frame_ms'], 2)} | {fmt(r['psnr'])} |")
    lines += ["", "```", last_line, "```", ""]
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


def plot(materials: list[dict], path: str, args) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker

    measured = [m for m in materials if "rows" in m]
    if not measured:
        return
    columns = min(4, len(measured))
    fig, axes = plt.subplots(math.ceil(len(measured) / columns), columns, figsize=(4.2 * columns, 3.4 * math.ceil(
        len(measured) / columns)), squeeze=False)
    styles = {("ours GL", "complete"): "tab:blue", ("ours GL", "specialized"): "tab:cyan",
              ("ours WGSL", "specialized"): "tab:purple", ("reference GL", "complete"): "tab:orange"}
    for ax, m in zip(axes.flat, measured):
        for (shader, interface), colour in styles.items():
            for method, marker in (("fis", "o-"), ("hybrid", "s--"), ("prefilter", "*")):
                rows = [r for r in m["rows"] if r["shader"] == shader and r["interface"] == interface
                        and r["method"] == method]
                if rows:
                    ax.plot([r["frame_ms"] for r in rows], [r["psnr"] for r in rows], marker, color=colour,
                            label=f"{shader} {interface} {method}", markersize=5)
        ax.axhline(GOAL_DB, color="grey", linestyle=":", linewidth=0.8)
        ax.set_xscale("log")
        # ticks at 1, 2 and 5 per decade, labelled as plain numbers: matplotlib's own labels every
        # minor tick of a range within about a decade, and those overlap
        ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda x, _: f"{x:g}"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.tick_params(labelsize=7)
        ax.set_title(m["name"], fontsize=9)
        ax.set_xlabel("steady frame, ms (log)", fontsize=8)
        ax.set_ylabel("PSNR vs ground truth, dB", fontsize=8)
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(measured):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=6, loc="lower right")
    fig.suptitle(f"Error against the testrender ground truth, against frame time ({args.size}x{args.size}; "
                 f"dotted: {GOAL_DB:.0f} dB)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("documents", nargs="*", help="default: the corpus's Examples materials")
    parser.add_argument("--corpus", default=os.path.join(SHARED, "corpus"), help="default: ../shared/corpus")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--filter", default="", help="only documents whose file name contains this")
    parser.add_argument("--cache", default=os.path.join(os.path.expanduser("~"), ".cache", "shadergen", "ground_truth"))
    parser.add_argument("--start-samples", type=int, default=64,
                        help="samples per sub-pixel of the first estimate (its noise from a quarter of them)")
    parser.add_argument("--max-samples", type=int, default=16384, help="samples per sub-pixel at most")
    parser.add_argument("--converged-db", type=float, default=50.0,
                        help="the estimated noise's PSNR that counts as converged")
    parser.add_argument("--frames", type=int, default=3, help="frames per real-time render (the first is not timed)")
    parser.add_argument("--truths-only", action="store_true",
                        help="path-trace and cache the truths, measure nothing (a long run ahead of a quiet one)")
    parser.add_argument("--table", default=os.path.join(ROOT, "docs", "ground_truth.md"))
    parser.add_argument("--plot", default=os.path.join(ROOT, "docs", "ground_truth.png"))
    args = parser.parse_args()
    if gts.testrender() is None:
        raise SystemExit("testrender is not installed (scripts/osl.sh builds it)")

    from shadergen.render import Renderer
    from shadergen.render.environment import Environment
    from shadergen.render.wgpu_renderer import WgpuRenderer

    documents = args.documents or sorted(glob.glob(os.path.join(args.corpus, EXAMPLES, "*.mtlx")))
    documents = [d for d in documents if args.filter in os.path.basename(d)]
    environment = Environment.procedural()
    env_key = gts.digest(environment.radiance.tobytes())
    renderers = {"gl": Renderer(search_paths=[args.corpus], confined=False),
                 "wgpu": WgpuRenderer(search_paths=[args.corpus], confined=False)}
    with tempfile.TemporaryDirectory(prefix="ground-truth-") as folder:
        world = gts.Scene(folder, environment.radiance)
        world.irradiance = environment.irradiance
        checks, diffuse = scene_checks(world, renderers["gl"], args)
        if not args.truths_only:
            checks += glass_checks(world, renderers["gl"], args)
        for line in checks:
            print(line, flush=True)
        # the table's machinery on the check: every real-time image of DIFFUSE_CHECK against testrender's
        # image of the same closure (a scene shader, not our OSL: it is not counted with the materials)
        check_document = os.path.join(folder, "oren_nayar_check.mtlx")
        with open(check_document, "w", encoding="utf-8") as f:
            f.write(DIFFUSE_CHECK)
        rows = [] if args.truths_only else measure(check_document, truth_rgba(diffuse["rgb"]), renderers, args)
        check = {"name": "check: oren_nayar_diffuse_bsdf 0.8", "truth": diffuse, "rows": rows,
                 "cause": "truth: testrender's oren_nayar_diffuse_bsdf (a scene shader), not our OSL"}
        if rows:
            s = summary(check)
            print(f"{check['name']}: ours best {fmt(s['ours_best'])} dB, reference best {fmt(s['reference_best'])} dB",
                  flush=True)
        materials = []
        for document in documents:
            name = os.path.splitext(os.path.basename(document))[0]
            try:
                truth = material_truth(document, world, env_key, args)
            except Exception as exc:  # a material the scene cannot render is a row, not the end of the run
                truth = {"error": f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"}
            if "error" in truth:
                materials.append({"name": name, "error": truth["error"]})
                print(f"{name}: no ground truth: {truth['error']}", flush=True)
                continue
            if args.truths_only:
                print(f"{name}: truth {truth['samples']} spp (noise {truth['noise_db']:.1f} dB, "
                      f"{'cached' if truth['cached'] else format(truth['seconds'], '.0f') + ' s'})", flush=True)
                continue
            try:
                rows = measure(document, truth_rgba(truth["rgb"]), renderers, args)
            except SystemExit as exc:
                materials.append({"name": name, "error": f"real-time: {exc}"})
                print(f"{name}: {exc}", flush=True)
                continue
            materials.append({"name": name, "truth": truth, "rows": rows})
            s = summary(materials[-1])
            took = "cached" if truth["cached"] else f"{truth['seconds']:.0f} s"
            print(f"{name}: truth {truth['samples']} spp (noise {truth['noise_db']:.1f} dB, "
                  f"{took}); ours best {fmt(s['ours_best'])} dB, "
                  f"reference best {fmt(s['reference_best'])} dB", flush=True)
            # the table so far, so that a run stopped early leaves the materials it finished
            write_table(args.table, checks, [check] + materials, args, summary_line(materials) + " (so far)")
    if args.truths_only:
        return 0
    last = summary_line(materials)
    write_table(args.table, checks, [check] + materials, args, last)
    plot([check] + materials, args.plot, args)
    print(last)
    return 0


if __name__ == "__main__":
    sys.exit(main())
