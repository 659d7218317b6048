"""testshade against GL: every TestSuite/stdlib element whose output is a value (not a closure),
our OSL evaluated by OSL's testshade on a 64 x 64 grid of texture coordinates and our GLSL drawn on
the GL plane at the same points; per element the largest absolute difference, and how many
elements agree within 1e-4 relative (|osl - gl| <= 1e-4 * max(1, |gl|)).

The two see the same scene: testshade shades pixel (x, y) at u = (x + 0.5) / 64, v = (y + 0.5) / 64
with P = (u, v, 1), N = (0, 0, 1), dPdu = (1, 0, 0), dPdv = (0, 1, 0) and its own object space (a
quarter turn and a shift of world space); the GL side draws a plane of its own at world (u, v, 1),
with testshade's object-to-world matrix, that normal and tangent, and a view-projection that maps
it onto the whole image, so each pixel centre is the same point in both spaces. Both take the
document's values in the source (values="source"); file names resolve against the corpus, as the
documents write them.

    .venv/bin/python bench/osl.py --agreement [--filter NAME]

testshade gets what the GL scene sets that no shader global of its holds (the frame number). Each
outlier's row names its cause (CAUSES, told by what its GLSL reads and calls), and the report
counts the outliers per cause; docs/osl_agreement.md is the table with the evidence for each cause.

    .venv/bin/python bench/osl.py --agreement --mipmapped   # file images filtered as the product does

Measured here (2 shared cores, Mesa llvmpipe), like for like: 587 of 592 within 1e-4 relative
(99.2 %; 565, 95.4 %, before the address-mode, cubic, texel-edge and asin fixes); the 5 outliers
are named in docs/osl_agreement.md (hex tiling, derivatives).
"""
import collections
import glob
import os
import subprocess
import tempfile

import numpy as np

from shadergen.api import DocumentFile
from shadergen.targets.osl.check import compile_shaders, tool

SIZE = 64
TOLERANCE = 1e-4
# (u, v, 1) -> clip (2u - 1, 2v - 1, 0, 1): the plane fills the image
VIEW_PROJECTION = np.array([[2.0, 0, 0, -1.0], [0, 2.0, 0, -1.0], [0, 0, 0, 0], [0, 0, 0, 1.0]])
# testshade's object-to-common matrix (a quarter turn about z and a shift, testshade.cpp's Mobj, as
# matrix("object", "common") prints it), for column vectors: object (x, y, z) is world (-y, x + 1, z)
WORLD = np.array([[0, -1.0, 0, 0], [1.0, 0, 0, 1.0], [0, 0, 1.0, 0], [0, 0, 0, 1.0]])


def plane_scene() -> None:
    """The GL renderer's plane and scene replaced by testshade's: the plane at world (u, v, 1),
    its object space testshade's, a view-projection that fills the image with it."""
    from shadergen.render import geometry, inputs, scene

    def plane() -> geometry.Mesh:
        uv = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], "f4")
        world = np.concatenate([uv, np.ones((4, 1), "f4"), np.ones((4, 1), "f4")], axis=1)
        position = (np.linalg.inv(WORLD) @ world.T).T[:, :3].astype("f4")
        normal = np.tile(np.array([0, 0, 1], "f4"), (4, 1))
        tangent = np.tile(np.array([0, -1, 0], "f4"), (4, 1))  # world (1, 0, 0), testshade's dPdu
        return geometry._mesh("plane", position, normal, uv, tangent, np.array([0, 1, 2, 0, 2, 3]))

    def uniforms(depth_zero_to_one: bool = False) -> dict:
        values = scene.scene_uniforms(depth_zero_to_one)
        inverse = np.linalg.inv(WORLD)
        values.update({"u_worldMatrix": WORLD, "u_worldInverseMatrix": inverse, "u_worldTransposeMatrix": WORLD.T,
                       "u_worldInverseTransposeMatrix": inverse.T, "u_viewProjectionMatrix": VIEW_PROJECTION,
                       "u_worldViewProjectionMatrix": VIEW_PROJECTION @ WORLD,
                       "u_worldViewMatrix": values["u_viewMatrix"] @ WORLD})
        return values
    geometry.plane = plane
    inputs.scene_uniforms = uniforms


# Like for like (the default): file images read the same way on both sides, one bilinear (bicubic,
# closest) lookup of the base level. Our OSL is generated with a zero filter width for its texture()
# calls (the osl target's texture_width, api.prepare_all), the GL renderer binds file images without
# their mipmaps (Renderer's file_mipmaps). The product filters as each library does (OIIO's
# footprint over the file, GL's trilinear mip chain): --mipmapped measures that instead.


