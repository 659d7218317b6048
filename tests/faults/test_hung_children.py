"""Issue 21, item 5: readiness from answers. A child stopped with SIGSTOP keeps its pipes open and
looks alive; only its heartbeats stop. Readiness must go 503 within the deadline, requests must
be refused at once (503 with Retry-After) rather than queued behind it, a job it held ends at its
time limit as 504, and the pool recovers: on SIGCONT, or by replacing a child silent as long as a
job's time limit."""
import os
import signal
from contextlib import contextmanager

import pytest

from faults_testing import processes, readiness, wait_ready
from hostile_packages import LAYER, png, textured_layer, usdz
from service_testing import Server, assert_error, document, is_png, wait_until

GEN, RENDER = "service.workers.gen_worker", "service.workers.render_worker"
DEADLINE_S, GENERATE_TIMEOUT_S, RENDER_TIMEOUT_S = 2, 6, 8
pytestmark = pytest.mark.usefixtures("renderer_required")


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("hung"), workers=1, render_workers=1, env={
        "SHADERGEN_READY_DEADLINE_S": str(DEADLINE_S), "SHADERGEN_HEARTBEAT_S": "0.25",
        "SHADERGEN_GENERATE_TIMEOUT_S": str(GENERATE_TIMEOUT_S), "SHADERGEN_RENDER_TIMEOUT_S": str(RENDER_TIMEOUT_S)})
    yield srv
    srv.close()


def one(server, module: str) -> int:
    pids = wait_until(lambda: processes(server, module), 60, module)
    assert len(pids) == 1, pids
    return pids[0]


@contextmanager
def stopped(pid: int):
    os.kill(pid, signal.SIGSTOP)
    try:
        yield
    finally:
        try:
            os.kill(pid, signal.SIGCONT)
        except ProcessLookupError:
            pass  # replaced meanwhile


def not_ready(client, component: str) -> dict:
    """Readiness 503 with `component` not ready; the wait is bounded by a few deadlines."""
    body = wait_until(lambda: (r := readiness(client))[0] == 503 and not r[1][component]["ready"] and r[1],
                      5 * DEADLINE_S, f"{component} not ready", pause_s=0.05)
    assert "0 answering" in body[component]["detail"], body
    return body


def assert_refused_now(response) -> None:
    assert_error(response, 503, "unavailable")
    assert int(response.headers["Retry-After"]) > 0
    assert "answered within" in response.json()["error"]["message"]


def generate(client, value: float):
    return client.post("/v1/generate", json={"document": document("ramp.mtlx").replace("0.5", repr(value))})


def test_stopped_generator_fails_fast_and_recovers_on_sigcont_or_replacement(server):
    client = server.client
    wait_ready(client)
    child = one(server, GEN)
    with stopped(child):
        body = not_ready(client, "generator")
        assert body["render"]["ready"] and body["cache"]["ready"], body
        assert_refused_now(generate(client, 0.211))
        assert_refused_now(client.get("/v1/nodedefs"))  # asked of a generator once, on first use
    wait_ready(client)  # SIGCONT: heard from again
    assert one(server, GEN) == child
    assert generate(client, 0.212).status_code == 200
    with stopped(child):
        not_ready(client, "generator")
        # silent as long as a job's time limit: killed and replaced
        wait_until(lambda: child not in processes(server, GEN), DEADLINE_S + GENERATE_TIMEOUT_S + 30, "replacement")
    wait_ready(client)
    assert one(server, GEN) != child
    assert generate(client, 0.213).status_code == 200


def thumbnail(client, value: float, size: int = 32, **params):
    """A thumbnail of a material no other request drew."""
    return client.post("/v1/thumbnails", params=params,
                       json={"document": document("ramp.mtlx").replace("0.5", repr(value)), "size": size})


def test_stopped_render_worker_fails_fast_its_job_times_out_504_and_it_is_replaced(server):
    client = server.client
    wait_ready(client)
    worker = one(server, RENDER)
    with stopped(worker):
        not_ready(client, "render")
        assert_refused_now(thumbnail(client, 0.311))
    wait_ready(client)
    assert one(server, RENDER) == worker
    r = thumbnail(client, 0.312)
    assert r.status_code == 200 and is_png(r.content, 32), r.text
    # stopped in the middle of a job (the first of its topology: compiled, then drawn at 1024 px,
    # seconds of work): the job ends at its time limit, a server-side 504
    accepted = client.post("/v1/thumbnails", params={"async": "true"},
                           json={"document": document("marble.mtlx"), "size": 1024})
    assert accepted.status_code == 202, accepted.text
    job = accepted.json()["id"]
    wait_until(lambda: client.get(f"/v1/jobs/{job}").json()["state"] == "running", 60, "running", pause_s=0.01)
    with stopped(worker):
        not_ready(client, "render")
        status = wait_until(lambda: (s := client.get(f"/v1/jobs/{job}").json())["state"] == "failed" and s,
                            RENDER_TIMEOUT_S + 30, "the job's time limit")
    assert status["error"]["code"] == "timeout", status
    r = client.get(f"/v1/jobs/{job}/thumbnail")
    assert_error(r, 504, "timeout")
    assert int(r.headers["Retry-After"]) > 0
    wait_ready(client)
    assert one(server, RENDER) != worker
    r = thumbnail(client, 0.314)
    assert r.status_code == 200 and is_png(r.content, 32), r.text


