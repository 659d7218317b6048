"""Documents that nodegraph expansion would blow up, sent to the real service: each refused with
413 too_large by the generator before it builds anything (not a 422 timeout after burning the
generator process until its time limit), the same generator process answering the next request;
legitimate large graphs still generate. One API worker, so every request meets the same child."""
import pytest

from faults_testing import processes, wait_ready
from hostile_graphs import layered_material, nested_definitions, wide_definition
from service_testing import Server, assert_error

GEN = "service.workers.gen_worker"
XML = {"content-type": "application/xml"}


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    # a generous time limit: a refusal must come from the bound on expansion, not from the clock
    srv = Server(tmp_path_factory.mktemp("expansion"), workers=1, render_workers=1,
                 env={"SHADERGEN_GENERATE_TIMEOUT_S": "120"})
    yield srv
    srv.close()


def post(server, text: str, **params):
    return server.client.post("/v1/generate", content=text, headers=XML, params=params)


@pytest.mark.parametrize("text, message", [
    (nested_definitions(16), "131,071 nodes"),
    (nested_definitions(30), "2,147,483,647 nodes"),
    (nested_definitions(40, fanout=1), "nested more than"),
])
def test_hostile_documents_are_refused_and_no_generator_is_lost(server, text, message):
    wait_ready(server.client)
    children = processes(server, GEN)
    error = assert_error(post(server, text, element="result"), 413, "too_large")
    assert message in error["message"] and error["where"] == "top"
    assert processes(server, GEN) == children  # the same process, never killed at its time limit
    r = post(server, layered_material(4))
    assert r.status_code == 200, r.text
    assert processes(server, GEN) == children


def test_a_definition_used_ten_thousand_times_generates(server):
    r = post(server, wide_definition(10_000), element="result")
    assert r.status_code == 200, r.text
    assert r.json()["passes"]["functions"] == 10_000


def test_a_large_legitimate_material_generates(server):
    r = post(server, layered_material(32))
    assert r.status_code == 200, r.text
    public = {v["path"] for v in r.json()["blocks"]["pixel"]["PublicUniforms"]}
    assert {f"s{i}/base_color" for i in range(32)} <= public
    assert "Traceback" not in server.log_text()
