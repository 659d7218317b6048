"""Colour management by OpenColorIO (shadergen/cms/ocio.py) with the real opencolorio package:
names resolve through the config, unknown spaces are error records, OCIO's code compiles in every
target, LUTs draw on GL, folded values are OCIO's CPU processor's, and the built-in system's
records are what they were."""
import json
import subprocess
import sys

import numpy as np
import pytest

from .conftest import doc
from required_tools import missing, require_module, require_renderer, require_wgpu
from shadergen.targets import TARGETS

OCIO = require_module("PyOpenColorIO", "pip install -e '.[ocio]'")

CG = "ocio://cg-config-v2.1.0_aces-v1.3_ocio-v2.3"
STUDIO = "ocio://studio-config-v2.1.0_aces-v1.3_ocio-v2.3"


def constants(spaces: list[str], working: str = "ACEScg") -> str:
    """A document adding one constant per colour space, each value given in its space."""
    body, total = [], None
    for k, space in enumerate(spaces):
        body.append(f'<constant name="c{k}" type="color3"><input name="value" type="color3" value="0.25, 0.5, 0.75" '
                    f'colorspace="{space}" /></constant>')
        if total is not None:
            body.append(f'<add name="a{k}" type="color3"><input name="in1" type="color3" nodename="{total}" />'
                        f'<input name="in2" type="color3" nodename="c{k}" /></add>')
            total = f"a{k}"
        else:
            total = f"c{k}"
    body.append(f'<output name="out" type="color3" nodename="{total}" />')
    return doc("<nodegraph name=\"g\">" + "".join(body) + "</nodegraph>", colorspace=working)


def record(gen, text: str, **kw) -> dict:
    return next(iter(gen.records(text, cms="ocio", ocio_config=kw.pop("ocio_config", CG), **kw)))


def test_names_resolve_through_aliases_and_roles(gen):
    # MaterialX's names are aliases of the CG config's spaces; scene_linear is a role (ACEScg)
    rec = record(gen, constants(["srgb_texture", "lin_rec709", "scene_linear"], working="acescg"))
    assert "error" not in rec, rec
    functions = [v for v in rec["stages"]["pixel"].splitlines() if v.startswith("vec4 cm_")]
    assert len(functions) == 2, functions  # scene_linear is the working space itself: no transform
    assert rec["warnings"] == []


def test_unknown_space_is_an_error_record_naming_space_element_and_config(gen):
    rec = record(gen, constants(["Utility - Made Up"]))
    assert rec["error"]["code"] == "unknown_colorspace"
    message = rec["error"]["message"]
    assert "Utility - Made Up" in message and CG in message
    assert rec["error"]["where"] == "g/c0/value"
    working = record(gen, constants(["srgb_texture"], working="no_such_working_space"))
    assert working["error"]["code"] == "unknown_colorspace" and "no_such_working_space" in working["error"]["message"]


def test_builtin_system_leaves_records_as_they_were(gen):
    text = constants(["srgb_texture", "g22_rec709"], working="lin_rec709")
    default = next(iter(gen.records(text)))
    builtin = next(iter(gen.records(text, cms="builtin")))
    assert builtin == default | {"timings_ms": builtin["timings_ms"]}
    assert "luts" not in builtin
    # the built-in system's unknown pair is still a warning and the value as is
    lenient = next(iter(gen.records(constants(["ACEScct"], working="lin_rec709"))))
    assert "error" not in lenient and any("no genglsl transform" in w for w in lenient["warnings"])


def test_system_and_config_are_in_the_cache_key(gen):
    text = constants(["srgb_texture"], working="lin_rec709")
    hashes = {next(iter(gen.records(text, **kw)))["hash"] for kw in (
        {}, {"cms": "ocio", "ocio_config": CG}, {"cms": "ocio", "ocio_config": STUDIO})}
    assert len(hashes) == 3


def test_bad_options_are_error_records(gen):
    text = constants(["srgb_texture"])
    assert next(iter(gen.records(text, cms="lcms")))["error"]["code"] == "unsupported_cms"
    bad = next(iter(gen.records(text, cms="ocio", ocio_config="/no/such/config.ocio")))
    assert bad["error"]["code"] == "invalid_ocio_config"


