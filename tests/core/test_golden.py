"""Golden shaders (tests/golden/): generated code is reviewed as code. A failure here after an
intended change: regenerate with `python -m tests.golden.cases` and review the diff."""
import difflib

import pytest

from tests.golden.cases import DOCUMENTS, VARIANTS, generate, golden_path

from .conftest import glslang, needs_glslang

CASES = [(name, variant) for name in DOCUMENTS for variant in VARIANTS]


@pytest.mark.parametrize("name,variant", CASES)
def test_generated_source_equals_the_golden_file(gen, name, variant):
    expected = golden_path(name, variant).read_text()
    actual = generate(gen, name, variant)
    diff = "".join(difflib.unified_diff(expected.splitlines(True), actual.splitlines(True), "golden", "generated", n=1))
    assert actual == expected, "regenerate with `python -m tests.golden.cases` if intended:\n" + diff[:4000]


@needs_glslang
@pytest.mark.parametrize("name,variant", CASES)
def test_golden_source_compiles(name, variant):
    ok, log = glslang(golden_path(name, variant).read_text(), "pixel")
    assert ok, log


def test_specialized_golden_is_smaller_than_complete():
    for name in DOCUMENTS:
        complete, specialized, thumbnail = (len(golden_path(name, v).read_text().splitlines()) for v in VARIANTS)
        assert thumbnail <= specialized <= complete, name
