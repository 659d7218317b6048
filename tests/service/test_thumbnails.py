"""Thumbnails through the live server's local render pool: PNGs, the cache, async jobs, a full
queue, and render workers that die mid-job."""
import time

import pytest

from service_testing import (Server, cmdline, descendants, document, is_png, kill_while_running,
                             wait_for_job)

pytestmark = pytest.mark.usefixtures("renderer_required")


def thumbnail(client, name="textured.mtlx", **params):
    return client.post("/v1/thumbnails", json={"document": document(name), **params})


def test_png_and_the_thumbnail_cache(client):
    first = thumbnail(client, size=96)
    assert first.status_code == 200, first.text
    assert first.headers["content-type"] == "image/png" and is_png(first.content, 96)
    hits = "shadergen_cache_total{kind=\"thumbnail\",result=\"hit\"}"

    def count():
        lines = client.get("/metrics").text.splitlines()
        line = next((line for line in lines if line.startswith(hits)), f"{hits} 0")
        return float(line.split()[-1])

    before = count()
    again = thumbnail(client, size=96)
    assert again.content == first.content and count() == before + 1


def test_env_method_draws_and_caches_apart(client):
    sampled = thumbnail(client, "metal.mtlx", size=64)
    prefiltered = thumbnail(client, "metal.mtlx", size=64, env_method="prefilter")
    assert prefiltered.status_code == 200 and is_png(prefiltered.content, 64)
    assert prefiltered.content != sampled.content
    corrected = thumbnail(client, "metal.mtlx", size=64, env_method="hybrid")
    assert corrected.status_code == 200 and is_png(corrected.content, 64)
    assert corrected.content not in (sampled.content, prefiltered.content)


def test_async_job(client):
    accepted = client.post("/v1/thumbnails?async=true", json={"document": document("ramp.mtlx"), "size": 64})
    assert accepted.status_code == 202, accepted.text
    job = accepted.json()
    assert job["status_url"] == f"/v1/jobs/{job['id']}"
    status = wait_for_job(client, job["id"])
    assert status["state"] == "done" and status["thumbnail_url"]
    png = client.get(status["thumbnail_url"])
    assert png.status_code == 200 and is_png(png.content, 64)


def test_render_parameters_are_validated(client):
    for bad in ({"size": 0}, {"size": 100_000}, {"mesh": "/etc/passwd.obj"}, {"interface": "x"},
                {"env_method": "pathtrace"}):
        r = thumbnail(client, **bad)
        assert r.status_code == 422 and r.json()["error"]["code"] == "invalid_request"


@pytest.fixture(scope="module")
def one_worker(tmp_path_factory):
    """One render process behind a queue of one: easy to fill, easy to find."""
    srv = Server(tmp_path_factory.mktemp("render"), workers=1, render_workers=1,
                 env={"SHADERGEN_RENDER_QUEUE_SIZE": "1"})
    yield srv
    srv.close()


def render_workers(server) -> list[int]:
    return [p for p in descendants(server.proc.pid) if "service.workers.render_worker" in cmdline(p)]


def submit(client, size=1024, name="textured.mtlx") -> str:
    r = client.post("/v1/thumbnails?async=true", json={"document": document(name), "size": size})
    assert r.status_code == 202, r.text
    return r.json()["id"]


def test_worker_that_dies_twice_fails_the_job_clearly(one_worker):
    client = one_worker.client
    job_id = submit(client)
    killed = kill_while_running(client, job_id, lambda: render_workers(one_worker), kills=2)
    status = wait_for_job(client, job_id)
    assert len(killed) == 2, status
    assert status["state"] == "failed" and status["error"]["code"] == "worker_crashed"
    assert "twice" in status["error"]["message"]
    r = client.get(f"/v1/jobs/{job_id}/thumbnail")
    assert r.status_code == 500 and r.json()["error"]["code"] == "worker_crashed"


def test_worker_that_dies_once_is_replaced_and_the_job_retried(one_worker):
    client = one_worker.client
    job_id = submit(client)
    killed = kill_while_running(client, job_id, lambda: render_workers(one_worker), kills=1)
    status = wait_for_job(client, job_id)
    assert len(killed) == 1 and status["state"] == "done", status
    assert render_workers(one_worker) and killed[0] not in render_workers(one_worker)


def test_full_queue_answers_503_with_retry_after(one_worker):
    client = one_worker.client
    answers = [client.post("/v1/thumbnails?async=true",
                           json={"document": document("textured.mtlx"), "size": 1024}) for _ in range(6)]
    refused = [a for a in answers if a.status_code == 503]
    assert refused, [a.status_code for a in answers]
    assert refused[0].headers["retry-after"].isdigit()
    assert refused[0].json()["error"]["code"] == "queue_full"
    for accepted in (a for a in answers if a.status_code == 202):
        assert wait_for_job(client, accepted.json()["id"])["state"] == "done"
    time.sleep(0.1)
    assert client.post("/v1/thumbnails", json={"document": document("ramp.mtlx"), "size": 32}).status_code == 200


def programs(client, result: str) -> float:
    line = next((ln for ln in client.get("/metrics").text.splitlines()
                 if ln.startswith(f'shadergen_programs_total{{result="{result}"}}')), None)
    return float(line.split()[-1]) if line else 0.0


def test_a_value_edit_in_complete_reuses_the_compiled_program(client):
    """Two documents no other test sends, differing in values only: in `complete` they have one source."""
    def post(text):
        return client.post("/v1/thumbnails", json={"document": text, "size": 40, "interface": "complete"})

    first = post(document("ramp.mtlx").replace('value="0.5"', 'value="0.375"'))
    assert first.status_code == 200, first.text
    reused = programs(client, "reused")
    edited = post(document("ramp.mtlx").replace('value="0.5"', 'value="0.875"'))
    assert edited.status_code == 200, edited.text
    assert programs(client, "reused") == reused + 1
    assert edited.content != first.content  # the edited value is bound: a different image