@pytest.mark.parametrize("config", [CG, STUDIO])
def test_every_space_of_the_aces_configs_compiles_in_every_target(gen, config):
    """One shader per target holding the transform of every scene colour space of the config
    to ACEScg, compiled by each target's real checker."""
    from name_cases import ShaderChecker

    cfg = OCIO.Config.CreateFromFile(config)
    spaces = [cs.getName() for cs in cfg.getColorSpaces(OCIO.SEARCH_REFERENCE_SPACE_SCENE, OCIO.COLORSPACE_ALL)
              if not cs.isData()]
    # (OSL: OCIO's LUT functions read their texture as a global, and an OSL function sees no
    # shader parameter)
    records = [(config, record(gen, constants(spaces), ocio_config=config, target=t)) for t in TARGETS if t != "osl"]
    assert all("error" not in r for _, r in records), [r.get("error") for _, r in records]
    functions = [line for line in records[0][1]["stages"]["pixel"].splitlines() if line.startswith("vec4 cm_")]
    assert len(functions) == len(spaces) - 1  # all but ACEScg itself
    assert not ShaderChecker(on_missing=missing).problems(records)


def test_osl_refuses_a_lut_transform_by_name_and_takes_an_analytic_one(gen):
    lut = record(gen, constants(["ACEScc"]), target="osl")
    assert lut["error"]["code"] == "unsupported_colorspace" and "ACEScc" in lut["error"]["message"]
    analytic = record(gen, constants(["ACEScct"]), target="osl")
    assert "error" not in analytic and "cm_" in analytic["stages"]["pixel"]
    from name_cases import ShaderChecker
    assert not ShaderChecker(on_missing=missing).problems([(CG, analytic)])  # oslc compiles it


def test_lut_transform_drawn_by_webgpu_equals_ocio_cpu_processor():
    """The same LUT transform in our WGSL (OCIO's GLSL through the IR), drawn by wgpu."""
    require_wgpu()
    from shadergen.cms.check import RampCheck

    error, scaled, has_luts = RampCheck(CG, "ACEScg", size=32, target="wgsl").error("ACEScc")
    assert has_luts and error <= 2e-3, error


def test_lut_transform_is_a_private_texture_with_its_texels(gen):
    rec = record(gen, constants(["ACEScc"]))
    samplers = [v["name"] for v in rec["blocks"]["pixel"]["PrivateUniforms"] if v["type"] == "filename"]
    assert samplers and set(samplers) == set(rec["luts"])
    lut = rec["luts"][samplers[0]]
    assert lut["format"] == "float32" and lut["channels"] == 1
    from shadergen.render.textures import lut_image
    assert lut_image(lut).shape == (lut["height"], lut["width"], 1)


def test_specialized_folds_through_the_cpu_processor(gen):
    text = constants(["sRGB - Texture"])
    prepared = gen.prepare(text, interface="specialized", cms="ocio", ocio_config=CG)
    out = next(iter(prepared.graph.outputs.values()))
    assert out.node.category == "constant"
    cpu = OCIO.Config.CreateFromFile(CG).getProcessor("sRGB - Texture", "ACEScg").getDefaultCPUProcessor()
    want = cpu.applyRGB([0.25, 0.5, 0.75])
    assert np.allclose(out.node.inputs["value"].value, want, rtol=0, atol=1e-6)


@pytest.fixture(scope="module")
def ramp():
    require_renderer()
    from shadergen.cms.check import RampCheck
    return RampCheck(CG, "ACEScg", size=48)


@pytest.mark.parametrize("space,tolerance", [("sRGB - Texture", 1e-4), ("ACEScc", 2e-3)])
def test_gl_draw_equals_ocio_cpu_processor(ramp, space, tolerance):
    """The ramp of test colours drawn through our shader against OCIO's CPU processor; ACEScc
    is the CG config's LUT transform."""
    error, scaled, has_luts = ramp.error(space)
    assert has_luts == (space == "ACEScc")
    assert error <= tolerance, error


def test_aces_round_trip(ramp):
    """ACEScg -> sRGB - Texture by our shader (a document whose working space is sRGB - Texture),
    then back to ACEScg by OCIO's CPU processor: the colours drawn as they were."""
    from shadergen.cms.check import RampCheck

    encoded = RampCheck(CG, "sRGB - Texture", colours=ramp.colours, size=ramp.size)
    drawn = encoded.draw("ACEScg")[0]
    covered = encoded.source[..., 3] > 0.5
    back = np.ascontiguousarray(drawn[covered][:, :3], "f4")
    OCIO.Config.CreateFromFile(CG).getProcessor("sRGB - Texture", "ACEScg").getDefaultCPUProcessor().applyRGB(back)
    assert np.abs(back - encoded.source[covered][:, :3]).max() <= 1e-4


