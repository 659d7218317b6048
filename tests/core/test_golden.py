"""Golden shaders (tests/golden/): generated code is reviewed as code. A failure here after an
intended change: regenerate with `python -m tests.golden.cases` and review the diff. Every golden
shader compiles with its target's own checker (targets/<name>/check.py: glslangValidator for GLSL
and ESSL, wgpu's naga for WGSL, glslangValidator -V and spirv-val for Vulkan, the Slang compiler of
slangpy for HLSL and Slang; MSL, which nothing here compiles, is cross-checked against naga's MSL of
the WGSL golden of the same case: tests/core/test_cfamily_targets.py)."""
import difflib

import pytest

from name_cases import ShaderChecker
from tests.golden.cases import CASES, DOCUMENTS, TARGETS, VARIANTS, generate, golden_path


@pytest.fixture(scope="module")
def checker():
    from required_tools import missing
    return ShaderChecker(on_missing=missing)


@pytest.mark.parametrize("name,variant,target,stage", CASES)
def test_generated_source_equals_the_golden_file(gen, name, variant, target, stage):
    expected = golden_path(name, variant, target, stage).read_text()
    actual = generate(gen, name, variant, target, stage)
    diff = "".join(difflib.unified_diff(expected.splitlines(True), actual.splitlines(True), "golden", "generated", n=1))
    assert actual == expected, "regenerate with `python -m tests.golden.cases` if intended:\n" + diff[:4000]


def test_every_golden_source_compiles_with_its_checker(checker):
    records = [(f"{name}.{variant}", {"target": target, "interface": variant, "element": name,
                                     "stages": {stage: golden_path(name, variant, target, stage).read_text()}})
               for name, variant, target, stage in CASES]
    assert not checker.problems(records)


@pytest.mark.parametrize("target", TARGETS)
def test_specialized_golden_is_smaller_than_complete(target):
    for name in DOCUMENTS:
        complete, specialized, thumbnail = (len(golden_path(name, v, target).read_text().splitlines()) for v in VARIANTS)
        assert thumbnail <= specialized <= complete, name
