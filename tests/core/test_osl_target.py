"""The OSL target: its shaders compile with oslc (scripts/osl.sh builds it), and the listing is
what oslinfo reads from the compiled shader (names, types, defaults, ui metadata)."""
import pytest

from shadergen.api import default_generator
from shadergen.errors import ShaderGenError
from shadergen.targets.osl import check
from shadergen.targets.osl.target import PARAMETER_TYPES
from tests.documents import image_document
from tests.required_tools import missing

DOCUMENT = """<?xml version="1.0"?>
<materialx version="1.39">
  <nodegraph name="g">
    <texcoord name="uv" type="vector2"/>
    <separate2 name="sep" type="multioutput"><input name="in" type="vector2" nodename="uv"/></separate2>
    <constant name="tint" type="color3"><input name="value" type="color3" value="0.8, 0.4, 0.2"/></constant>
    <multiply name="scaled" type="color3">
      <input name="in1" type="color3" nodename="tint"/>
      <input name="in2" type="float" nodename="sep" output="outx"/>
    </multiply>
    <mix name="mixed" type="vector4">
      <input name="fg" type="vector4" value="1, 0, 0, 1"/>
      <input name="bg" type="vector4" value="0, 0, 1, 1"/>
      <input name="mix" type="vector4" value="0.5, 0.5, 0.5, 0.5"/>
    </mix>
    <fract name="fractional" type="vector2"><input name="in" type="vector2" nodename="uv"/></fract>
    <output name="color_out" type="color3" nodename="scaled"/>
    <output name="mixed_out" type="vector4" nodename="mixed"/>
    <output name="fract_out" type="vector2" nodename="fractional"/>
  </nodegraph>
</materialx>
"""


@pytest.fixture(scope="module")
def oslc():
    if check.tool("oslc") is None or check.tool("oslinfo") is None:
        missing("oslc and oslinfo", "scripts/osl.sh builds them")


def records(interface="complete"):
    return list(default_generator().records(DOCUMENT.encode(), target="osl", all=True, interface=interface))


@pytest.mark.parametrize("interface", ["complete", "reduced", "specialized"])
def test_every_output_compiles(oslc, interface):
    shaders = {}
    for rec in records(interface):
        assert "error" not in rec, rec
        assert set(rec["stages"]) == {"pixel"}  # OSL has no vertex stage
        shaders[rec["element"]] = ("pixel", rec["stages"]["pixel"])
    assert len(shaders) == 3
    assert check.errors(shaders) == {}


def test_oslc_rejects_a_broken_shader(oslc):
    failed = check.errors({"broken": ("pixel", "shader s(output float x = 0) { x = nothing; }")})
    assert "nothing" in failed["broken"]


def test_listing_is_what_oslinfo_reads(oslc):
    for rec in records():
        info = check.oslinfo(rec["stages"]["pixel"])
        public = rec["blocks"]["pixel"]["PublicUniforms"]
        assert public
        for v in public:
            osl_type = PARAMETER_TYPES[v["type"]]
            shown = f'"{v["name"]}" "struct {osl_type}"' if osl_type in ("vector2", "vector4") \
                else f'"{v["name"]}" "{osl_type}"'
            assert shown in info, (v, info)
        for name in rec["blocks"]["pixel"]["Outputs"]:
            assert f'"{name["name"]}" "output color"' in info
            assert f'"{name["name"]}_alpha" "output float"' in info


def test_ui_hints_are_osl_metadata(oslc):
    doc = DOCUMENT.replace('<mix name="mixed" type="vector4">', '<mix name="mixed" type="vector4">'
                           '<input name="mix" type="float" value="0.25"/>').replace(
        '<input name="mix" type="vector4" value="0.5, 0.5, 0.5, 0.5"/>', "").encode()
    rec = next(r for r in default_generator().records(doc, target="osl", all=True) if r["element"] == "g/mixed_out")
    info = check.oslinfo(rec["stages"]["pixel"])
    weight = next(v for v in rec["blocks"]["pixel"]["PublicUniforms"] if v["path"].endswith("mixed/mix"))
    assert weight["value"] == 0.25 and weight["ui"] == {"softmin": 0.0, "softmax": 1.0}
    assert f'"{weight["name"]}" "float"' in info
    assert "metadata: float slidermin = 0" in info and "metadata: float slidermax = 1" in info