def testshade(source: str, folder: str, corpus: str) -> np.ndarray:
    """Our OSL evaluated by testshade: the colour output and its alpha, rows of increasing v."""
    failed = compile_shaders({"shader": ("pixel", source)}, folder)
    if failed:
        raise RuntimeError(failed["shader"])
    colour, alpha = os.path.join(folder, "out.exr"), os.path.join(folder, "alpha.exr")
    from shadergen.render import scene
    # what the GL scene sets and no shader global of testshade's holds: the frame number
    params = ["--param", "u_frame", repr(scene.FRAME)] if "float u_frame =" in source else []
    subprocess.run([tool("testshade"), "-t", "1", "--res", str(SIZE), str(SIZE), "--center", "-d", "float",
                    "-o", "out1", colour, "-o", "out1_alpha", alpha, *params, os.path.join(folder, "shader0")],
                   capture_output=True, text=True, timeout=120, check=True, cwd=corpus)
    import OpenImageIO as oiio
    rgb = oiio.ImageBuf(colour).get_pixels(oiio.FLOAT)
    a = oiio.ImageBuf(alpha).get_pixels(oiio.FLOAT)
    return np.concatenate([rgb.reshape(SIZE, SIZE, -1)[..., :3], a.reshape(SIZE, SIZE, -1)[..., :1]], axis=2)


# Why an element disagrees, told by what its GLSL reads and calls (the first that matches); each
# was verified on the elements it names (docs/osl_agreement.md)
DERIVATIVES = ("derivatives: GL's finite differences over a 2 x 2 pixel quad against OSL's exact (automatic) "
               "ones of the same expression")
FILTERED = ("image filtering: like for like, a fraction of a texel next to a 1-texel line (hex tiling's rotated "
            "tiles); with --mipmapped, OIIO's texture() filter footprint over the file against GL's trilinear mip "
            "chain")
CAUSES = (
    (lambda glsl: "mx_heighttonormal" in glsl, DERIVATIVES),
    (lambda glsl: "mx_hextilednormalmap" in glsl,
     FILTERED + ", amplified by the surface-gradient blend where a texel decodes to a normal near the tangent "
     "plane (grid.png is no normal map)"),
    (lambda glsl: "sampler2D" in glsl, FILTERED),
)


def cause(rec: dict) -> str:
    """The cause of `rec`'s disagreement (CAUSES), or "unexplained"."""
    glsl = rec["stages"]["pixel"]
    return next((text for test, text in CAUSES if test(glsl)), "unexplained")


def differences(gen, corpus: str, name_filter: str | None = None, like_for_like: bool = True) -> list[tuple]:
    """(element, largest absolute difference, largest relative one, share of pixels within the
    tolerance, cause) per value element; `like_for_like`: file images read as the comment above testshade says."""
    from shadergen.render.renderer import Renderer
    plane_scene()
    renderer = Renderer(texture_roots=(corpus,), search_paths=(corpus,), file_mipmaps=not like_for_like)
    results = []
    docs = sorted(glob.glob(os.path.join(corpus, "resources/Materials/TestSuite/stdlib/**/*.mtlx"), recursive=True))
    with tempfile.TemporaryDirectory(prefix="osl-agreement-") as folder:
        for doc in docs:
            if name_filter and name_filter not in doc:
                continue
            osl = {r["element"]: r for r in gen.records(DocumentFile(doc), target="osl", all=True, values="source",
                                                        texture_width=0.0 if like_for_like else None)
                   if "error" not in r}
            for rec in gen.records(DocumentFile(doc), target="glsl", all=True, values="source"):
                theirs = osl.get(rec.get("element"))
                if "error" in rec or theirs is None or theirs["blocks"]["pixel"]["Outputs"][0]["type"] != "color4":
                    continue  # (a closure's output: no value to compare)
                label = f"{os.path.relpath(doc, corpus)}:{rec['element']}"
                try:
                    gl = renderer.render(rec, size=SIZE, mesh="plane", env_method="fis").rgba[::-1]
                    shaded = testshade(theirs["stages"]["pixel"], folder, corpus)
                except Exception as exc:  # a failure to draw or shade is a row of its own
                    results.append((label, float("nan"), float("nan"), 0.0, f"failed: {type(exc).__name__}"))
                    print(f"  {label}: {type(exc).__name__}: {str(exc)[:200]}")
                    continue
                delta = np.abs(shaded - gl)
                relative = (delta / np.maximum(1.0, np.abs(gl))).max(axis=2)
                results.append((label, float(delta.max()), float(relative.max()),
                                float((relative <= TOLERANCE).mean()), cause(rec)))
    return results


def report(results: list[tuple]) -> str:
    """The table of outliers with their causes, the count per cause and the summary figure."""
    agree = [r for r in results if r[2] <= TOLERANCE]
    outliers = sorted((r for r in results if not r[2] <= TOLERANCE), key=lambda r: -np.nan_to_num(r[2], nan=np.inf))
    print("\n| element | max abs difference | max relative | pixels within | cause |\n|---|---:|---:|---:|---|")
    for label, absolute, relative, pixels, why in outliers:
        print(f"| {label} | {absolute:.3g} | {relative:.3g} | {100 * pixels:.1f} % | {why.split(':')[0]} |")
    print("\n| cause | outliers |\n|---|---:|")
    for why, count in collections.Counter(r[4] for r in outliers).most_common():
        print(f"| {why} | {count} |")
    share = 100 * len(agree) / max(len(results), 1)
    print(f"\n{len(agree)} of {len(results)} value elements agree within {TOLERANCE:g} relative ({share:.1f} %)")
    return f"stdlib testshade vs GL within {TOLERANCE:g}: {share:.1f} %"
