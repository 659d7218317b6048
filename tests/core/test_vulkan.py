"""The Vulkan target: GLSL 4.50 for Vulkan with each stage's SPIR-V in the record
(targets/vulkan/), checked by glslangValidator -V and spirv-val (targets/vulkan/check.py); its
std140 layout is the one glslang itself computes; a missing compiler is an error record."""
import base64
import os
import re
import subprocess

import pytest

from name_cases import ShaderChecker
from shadergen.targets import checker_for
from shadergen.targets.closures import LIGHT_DATA_MEMBERS
from shadergen.targets.wgsl.layout import struct_members
from tests.golden.cases import DOCUMENTS

from .conftest import doc

SPIRV_MAGIC = 0x07230203
LIGHT_DATA, LIGHT_DATA_SIZE = struct_members(LIGHT_DATA_MEMBERS)


@pytest.fixture(scope="module")
def glslang():
    from required_tools import tool_path
    tool_path("spirv-val")
    return tool_path("glslangValidator")


def test_a_record_carries_each_stages_spirv_and_spirv_val_accepts_it(gen, glslang, tmp_path):
    record = gen.prepare(DOCUMENTS["standard_surface_coated"], target="vulkan").emit()
    assert set(record["spirv"]) == {"vertex", "pixel"}
    for stage, text in record["spirv"].items():
        module = base64.b64decode(text)
        assert int.from_bytes(module[:4], "little") == SPIRV_MAGIC
        path = tmp_path / f"{stage}.spv"
        path.write_bytes(module)
        run = subprocess.run(["spirv-val", "--target-env", "vulkan1.0", str(path)], capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
    again = gen.prepare(DOCUMENTS["standard_surface_coated"], target="vulkan").emit()
    assert again["spirv"] == record["spirv"] and again["stages"] == record["stages"]  # deterministic


def test_every_variable_is_bound_explicitly(gen, glslang):
    record = gen.prepare(DOCUMENTS["standard_surface_coated"], target="vulkan").emit()
    for stage, source in record["stages"].items():
        assert source.startswith("#version 450\n")
        for line in source.splitlines():
            if re.match(r"(uniform|in|out) ", line):  # every global with a storage qualifier has a layout
                pytest.fail(f"{stage}: no layout: {line}")
    assert "layout(std140, set = 1, binding = 0) uniform PixelUniforms" in record["stages"]["pixel"]
    assert "layout(set = 1, binding = 1) uniform texture2D u_envRadiance;" in record["stages"]["pixel"]


def test_the_layout_offsets_are_glslangs_std140_offsets(gen, glslang, tmp_path):
    """glslang's reflection (-q) of the module against the record's layout, member by member (the
    members the code reads: glslang reflects only those), the light rig's array of structs too."""
    record = gen.prepare(DOCUMENTS["standard_surface_coated"], target="vulkan", interface="complete").emit()
    compared = 0
    for stage, suffix in (("vertex", "vert"), ("pixel", "frag")):
        path = tmp_path / f"s.{suffix}"
        path.write_text(record["stages"][stage])
        run = subprocess.run([glslang, "-V", "-q", str(path), "-o", os.devnull], capture_output=True, text=True)
        assert run.returncode == 0, run.stdout
        reflected = {m.group(1): int(m.group(2)) for m in re.finditer(r"^(\S+): offset (-?\d+),", run.stdout, re.M)}
        for member in record["layout"][stage]["members"]:
            if member["type"] == "LightData":  # glslang reflects the array's first element, and its stride
                for light in LIGHT_DATA:
                    assert reflected[f"u_lightData.{light['name']}"] == member["offset"] + light["offset"], light
                    compared += 1
                stride = re.search(r"^u_lightData\.type: .*topLevelArrayStride (\d+)", run.stdout, re.M)
                assert int(stride.group(1)) == LIGHT_DATA_SIZE
            elif member["name"] in reflected:
                assert reflected[member["name"]] == member["offset"], member
                compared += 1
    assert compared > 30


def test_the_checker_refuses_bad_source_with_the_line():
    errors = checker_for("vulkan").errors({
        "good": ("pixel", "#version 450\nlayout(location = 0) out vec4 o;\nvoid main()\n{\n    o = vec4(1.0);\n}\n"),
        "bad": ("pixel", "#version 450\nlayout(location = 0) out vec4 o;\nvoid main()\n{\n    o = undefined;\n}\n"),
        "loose": ("pixel", "#version 450\nuniform float u;\nlayout(location = 0) out vec4 o;\n"
                           "void main()\n{\n    o = vec4(u);\n}\n")})
    assert set(errors) == {"bad", "loose"}
    assert "undefined" in errors["bad"] and "5" in errors["bad"]
    assert "uniform" in errors["loose"]  # Vulkan has no loose uniforms


def test_a_pair_compiled_in_one_run_names_the_stage_glslang_refused(glslang):
    """Both stages go to one glslang run (spirv.py): its error names the refused stage and line,
    and the checker flags that stage only."""
    from shadergen.errors import ShaderGenError
    from shadergen.targets.vulkan.spirv import compile_stages

    vertex = "#version 450\nvoid main()\n{\n    gl_Position = vec4(0.0);\n}\n"
    pixel = "#version 450\nlayout(location = 0) out vec4 o;\nvoid main()\n{\n    o = undefined;\n}\n"
    with pytest.raises(ShaderGenError) as refused:
        compile_stages({"vertex": vertex, "pixel": pixel})
    assert refused.value.where == "pixel:5" and "undefined" in refused.value.message
    errors = checker_for("vulkan").errors({"a vertex": ("vertex", vertex), "a pixel": ("pixel", pixel)})
    assert set(errors) == {"a pixel"}


def test_generated_shaders_of_every_interface_pass_the_checker(gen, glslang):
    from required_tools import missing
    text = doc('<image name="i" type="color3"><input name="file" type="filename" value="a.png"/></image>'
               '<standard_surface name="s" type="surfaceshader"><input name="base_color" type="color3" nodename="i"/>'
               '</standard_surface><surfacematerial name="m" type="material">'
               '<input name="surfaceshader" type="surfaceshader" nodename="s"/></surfacematerial>')
    records = [("image", r) for i in ("complete", "reduced", "specialized")
               for r in gen.records(text, target="vulkan", interface=i)]
    assert all("spirv" in r for _, r in records)
    assert not ShaderChecker(on_missing=missing).problems(records)


def test_without_glslang_a_vulkan_record_is_an_error_record(gen, glslang, monkeypatch):
    monkeypatch.setenv("PATH", "/nonexistent")
    [record] = gen.records(DOCUMENTS["marble_checker"].read_text(), target="vulkan")
    assert record["error"]["code"] == "missing_tool"
    assert "glslangValidator" in record["error"]["message"] and record["error"]["where"] == "vulkan"


def test_constant_tables_are_indexed_in_place_not_copied_at_each_index(gen, glslang, tmp_path):
    """glslang copies a `const` array into a function-local variable at every run-time index (SPIR-V
    cannot index a value): 12 copies of the albedo tables, and lavapipe took over 14 minutes to build
    the lit standard_surface's pipeline. Printed as module-scope variables, they are Private
    variables indexed in place (targets/vulkan/printer.py)."""
    from required_tools import tool_path
    record = gen.prepare(DOCUMENTS["standard_surface_coated"], target="vulkan", interface="specialized").emit()
    path = tmp_path / "pixel.spv"
    path.write_bytes(base64.b64decode(record["spirv"]["pixel"]))
    text = subprocess.run([tool_path("spirv-dis"), str(path)], capture_output=True, text=True, check=True).stdout
    assert "OpVariable %_ptr_Private__arr_float_uint_1024 Private" in text  # the largest table
    assert re.findall(r"OpVariable %_ptr_Function__arr_float_uint_\d+ Function", text) == []
