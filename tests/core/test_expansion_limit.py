"""Nodegraph expansion is bounded: a document whose definitions nest uses of each other expands
exponentially, and is refused (too_large, naming the use and the counts) before any copy is
made, by the library and by the real command line; real and large legitimate graphs generate."""
import json
import subprocess
import sys

import pytest

from hostile_graphs import layered_material, nested_definitions, nested_nodegraphs, wide_definition
from shadergen.errors import ShaderGenError
from shadergen.passes.expand import CAPPED_COUNT, MAX_EXPANDED_NODES, MAX_NESTING


def cli(tmp_path, text: str, *args: str) -> tuple[int, list[dict]]:
    path = tmp_path / "d.mtlx"
    path.write_text(text)
    p = subprocess.run([sys.executable, "-m", "shadergen.cli", "generate", str(path), *args],
                       capture_output=True, text=True, timeout=300)
    assert "Traceback" not in p.stderr, p.stderr
    return p.returncode, [json.loads(line) for line in p.stdout.splitlines()]


def expanded_nodes(depth: int, fanout: int = 2) -> int:
    """Nodes of nested_definitions: the leaf body is one node, each level adds `fanout - 1` adds."""
    size = 1
    for _ in range(depth):
        size = fanout * size + fanout - 1
    return size


@pytest.mark.parametrize("depth, fanout, count", [
    (16, 2, "131,071"),
    (30, 2, "2,147,483,647"),  # counted, never built
    (8, 100, f"at least {CAPPED_COUNT:,}"),  # 100**8 leaves: the count stops at the cap
])
def test_nested_definitions_are_refused_by_the_cli_naming_the_counts(tmp_path, depth, fanout, count):
    code, records = cli(tmp_path, nested_definitions(depth, fanout), "--element", "result")
    error = records[0]["error"]
    assert code == 1 and error["code"] == "too_large" and error["where"] == "top"
    assert f"graph {count} nodes" in error["message"]
    assert f"limit of {MAX_EXPANDED_NODES:,}" in error["message"] and f"NG_level{depth}" in error["message"]


def test_every_element_of_a_hostile_document_is_answered(tmp_path):
    """--all generates each definition's graph too: up to the limit records, over it errors."""
    depth = 16
    code, records = cli(tmp_path, nested_definitions(depth), "--all")
    assert code == 1 and len(records) == depth + 2  # NG_level0..16/out, then the document's output
    under = [level for level in range(depth + 1) if expanded_nodes(level) <= MAX_EXPANDED_NODES]
    assert expanded_nodes(under[-1]) > MAX_EXPANDED_NODES / 2  # the largest generated is near the limit
    for level, record in enumerate(records[:-1]):
        assert record["element"] == f"NG_level{level}/out"
        if level in under:
            assert "stages" in record, record
        else:
            assert record["error"]["code"] == "too_large" and record["error"]["where"].startswith(f"NG_level{level}/")
    assert records[-1]["error"]["code"] == "too_large"


def test_nesting_deeper_than_the_limit_is_refused(gen):
    """One use per level: small, but each level deeper costs function sharing a pass over the rest.
    nested_definitions(d) nests d + 1 definitions (NG_level<d> down to NG_level0)."""
    with pytest.raises(ShaderGenError) as exc:
        gen.prepare(nested_definitions(MAX_NESTING, fanout=1), element="result")
    assert exc.value.code == "too_large" and exc.value.where == "top"
    assert f"more than {MAX_NESTING} deep: NG_level{MAX_NESTING} -> " in exc.value.message
    prepared = gen.prepare(nested_definitions(MAX_NESTING - 1, fanout=1), element="result")
    assert prepared.graph.expanded_size == 1 and prepared.graph.passes["expand"] == MAX_NESTING


def test_document_nodegraphs_read_twice_are_not_copied(gen):
    """A connection to a document nodegraph's output reads one node, however many nodes read it."""
    prepared = gen.prepare(nested_nodegraphs(40), element="result")
    assert prepared.graph.expanded_size == 3 * 40 + 1  # two sines and an add per level, one multiply


def test_a_definition_used_ten_thousand_times_generates(tmp_path):
    """Function sharing used to scan the whole graph per use (ten minutes for this document)."""
    code, records = cli(tmp_path, wide_definition(10_000), "--element", "result", "--names", "document")
    assert code == 0 and records[0]["passes"]["functions"] == 10_000
    assert records[0]["stages"]["pixel"].count("NG_w(") == 10_001  # the function and a call per use


def test_a_large_legitimate_material_generates(tmp_path, gen):
    text = layered_material(32)
    assert gen.prepare(text).graph.expanded_size < MAX_EXPANDED_NODES / 10
    code, records = cli(tmp_path, text)
    assert code == 0 and records[0]["element"] == "Layered"
    public = {v["path"] for v in records[0]["blocks"]["pixel"]["PublicUniforms"]}
    assert {f"s{i}/base_color" for i in range(32)} <= public
