"""Golden shaders (tests/golden/): generated code is reviewed as code. A failure here after an
intended change: regenerate with `python -m tests.golden.cases` and review the diff."""
import difflib

import pytest

from tests.golden.cases import DOCUMENTS, INTERFACES, generate, golden_path

from .conftest import glslang, needs_glslang

CASES = [(name, interface) for name in DOCUMENTS for interface in INTERFACES]


@pytest.mark.parametrize("name,interface", CASES)
def test_generated_source_equals_the_golden_file(gen, name, interface):
    expected = golden_path(name, interface).read_text()
    actual = generate(gen, name, interface)
    diff = "".join(difflib.unified_diff(expected.splitlines(True), actual.splitlines(True), "golden", "generated", n=1))
    assert actual == expected, "regenerate with `python -m tests.golden.cases` if intended:\n" + diff[:4000]


@needs_glslang
@pytest.mark.parametrize("name,interface", CASES)
def test_golden_source_compiles(name, interface):
    ok, log = glslang(golden_path(name, interface).read_text(), "pixel")
    assert ok, log


def test_specialized_golden_is_smaller_than_complete():
    for name in DOCUMENTS:
        complete, specialized = (len(golden_path(name, i).read_text().splitlines()) for i in INTERFACES)
        assert specialized <= complete, name
