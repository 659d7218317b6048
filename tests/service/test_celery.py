"""The multi-machine configuration on one machine: the cache and the job queue on a real
redis-server (started by the tests, on 127.0.0.1), render workers from `shadergen worker`."""
import subprocess
import sys

import pytest
import redis

from service_testing import (ROOT, Server, descendants, document, is_png, kill_while_running,
                             stop, wait_for_job, wait_until)

needs_renderer = pytest.mark.usefixtures("renderer_required")


@pytest.fixture(scope="module")
def stack(redis_server, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("celery")
    env = {"SHADERGEN_BROKER": redis_server.url, "SHADERGEN_CACHE": redis_server.url,
           "SHADERGEN_RENDER_QUEUE_SIZE": "2"}
    srv = Server(tmp, workers=2, env=env)
    yield srv
    srv.close()


@pytest.fixture(scope="module")
def worker(stack, tmp_path_factory):
    log = tmp_path_factory.mktemp("worker") / "worker.log"
    with open(log, "wb") as out:
        proc = subprocess.Popen([sys.executable, "-m", "shadergen.cli", "worker", "--concurrency", "1"],
                                cwd=ROOT, env=stack.env, stdout=out, stderr=subprocess.STDOUT)
    try:
        wait_until(lambda: proc.poll() is not None or b" ready." in log.read_bytes(), 60, "shadergen worker")
        assert proc.poll() is None, log.read_text()
        yield proc
    finally:
        stop(proc)


def test_health_names_the_back_ends(stack):
    body = stack.client.get("/healthz").json()
    assert body["cache"] == "RedisStore" and body["jobs"] == "celery"


def test_records_are_cached_in_redis(stack, redis_server):
    client = stack.client
    text = document("ramp.mtlx").replace("0.5", "0.625")
    first = client.post("/v1/generate", json={"document": text}).json()
    second = client.post("/v1/generate", json={"document": text}).json()
    assert first["cached"] is False and second["cached"] is True
    assert redis.Redis.from_url(redis_server.url).exists(f"shadergen:cache:rec:{first['hash']}")
    same = client.post("/v1/generate", json={"document": document("ramp_equivalent.mtlx").replace("0.5", "0.625")})
    assert same.json()["cached"] is True and same.json()["hash"] == first["hash"]
    assert client.get(f"/v1/shaders/{first['hash']}").status_code == 200


def test_worker_command_needs_a_broker():
    env = {k: v for k, v in __import__("os").environ.items() if k != "SHADERGEN_BROKER"}
    done = subprocess.run([sys.executable, "-m", "shadergen.cli", "worker"], cwd=ROOT, env=env,
                          capture_output=True, timeout=60)
    assert done.returncode == 2 and b"SHADERGEN_BROKER" in done.stderr


def test_full_queue_answers_503(stack):
    # no worker consumes yet (the worker fixture is not started before this test): the queue only grows
    client = stack.client
    answers = [client.post("/v1/thumbnails?async=true", json={"document": document("ramp.mtlx"), "size": 32})
               for _ in range(4)]
    assert [a.status_code for a in answers] == [202, 202, 503, 503]
    assert answers[2].headers["retry-after"].isdigit() and answers[2].json()["error"]["code"] == "queue_full"


@needs_renderer
def test_thumbnails_through_celery(stack, worker):
    client = stack.client
    r = client.post("/v1/thumbnails", json={"document": document("textured.mtlx"), "size": 64})
    assert r.status_code == 200, r.text
    assert is_png(r.content, 64)
    job = client.post("/v1/thumbnails?async=true", json={"document": document("ramp.mtlx"), "size": 48}).json()
    status = wait_for_job(client, job["id"])
    assert status["state"] == "done", status
    assert is_png(client.get(status["thumbnail_url"]).content, 48)


def celery_children(worker) -> list[int]:
    return descendants(worker.pid)


@needs_renderer
def test_worker_process_that_dies_twice_fails_the_job(stack, worker):
    client = stack.client
    job = client.post("/v1/thumbnails?async=true", json={"document": document("textured.mtlx"), "size": 1024})
    job_id = job.json()["id"]
    killed = kill_while_running(client, job_id, lambda: celery_children(worker), kills=2)
    status = wait_for_job(client, job_id)
    assert len(killed) == 2 and status["state"] == "failed", status
    assert status["error"]["code"] == "worker_crashed" and "twice" in status["error"]["message"]


@needs_renderer
def test_worker_process_that_dies_once_is_retried(stack, worker):
    client = stack.client
    job = client.post("/v1/thumbnails?async=true", json={"document": document("textured.mtlx"), "size": 1024})
    job_id = job.json()["id"]
    killed = kill_while_running(client, job_id, lambda: celery_children(worker), kills=1)
    status = wait_for_job(client, job_id)
    assert len(killed) == 1 and status["state"] == "done", status
