"""Issue 8, faults 4 and 5: the render pool server killed (kill -9) is started again by its
supervisor, thumbnails work again, and jobs that were in flight are submitted again and finish.
Readiness reports the render pool while it is away."""
import time

import pytest

from faults_testing import kill, poll_job, processes, readiness, wait_ready
from service_testing import Server, document, is_png, wait_until

POOL = "service.jobs.pool_server"
pytestmark = pytest.mark.usefixtures("renderer_required")


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("renderfaults"), workers=2, render_workers=1)
    yield srv
    srv.close()


def thumbnail_request(value: float, size: int = 48) -> dict:
    return {"document": document("ramp.mtlx").replace("0.5", repr(value)), "size": size}


def test_killed_render_pool_is_restarted_and_reported_meanwhile(server):
    client = server.client
    wait_ready(client)
    for attempt in range(2):  # the restarted pool is supervised like the first one
        pools = processes(server, POOL)
        assert len(pools) == 1
        kill(pools)
        body = wait_until(lambda: (r := readiness(client))[0] == 503 and r[1], 10, "readiness 503", pause_s=0.01)
        assert not body["render"]["ready"] and body["generator"]["ready"] and body["cache"]["ready"]
        r = client.post("/v1/thumbnails", json=thumbnail_request(0.81 + attempt), timeout=120)
        assert r.status_code == 200 and is_png(r.content, 48), r.text
        fresh = processes(server, POOL)
        assert len(fresh) == 1 and fresh != pools
        wait_ready(client)


def test_jobs_in_flight_when_the_pool_dies_are_retried(server):
    client = server.client
    wait_ready(client)
    jobs = []
    for i in range(4):  # one render process: while the first runs, the others wait in the pool's queue
        accepted = client.post("/v1/thumbnails?async=true", json=thumbnail_request(0.9 + i / 100, size=1024))
        assert accepted.status_code == 202, accepted.text
        jobs.append(accepted.json()["id"])
    states = lambda: [client.get(f"/v1/jobs/{j}").json().get("state") for j in jobs]  # noqa: E731
    in_flight = wait_until(lambda: "running" in (s := states()) and s, 60, "a running job", pause_s=0.01)
    kill(processes(server, POOL))
    assert in_flight.count("done") < len(jobs) - 1, in_flight
    started = time.monotonic()
    for job_id in jobs:
        status = poll_job(client, job_id)
        assert status["state"] == "done", status
        png = client.get(status["thumbnail_url"])
        assert png.status_code == 200 and is_png(png.content, 1024)
    assert time.monotonic() - started < 120
    # and a synchronous render in flight: its API worker waits for the new pool and submits again
    import threading

    result = {}
    worker = threading.Thread(target=lambda: result.update(r=client.post(
        "/v1/thumbnails", json=thumbnail_request(0.95, size=256), timeout=120)))
    worker.start()
    wait_until(lambda: processes(server, "service.workers.render_worker"), 30, "a render worker")
    time.sleep(0.3)
    kill(processes(server, POOL))
    worker.join(150)
    assert result["r"].status_code == 200 and is_png(result["r"].content, 256), result["r"].text
    assert "Traceback" not in server.log_text()
