"""Struct members nothing reads, and their stores, leave a stage (targets/deadfields.py)."""
from .conftest import kept_code

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
    # a store that a brace-less if governs stays, and so does its member
    assert "    bool flag;" in code and "        lobe.flag = true;" in code


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


def test_wgsl_structs_on_one_line_lose_their_dead_members():
    library = ("struct Lobe { weight: f32, frame: mat3x3f, taps: array<f32, 3> }\n\n"
               "fn prepare(w: f32) -> Lobe {\n    var lobe: Lobe;\n    lobe.weight = w;\n"
               "    lobe.frame = mat3x3f();\n    return lobe;\n}\n")
    code = kept_code(library, "var l: Lobe = prepare(1.0); let x = l.weight + l.taps[0];")
    assert "struct Lobe { weight: f32, taps: array<f32, 3> }" in code
    assert "frame" not in code