def test_a_bad_parameter_value_is_an_error_record():
    doc = DOCUMENT.replace('<input name="value" type="color3" value="0.8, 0.4, 0.2"/>',
                           '<input name="value" type="color3" value="0.8, red, 0.2"/>').encode()
    rec = next(r for r in default_generator().records(doc, target="osl", all=True) if r["element"] == "g/color_out")
    assert rec["error"]["code"] == "invalid_value" and rec["error"]["where"] == "g/tint/value"


def test_a_file_name_is_the_string_it_was(oslc):
    """Backslashes, quotes and control characters in a file name stay in OSL's string literal as
    they were (a Windows path's `\\t` is no tab)."""
    doc = b"""<?xml version="1.0"?>
<materialx version="1.39">
  <image name="img" type="color3"><input name="file" type="filename" value="C:\\tex\\&quot;a&#9;b.png"/></image>
  <output name="out" type="color3" nodename="img"/>
</materialx>"""
    [rec] = default_generator().records(doc, target="osl", all=True, values="source")
    [file] = [v for v in rec["blocks"]["pixel"]["PublicUniforms"] if v["type"] == "filename"]
    assert file["value"] == 'C:\\tex\\"a\tb.png'
    info = check.oslinfo(rec["stages"]["pixel"])
    assert 'Default value: "C:\\\\tex\\\\\\"a\\tb.png"' in info, info


def test_a_component_of_a_swizzle_is_the_component_of_its_vector():
    """OSL indexes no constructor: `vec4(c.xyz, 1.0)` takes c's own components (oslc rejected
    `vector(c.x, c.y, c.z)[0]` in OCIO's matrix code)."""
    from shadergen.code import ir
    from shadergen.targets.osl.printer import OslPrinter
    c = ir.Name("c", "local", type="vec4")
    rgb = ir.Field(c, "xyz", type="vec3", swizzle=True)
    e = ir.Construct("vec4", [rgb, ir.Literal(1.0, "1.0", type="float")])
    assert OslPrinter().render(e, None, 0) == "vector4(c.x, c.y, c.z, 1.0)"
    assert OslPrinter().render(ir.Field(rgb, "zx", type="vec2", swizzle=True), None, 0) == "vector2(c.z, c.x)"


def shade_image(tmp_path, pixels, filtertype: str, res: tuple[int, int]) -> list[list[str]]:
    """testshade's printed values (out1, then out1_alpha, per pixel) of our OSL of a color4 <image>
    with `filtertype` reading `pixels` ((h, w, 3), top row first, no alpha) at `res` pixels."""
    import subprocess

    oiio = pytest.importorskip("OpenImageIO")
    if check.tool("testshade") is None:
        missing("testshade", "scripts/osl.sh builds it")
    image = str(tmp_path / "image.exr")
    assert oiio.ImageBuf(pixels).write(image)
    doc = image_document(image, filtertype, "color4").encode()
    [rec] = default_generator().records(doc, target="osl", all=True, values="source")
    failed = check.compile_shaders({"shader": ("pixel", rec["stages"]["pixel"])}, str(tmp_path))
    assert not failed, failed
    done = subprocess.run([check.tool("testshade"), "--res", *map(str, res), "--center", "--print", "-o", "out1",
                           "null", "-o", "out1_alpha", "null", str(tmp_path / "shader0")],
                          capture_output=True, text=True, timeout=120, check=True)
    return [line.split(":")[1].split() for line in done.stdout.splitlines() if line.strip().startswith("out1")]


