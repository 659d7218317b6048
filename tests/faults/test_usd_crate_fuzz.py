"""Issue 21, item 4 (USD): every failure path of a USD upload is a 4xx with a code, on the real
service. 1,000 corrupted crate files (truncations and byte flips of real .usdc files, seed 21,
tests/fuzz_testing.py) each sent as a usdz: no 5xx, every refusal the error object, every case
answered within the client's time-out, and no generator child's peak resident memory past its
limit (with what the watchdog may overshoot by between two reads). Then the two 500s the issue
found: a connection to a prim that does not exist, and a crate token that is not UTF-8."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

from pathlib import Path

import pytest
from pxr import Sdf

from fuzz_testing import USDZ, ChildPeakMemory, corrupted_crates, crate_cases, judge, usdz
from service_testing import Server, assert_error

CASES, SEED = 1000, 21
MEMORY_LIMIT_MIB = 768
# RSS is read every 0.05 s: an allocation as fast as a corrupt crate's (about 600 MB/s) passes the
# limit by a few tens of MiB before its child is killed, more when the machine is loaded and the
# watchdog reads late: 512 leaves room for that, and a child without a limit reaches 7 GB
OVERSHOOT_MIB = 512
ANSWER_TIMEOUT_S = 120


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("cratefuzz"), workers=2, render_workers=1,
                 env={"SHADERGEN_GENERATE_MEMORY_MIB": str(MEMORY_LIMIT_MIB)})
    yield srv
    srv.close()


def test_corrupted_crates_are_refused_with_a_code(server):
    broken, statuses = [], {}
    with ChildPeakMemory(server.proc.pid) as memory:
        for label, body in crate_cases(CASES, SEED):
            r = server.client.post("/v1/generate", content=body, headers=USDZ, timeout=ANSWER_TIMEOUT_S)
            statuses[r.status_code] = statuses.get(r.status_code, 0) + 1
            why = judge(r)
            if why:
                broken.append(f"{label}: {why}")
    assert not broken, broken[:10]
    assert sum(statuses.values()) == CASES and 400 in statuses, statuses  # the cases do reach the parser
    assert memory.peak_mib < MEMORY_LIMIT_MIB + OVERSHOOT_MIB, (memory.peak_mib, statuses)
    assert "Traceback" not in server.log_text()


# Cases of longer runs (bench/fuzz.py --seed 7) whose crate names a child it holds no spec for
# (one an empty path): usd-core's ModifyAssetPaths aborted the generator child on them (SIGABRT, 500
# worker_crashed). They are these cases while usd-core writes the test scenes' crates as 0.26 does.
ABORTING_CASES = ((7, 964), (7, 2014))


@pytest.mark.parametrize("seed, index", ABORTING_CASES)
def test_crate_naming_a_child_without_a_spec(server, tmp_path, seed, index):
    *_, (label, data) = corrupted_crates(index + 1, seed)
    r = server.client.post("/v1/generate", content=usdz(data, tmp_path), headers=USDZ, timeout=ANSWER_TIMEOUT_S)
    assert r.status_code < 500 and judge(r) is None, (label, r.text)
    assert "SIGABRT" not in server.log_text()


def layer(text: str) -> Sdf.Layer:
    result = Sdf.Layer.CreateAnonymous(".usda")
    result.ImportFromString(text)
    return result


SHADER = """#usda 1.0
def Material "M"
{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "%s"
        token outputs:surface
        %s
    }
}
"""


def test_connection_to_a_prim_that_does_not_exist(server):
    text = SHADER % ("UsdPreviewSurface", "color3f inputs:diffuseColor.connect = </Nowhere/Texture.outputs:rgb>")
    r = server.client.post("/v1/generate", content=text, headers={"content-type": "model/vnd.usda"})
    error = assert_error(r, 422, "dangling_connection")
    assert error["where"] == "/M/S.inputs:diffuseColor" and "/Nowhere/Texture.outputs:rgb" in error["message"]


def test_crate_token_that_is_not_utf8(server, tmp_path):
    """A token (the shader's info:id) whose bytes in the crate are not UTF-8: the crate keeps token
    text as LZ4 literals, so the token's bytes are found in the file and one is replaced."""
    marker = "Qz7kLp2Xw9"
    assert layer(SHADER % (marker, "float inputs:roughness = 0.5")).Export(str(tmp_path / "token.usdc"))
    data = (tmp_path / "token.usdc").read_bytes()
    at = data.index(marker.encode())
    body = usdz(data[:at + 3] + b"\xff" + data[at + 4:], tmp_path)
    r = server.client.post("/v1/generate", content=body, headers=USDZ)
    assert "not UTF-8" in assert_error(r, 400, "invalid_document")["message"]
    assert "Traceback" not in server.log_text()
