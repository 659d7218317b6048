"""Struct members nothing reads, and their stores, leave a stage (the fields pass,
shadergen/code/passes/fields.py), in every target."""
import re

from .conftest import kept_code, material

LOBE = """struct Lobe
{
    float weight;
    vec3 frame;     // only what `tilted` stores reads it
    vec3 tilted;
    vec3 spare;
    bool flag;
};

void fill(out vec3 v)
{
    v = vec3(1.0);
}

vec3 tilt(vec3 v)
{
    return v.zyx;
}

Lobe prepare(float w)
{
    Lobe lobe;
    lobe.weight = w;
    lobe.frame = vec3(w);
    lobe.tilted = tilt(lobe.frame);
    lobe.tilted.z = max(lobe.tilted.z, 0.0);
    lobe.spare = vec3(0.0);
    if (w > 0.5)
        lobe.flag = true;
    return lobe;
}
"""


def test_members_only_stored_go_with_their_stores_and_what_only_they_called():
    code = kept_code(LOBE, "Lobe l = prepare(1.0); float x = l.weight;")
    for gone in ("frame", "tilted", "spare", "tilt("):
        assert gone not in code
    assert "    float weight;" in code and "    lobe.weight = w;" in code
    # a store a brace-less if governs goes too, and the if with it: its condition calls nothing
    assert "flag" not in code and "if (w > 0.5)" not in code


def test_a_member_the_roots_read_stays():
    code = kept_code(LOBE, "Lobe l = prepare(1.0); vec3 t = l.tilted;")
    assert "    vec3 tilted;" in code and "lobe.tilted = tilt(lobe.frame);" in code
    assert "    vec3 frame;" in code and "vec3 tilt(vec3 v)" in code
    assert "spare" not in code


def test_a_store_that_calls_an_out_function_keeps_its_member():
    library = LOBE.replace("    lobe.spare = vec3(0.0);", "    lobe.spare = vec3(0.0);\n    lobe.tilted = fill2(lobe.spare);") \
        + "\nvec3 fill2(inout vec3 v)\n{\n    v = vec3(2.0);\n    return v;\n}\n"
    code = kept_code(library, "Lobe l = prepare(1.0); float x = l.weight;")
    assert "lobe.tilted = fill2(lobe.spare);" in code and "    vec3 spare;" in code


def test_a_struct_built_by_its_constructor_keeps_every_member():
    library = "struct Pair\n{\n    float a;\n    float b;\n};\n"
    code = kept_code(library, "Pair p = Pair(1.0, 2.0); float x = p.a;")
    assert "    float b;" in code


CONDUCTOR = material('<conductor_bsdf name="b" type="BSDF"/>')


def struct_members(source: str, name: str) -> list[str]:
    """The members of struct `name` as GLSL (`vec3 N;`) or WGSL (`N: vec3f,`) declares them."""
    body = re.search(r"struct %s\s*\{(.*?)\}" % name, source, re.S).group(1)
    lines = [line.strip() for line in body.split("\n") if line.strip() and not line.strip().startswith("//")]
    return [line.split(":")[0] if ":" in line else line.split()[1].rstrip(";") for line in lines]


def test_a_specular_lobe_lit_by_the_environment_alone_loses_its_light_loop_members_in_every_target(gen):
    """Its tangent frame and Fresnel set-up are for the light loop: a shader without lights only
    stores them. WGSL, printed from the same IR, gets every member GLSL loses."""
    records = {t: gen.prepare(CONDUCTOR, interface="specialized", lights=False, environment="fis", target=t).emit()
               for t in ("glsl", "essl", "wgsl")}
    members = {t: struct_members(r["stages"]["pixel"], "SpecularLobe") for t, r in records.items()}
    assert "frame" not in members["glsl"] and "fd" not in members["glsl"] and "weight" in members["glsl"]
    assert members["essl"] == members["glsl"] == members["wgsl"]
    lit = struct_members(gen.prepare(CONDUCTOR, interface="specialized", environment="fis").emit()["stages"]["pixel"],
                         "SpecularLobe")
    assert "frame" in lit and "fd" in lit  # read by the light loop
    assert records["glsl"]["passes"]["fields"] == records["wgsl"]["passes"]["fields"] > 0
    assert "lobe.frame =" not in records["wgsl"]["stages"]["pixel"]


def test_a_function_only_a_dead_members_store_called_leaves_the_record(gen):
    """The prefiltered environment never reads the lobe's tangent frame: its store goes, and with
    it the call of mx_tangent_frame, its only one in the stage."""
    record = gen.prepare(CONDUCTOR, interface="specialized", lights=False, environment="prefilter").emit()
    pixel = record["stages"]["pixel"]
    assert "lobe.frame" not in pixel
    assert "mx_tangent_frame" not in pixel and "mx_frame_from_normal" not in pixel