def test_an_image_reads_as_gl_reads_it(oslc, tmp_path):
    """testshade shading our OSL of an <image> of a file with a red top row and a blue bottom row,
    and no alpha: texture coordinate v = 0.25 reads the bottom row, v = 0.75 the top (MaterialX's v
    runs up the image), alpha is 1 as GL samples it (the helpers once flipped t twice and read
    alpha 0)."""
    import numpy as np
    pixels = np.array([[[1, 0, 0], [1, 0, 0]], [[0, 0, 1], [0, 0, 1]]], "f4")  # rows top first
    values = shade_image(tmp_path, pixels, "closest", (1, 2))
    # testshade's row y shades v = (y + 0.5) / 2: pixel (0, 0) is v = 0.25, pixel (0, 1) v = 0.75
    assert values == [["0", "0", "1"], ["1"], ["1", "0", "0"], ["1"]]


@pytest.mark.parametrize("interface", ["complete", "reduced"])
def test_an_image_read_is_osls_alone(oslc, interface):
    """OSL writes mx_image_fetch itself (texture()), so what only the library's body of it calls is
    not in the shader: the cubic filter's texel reads (textureSize, texelFetch: OSL has neither)
    failed the shader, the edge folding was dead code in it."""
    doc = image_document("grid.png", "cubic").encode()
    [rec] = default_generator().records(doc, target="osl", all=True, interface=interface)
    assert "error" not in rec, rec
    text = rec["stages"]["pixel"]
    assert "mx_image_fetch(" in text and "mx_image_cubic" not in text and "mx_address" not in text
    assert check.errors({"img": ("pixel", text)}) == {}


def test_texture_width_is_an_option_of_the_osl_target(oslc):
    """texture_width=0 writes a zero filter width into every texture() call (one lookup of the base
    level: bench/osl_agreement.py's like-for-like reads), keys the record apart, and compiles; the
    default writes none; any other target, or a width that is no finite number >= 0, is an error."""
    doc = image_document("grid.png").encode()
    generator = default_generator()
    [plain] = generator.records(doc, target="osl")
    [base] = generator.records(doc, target="osl", texture_width=0.0)
    assert "float width = filtertype == 0 ? 0.0 : 1.0;" in plain["stages"]["pixel"]
    assert "float width = filtertype == 0 ? 0.0 : 0.0;" in base["stages"]["pixel"]
    assert base["hash"] != plain["hash"]
    assert check.errors({"base": ("pixel", base["stages"]["pixel"])}) == {}
    for target, width in (("glsl", 0.0), ("osl", -1.0), ("osl", float("inf")), ("osl", "0")):
        with pytest.raises(ShaderGenError) as caught:
            generator.prepare(doc, target=target, texture_width=width)
        assert caught.value.code == "unsupported_texture_width"


def test_a_closest_read_on_a_texel_edge_takes_the_texel_after_it(oslc, tmp_path):
    """u = 0.25 and 0.75 lie exactly on texel edges of a 4-texel row: GL's floor(u * 4) reads
    texels 1 and 3, and so does our OSL (OIIO's "closest" read texels 0 and 2, the ones before)."""
    import numpy as np
    pixels = np.array([[[0, 0, 0], [1, 1, 1], [2, 2, 2], [3, 3, 3]]], "f4")
    assert [v[0] for v in shade_image(tmp_path, pixels, "closest", (2, 1))[::2]] == ["1", "3"]


def test_a_linear_image_read_is_bilinear(oslc, tmp_path):
    """testshade shading a linear <image> at its texel centres reads each texel as it is: OSL's
    interp is "linear" (it was "bilinear", not an OSL name, so OIIO's default smartcubic spread
    the black column into its neighbours)."""
    import numpy as np
    pixels = np.ones((1, 16, 3), "f4")
    pixels[0, 10] = 0.0
    reds = [float(v[0]) for v in shade_image(tmp_path, pixels, "linear", (16, 1))[::2]]
    assert reds == pytest.approx([0.0 if x == 10 else 1.0 for x in range(16)], abs=1e-6)