def test_stopped_render_pool_server_fails_fast_and_recovers_on_sigcont(server):
    """The render pool server itself stopped: its socket still accepts, so only the heartbeats it
    sends while a render is waited for tell the API worker that nobody is there. A thumbnail is
    answered 503 once the pool has been silent past the readiness deadline, long before the
    job's own wait (three render time limits) would end."""
    client = server.client
    wait_ready(client)
    pool = one(server, "service.jobs.pool_server")
    accepted = thumbnail(client, 0.317, **{"async": "true"})
    assert accepted.status_code == 202, accepted.text
    job = accepted.json()["id"]
    wait_until(lambda: client.get(f"/v1/jobs/{job}").json()["state"] == "done", 60, "the job done")
    with stopped(pool):
        r = client.get(f"/v1/jobs/{job}")  # a question the pool answers at once, or not at all
        assert_error(r, 503, "unavailable")
        assert int(r.headers["Retry-After"]) > 0
        body = wait_until(lambda: (r := readiness(client))[0] == 503 and not r[1]["render"]["ready"] and r[1],
                          5 * DEADLINE_S, "render not ready", pause_s=0.05)
        assert "has not answered for" in body["render"]["detail"], body
        r = thumbnail(client, 0.316)
        assert_error(r, 503, "unavailable")
        assert int(r.headers["Retry-After"]) > 0
        assert "has not answered for" in r.json()["error"]["message"], r.text
    wait_ready(client)
    assert one(server, "service.jobs.pool_server") == pool
    r = thumbnail(client, 0.315)
    assert r.status_code == 200 and is_png(r.content, 32), r.text


def test_a_package_larger_than_the_socket_buffer_is_refused_by_a_stopped_pool_too(server):
    """A usdz thumbnail carries its package to the pool (1.9 MB here): more than the socket holds,
    so writing it waits on a stopped pool that reads nothing, before any heartbeat could be missed.
    That wait is bounded by the same silence."""
    client = server.client
    wait_ready(client)
    package = usdz([(LAYER, textured_layer("textures/t.png").encode()), ("textures/t.png", png(8, 8, (9, 9, 9))),
                    ("padding.bin", bytes(1900 << 10))])
    pool = one(server, "service.jobs.pool_server")
    with stopped(pool):
        r = client.post("/v1/thumbnails", params={"size": 32}, content=package,
                        headers={"content-type": "model/vnd.usdz+zip"}, timeout=60)
        assert_error(r, 503, "unavailable")
        assert int(r.headers["Retry-After"]) > 0
    wait_ready(client)
    r = client.post("/v1/thumbnails", params={"size": 32}, content=package,
                    headers={"content-type": "model/vnd.usdz+zip"})
    assert r.status_code == 200 and is_png(r.content, 32), r.text


def test_a_generator_stopped_before_it_reads_a_large_upload_is_killed_at_the_time_limit(server):
    """Stopped at once, before readiness can tell: the 1.9 MB package is more than the pipe holds,
    and the job's time limit, which began only once it was written, never began; the slot waited
    for the pool's whole wait and the stopped child was never replaced."""
    client = server.client
    wait_ready(client)
    package = usdz([(LAYER, textured_layer("textures/t.png").encode()), ("textures/t.png", png(8, 8, (7, 7, 7))),
                    ("padding.bin", bytes(1900 << 10))])
    child = one(server, GEN)
    with stopped(child):
        r = client.post("/v1/generate", content=package, headers={"content-type": "model/vnd.usdz+zip"}, timeout=90)
        assert_error(r, 504, "timeout")
        assert int(r.headers["Retry-After"]) > 0
    wait_ready(client)
    assert one(server, GEN) != child
    r = client.post("/v1/generate", content=package, headers={"content-type": "model/vnd.usdz+zip"})
    assert r.status_code == 200, r.text
