"""Issue 8, faults 1 and 5: a generator child killed while idle is replaced, the next request
is answered, and readiness reports the pool while it is down. One API worker, so that every
request meets the pool whose child was killed."""
import time

import pytest

from faults_testing import kill, processes, readiness, wait_ready
from service_testing import Server, document, wait_until

GEN = "service.workers.gen_worker"


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("genfaults"), workers=1, render_workers=1)
    yield srv
    srv.close()


def uncached(value: float) -> str:
    return document("ramp.mtlx").replace("0.5", repr(value))  # a graph no other request generated


def test_healthz_answers_head_like_get(server):
    get, head = server.client.get("/healthz"), server.client.head("/healthz")
    assert head.status_code == get.status_code == 200
    assert head.content == b"" and head.headers["content-type"] == get.headers["content-type"]


def test_ready_when_everything_runs(server):
    body = wait_ready(server.client)
    assert body["status"] == "ready"
    assert body["generator"]["detail"].startswith("1/1 generator processes")
    assert body["render"]["ready"] and body["cache"]["ready"]


def test_idle_generator_child_killed_is_replaced_and_the_request_answered(server):
    client = server.client
    wait_ready(client)
    for attempt in range(3):  # three times: the replacement is supervised like the first child
        children = processes(server, GEN)
        kill(children)
        # seen as soon as the death is noticed, while the replacement still loads its libraries
        body = wait_until(lambda: (r := readiness(client))[0] == 503 and r[1], 5, "readiness 503", pause_s=0.01)
        assert body["status"] == "not_ready" and not body["generator"]["ready"], body
        assert body["generator"]["detail"].startswith("0/1 generator processes")
        assert body["render"]["ready"] and body["cache"]["ready"]
        started = time.monotonic()
        r = client.post("/v1/generate", json={"document": uncached(0.101 + attempt)}, timeout=60)
        assert r.status_code == 200, r.text
        assert r.json()["cached"] is False and time.monotonic() - started < 45
        fresh = wait_until(lambda: processes(server, GEN), 30, "a new generator child")
        assert not set(fresh) & set(children)
        wait_ready(client)
    assert "Traceback" not in server.log_text()


def test_many_requests_after_a_kill_are_all_answered(server):
    """Today's failure mode was 64 requests hanging, then 503 queue_full: here none hangs."""
    from concurrent.futures import ThreadPoolExecutor

    import httpx

    kill(processes(server, GEN))

    def post(i):
        with httpx.Client(base_url=server.url, timeout=60) as c:
            return c.post("/v1/generate", json={"document": uncached(0.2 + i / 1000)}).status_code

    with ThreadPoolExecutor(8) as pool:
        statuses = list(pool.map(post, range(16)))
    assert statuses == [200] * 16