def test_a_matrix_product_is_swapped_once():
    """OSL holds the transpose of GLSL's matrix: GLSL's `B * A` is OSL's `A * B`, also where the
    GLSL printer renders the product again to see whether it fits its line (it was swapped back)."""
    from shadergen.code import ir
    from shadergen.targets.osl.printer import OslPrinter
    a, b = (ir.Name(n, "local", type="mat3") for n in "ab")
    product = ir.Binary("*", b, ir.Call("inverse", [a], type="mat3", builtin=True), type="mat3")
    assert OslPrinter().render(product, None, 0) == "1.0 / a * b"
    assert OslPrinter().render(product, 20, 4) == "1.0 / a * b"


def test_matrix_arithmetic_and_round_evaluate_as_in_glsl(oslc, tmp_path):
    """testshade evaluates multiply and divide of matrices as MaterialX orders them (a row vector
    times in1 then in2; MaterialX's values are rows), and round takes a tie to the even integer,
    as the GLSL library does."""
    import subprocess
    if check.tool("testshade") is None:
        missing("testshade", "scripts/osl.sh builds it")
    doc = b"""<?xml version="1.0"?>
<materialx version="1.39">
  <multiply name="m" type="matrix33">
    <input name="in1" type="matrix33" value="0, 1.5, 0,  0.5, 0, 0,  0, 0, 1"/>
    <input name="in2" type="matrix33" value="0, 1, 0,  1, 0, 0,  0, 0, 1"/>
  </multiply>
  <divide name="d" type="matrix44">
    <input name="in1" type="matrix44" value="1.5, 1.5, 0, 0,  0, 1.5, 1.5, 0,  0, 0, 1.5, 1.5,  0, 0, 0, 1"/>
    <input name="in2" type="matrix44" value="1, 1, 0, 0,  0, 1, 1, 0,  0, 0, 1, 1,  0, 0, 0, 1"/>
  </divide>
  <transformmatrix name="tm" type="vector3">
    <input name="in" type="vector3" value="0.5, 0.5, 0.5"/><input name="mat" type="matrix33" nodename="m"/>
  </transformmatrix>
  <transformmatrix name="td" type="vector4">
    <input name="in" type="vector4" value="0.5, 0.25, 0.5, 1"/><input name="mat" type="matrix44" nodename="d"/>
  </transformmatrix>
  <round name="r" type="vector3"><input name="in" type="vector3" value="-0.5, 2.5, 1.5"/></round>
  <output name="mout" type="vector3" nodename="tm"/>
  <output name="dout" type="vector4" nodename="td"/>
  <output name="rout" type="vector3" nodename="r"/>
</materialx>"""
    printed = {}
    for rec in default_generator().records(doc, target="osl", all=True, values="source"):
        failed = check.compile_shaders({"shader": ("pixel", rec["stages"]["pixel"])}, str(tmp_path))
        assert not failed, failed
        done = subprocess.run([check.tool("testshade"), "--res", "1", "1", "--print", "-o", "out1", "null",
                               "-o", "out1_alpha", "null", str(tmp_path / "shader0")],
                              capture_output=True, text=True, timeout=120, check=True)
        lines = [line for line in done.stdout.splitlines() if line.strip().startswith("out1")]
        printed[rec["element"]] = [float(x) for line in lines for x in line.split(":")[1].split()]
    # (0.5, 0.5, 0.5) in1 in2 (in2 in1: 0.25, 0.75, 0.5); (0.5, 0.25, 0.5, 1) in1 inverse(in2)
    # (inverse(in2) in1: alpha 1.375)
    assert printed == {"mout": [0.75, 0.25, 0.5, 1.0], "dout": [0.75, 0.375, 0.75, 1.0], "rout": [0.0, 2.0, 2.0, 1.0]}