def test_cli_generate_takes_the_options(tmp_path):
    path = tmp_path / "doc.mtlx"
    path.write_text(constants(["Utility - Made Up"]))
    out = subprocess.run([sys.executable, "-m", "shadergen.cli", "generate", "--cms", "ocio", "--ocio-config", CG,
                          str(path)], capture_output=True, text=True, timeout=120)
    assert out.returncode == 1 and json.loads(out.stdout)["error"]["code"] == "unknown_colorspace"


def test_render_keeps_linear_working_values_and_shows_the_display(tmp_path):
    """`render --cms ocio`: the .npy holds the working-space (ACEScg) values, the PNG the config's
    default display and view of them."""
    require_renderer()
    from shadergen.render.imageio import read_image

    path = tmp_path / "doc.mtlx"
    path.write_text(constants(["sRGB - Texture"]))
    npy, png = tmp_path / "out.npy", tmp_path / "out.png"
    out = subprocess.run([sys.executable, "-m", "shadergen.cli", "render", str(path), "--mesh", "plane", "--size", "32",
                          "--cms", "ocio", "--ocio-config", CG, "--npy", str(npy), "-o", str(png)],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    rgba = np.load(npy)
    centre = rgba[16, 16]
    cfg = OCIO.Config.CreateFromFile(CG)
    linear = np.array([[0.25, 0.5, 0.75]], "f4")
    cfg.getProcessor("sRGB - Texture", "ACEScg").getDefaultCPUProcessor().applyRGB(linear)
    assert centre[3] == 1.0 and np.abs(centre[:3] - linear[0]).max() <= 1e-4
    display = cfg.getDefaultDisplay()
    shown = linear.copy()
    cfg.getProcessor(OCIO.DisplayViewTransform(src="ACEScg", display=display, view=cfg.getDefaultView(display))) \
        .getDefaultCPUProcessor().applyRGB(shown)
    pixel = read_image(str(png))[16, 16, :3]
    assert np.abs(pixel - np.clip(shown[0], 0, 1)).max() <= 1.5 / 255.0


def test_render_view_is_chosen_and_an_unknown_one_refused(tmp_path):
    """`render --view`: the PNG through that view of the default display; a view the config lacks
    is an `unknown_view` error listing its views, before anything is drawn."""
    require_renderer()
    from shadergen.render.imageio import read_image

    path = tmp_path / "doc.mtlx"
    path.write_text(constants(["sRGB - Texture"]))
    png = tmp_path / "out.png"
    base = [sys.executable, "-m", "shadergen.cli", "render", str(path), "--mesh", "plane", "--size", "32",
            "--cms", "ocio", "--ocio-config", CG, "-o", str(png), "--json"]
    out = subprocess.run(base + ["--view", "Un-tone-mapped"], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    cfg = OCIO.Config.CreateFromFile(CG)
    shown = np.array([[0.25, 0.5, 0.75]], "f4")
    cfg.getProcessor("sRGB - Texture", "ACEScg").getDefaultCPUProcessor().applyRGB(shown)
    cfg.getProcessor(OCIO.DisplayViewTransform(src="ACEScg", display=cfg.getDefaultDisplay(), view="Un-tone-mapped")) \
        .getDefaultCPUProcessor().applyRGB(shown)
    assert np.abs(read_image(str(png))[16, 16, :3] - np.clip(shown[0], 0, 1)).max() <= 1.5 / 255.0
    bad = subprocess.run(base + ["--view", "Filmic"], capture_output=True, text=True, timeout=300)
    error = json.loads(bad.stdout)["error"]
    assert bad.returncode != 0 and error["code"] == "unknown_view" and "Un-tone-mapped" in error["message"]


def test_no_space_of_the_builtin_configs_needs_a_3d_lut_and_a_config_that_does_is_refused(gen, tmp_path):
    """OCIO's GPU shaders of every colour space of the built-in configs (to ACEScg) and of their
    displays' views use 1D LUTs at most, which we draw; a studio's own config whose space reads a
    3D LUT (.cube) is an `unsupported_colorspace` record naming it, not a wrong colour."""
    for name in (CG, STUDIO):
        cfg = OCIO.Config.CreateFromFile(name)
        processors = [cfg.getProcessor(cs, "ACEScg") for cs in cfg.getColorSpaceNames()]
        processors += [cfg.getProcessor(OCIO.DisplayViewTransform(src="ACEScg", display=d, view=v))
                       for d in cfg.getDisplays() for v in cfg.getViews(d)]
        for processor in processors:
            desc = OCIO.GpuShaderDesc.CreateShaderDesc(language=OCIO.GPU_LANGUAGE_GLSL_4_0)
            processor.getDefaultGPUProcessor().extractGpuShaderInfo(desc)
            assert not list(desc.get3DTextures()), name
    cube = tmp_path / "look.cube"
    cube.write_text("LUT_3D_SIZE 2\n" + "".join(f"{b} {g} {r}\n".replace("1", "0.9") for r in (0, 1) for g in (0, 1)
                                                   for b in (0, 1)))
    studio = OCIO.Config.CreateRaw()
    studio.setSearchPath(str(tmp_path))
    studio.addColorSpace(OCIO.ColorSpace(name="lin"))
    graded = OCIO.ColorSpace(name="graded")
    graded.setTransform(OCIO.FileTransform(src="look.cube", interpolation=OCIO.INTERP_LINEAR),
                        OCIO.COLORSPACE_DIR_TO_REFERENCE)
    studio.addColorSpace(graded)
    studio.setRole("scene_linear", "lin")
    config = tmp_path / "studio.ocio"
    config.write_text(studio.serialize())
    rec = record(gen, constants(["graded"], working="lin"), ocio_config=str(config))
    assert rec["error"]["code"] == "unsupported_colorspace" and "graded" in rec["error"]["message"], rec


def test_the_record_names_its_working_space_and_is_keyed_by_it(gen):
    """Values with no colour space of their own make the same graph in any working space: the
    records still differ, each naming its space, since a viewer shows each from its own (a service
    once answered the second document with the first's record and thumbnail)."""
    plain = constants(["scene_linear"]).replace(' colorspace="scene_linear"', "")
    acescg = record(gen, plain, interface="specialized")
    rec709 = record(gen, plain.replace('colorspace="ACEScg"', 'colorspace="Linear Rec.709 (sRGB)"'),
                    interface="specialized")
    assert acescg["working_colorspace"] == "ACEScg" and rec709["working_colorspace"] == "Linear Rec.709 (sRGB)"
    assert acescg["stages"] == rec709["stages"] and acescg["hash"] != rec709["hash"]
    assert "working_colorspace" not in next(iter(gen.records(plain)))  # the built-in system's records as they were


def test_render_batch_draws_through_the_display_and_view(tmp_path):
    """`render --batch --cms ocio`: each PNG is its record's working space through the view, as
    a single render's; an unknown view stops the batch before it draws."""
    require_renderer()
    from shadergen.render.imageio import read_image

    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "doc.mtlx").write_text(constants(["sRGB - Texture"]))
    base = [sys.executable, "-m", "shadergen.cli", "render", "--batch", str(tmp_path / "docs"), "-o",
            str(tmp_path / "out"), "--mesh", "plane", "--size", "32", "--cms", "ocio", "--ocio-config", CG]
    out = subprocess.run(base + ["--view", "Un-tone-mapped"], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    result = json.loads((tmp_path / "out" / "results.jsonl").read_text().splitlines()[0])
    cfg = OCIO.Config.CreateFromFile(CG)
    shown = np.array([[0.25, 0.5, 0.75]], "f4")
    cfg.getProcessor("sRGB - Texture", "ACEScg").getDefaultCPUProcessor().applyRGB(shown)
    cfg.getProcessor(OCIO.DisplayViewTransform(src="ACEScg", display=cfg.getDefaultDisplay(), view="Un-tone-mapped")) \
        .getDefaultCPUProcessor().applyRGB(shown)
    assert np.abs(read_image(result["png"])[16, 16, :3] - np.clip(shown[0], 0, 1)).max() <= 1.5 / 255.0
    bad = subprocess.run(base + ["--view", "Filmic", "--json"], capture_output=True, text=True, timeout=300)
    assert bad.returncode != 0 and json.loads(bad.stdout.splitlines()[-1])["error"]["code"] == "unknown_view"
