"""POST /v1/thumbnails/batch on the real server (issue 23): many documents as one job, progress
while it runs, one result per document (PNG or error record), any API worker answering a poll; a
batch over the configured limit is 413 naming it."""
import time

import pytest

from service_testing import Server, assert_error

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
LIMIT = 6


def material(prefix: str, color: str) -> str:
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <multiply name="{prefix}_tint" type="color3">
    <input name="in1" type="color3" value="{color}" /><input name="in2" type="float" value="0.8" />
  </multiply>
  <surface_unlit name="{prefix}_shader" type="surfaceshader">
    <input name="emission_color" type="color3" nodename="{prefix}_tint" />
  </surface_unlit>
  <surfacematerial name="{prefix}_material" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="{prefix}_shader" />
  </surfacematerial>
</materialx>"""


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("batches"), env={"SHADERGEN_MAX_BATCH_DOCUMENTS": str(LIMIT)})
    yield srv
    srv.close()


def finished(client, status_url: str, timeout_s: float = 300) -> dict:
    deadline = time.monotonic() + timeout_s
    seen = []
    while time.monotonic() < deadline:
        status = client.get(status_url).json()
        seen.append(status["done"])
        if status["state"] == "done":
            assert seen == sorted(seen)  # progress only grows
            return status
        time.sleep(0.2)
    raise TimeoutError(f"{status_url} not done within {timeout_s} s")


def test_a_batch_gives_one_result_per_document_with_broken_ones_beside_the_good(server):
    documents = [{"document": material("red", "0.9, 0.1, 0.1"), "name": "red"},
                 {"document": "<materialx version='1.39'><multiply", "name": "not xml"},
                 {"document": material("green", "0.1, 0.9, 0.1"), "name": "green"},
                 {"document": material("blue", "0.1, 0.1, 0.9"), "name": "unknown element", "element": "nowhere"},
                 {"document": material("other_blue", "0.1, 0.1, 0.9"), "name": "blue"}]
    r = server.client.post("/v1/thumbnails/batch", json={"documents": documents, "size": 32})
    assert r.status_code == 202, r.text
    status = finished(server.client, r.json()["status_url"])
    assert (status["total"], status["done"], status["failed"]) == (5, 5, 2)
    results = status["results"]
    assert [x["name"] for x in results] == [d["name"] for d in documents]
    assert [x["state"] for x in results] == ["done", "failed", "done", "failed", "done"]
    assert results[1]["error"]["code"] == "invalid_document"
    assert results[3]["error"]["code"] == "unknown_element"
    assert [results[i]["element"] for i in (0, 2, 4)] == ["red_material", "green_material", "other_blue_material"]
    pngs = [server.client.get(results[i]["thumbnail_url"]) for i in (0, 2, 4)]
    assert all(p.status_code == 200 and p.content[:8] == PNG_MAGIC for p in pngs)
    assert len({p.content for p in pngs}) == 3  # each drawn with its own values
    failed = server.client.get(f"/v1/thumbnails/batch/{status['id']}/1")
    assert_error(failed, 400, "invalid_document")  # a failed document's PNG is its error
    assert_error(server.client.get(f"/v1/thumbnails/batch/{status['id']}/5"), 404, "not_found")
    metrics = server.client.get("/metrics").text
    assert 'shadergen_programs_total{result="reused"}' in metrics  # three materials, one topology


def test_a_batch_over_the_limit_is_413_naming_it(server):
    documents = [{"document": material(f"m{i}", "0.5, 0.5, 0.5")} for i in range(LIMIT + 1)]
    error = assert_error(server.client.post("/v1/thumbnails/batch", json={"documents": documents}), 413, "too_large")
    assert f"limit of {LIMIT}" in error["message"] and error["where"] == "documents"
    assert_error(server.client.post("/v1/thumbnails/batch", json={"documents": []}), 422, "invalid_request")


def test_an_unknown_batch_is_404(server):
    assert_error(server.client.get("/v1/thumbnails/batch/" + "0" * 32), 404, "not_found")
    assert_error(server.client.get("/v1/thumbnails/batch/not-an-id"), 422, "invalid_request")
