"""More than one machine, on one: a redis-server (cache and queue), two API servers that share
it, and two `shadergen worker` processes, each a stand-in for a host of its own. Which worker ran
which job is read from the workers' own logs."""
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from service_testing import ROOT, Server, document, is_png, wait_for_job, wait_until

pytestmark = pytest.mark.usefixtures("renderer_required")

THUMBNAILS = 20
RENDER_TIMEOUT_S = 30  # a job of a lost worker comes back after twice this; renders under load stay within it
SUCCEEDED = re.compile(rb"Task shadergen\.render_thumbnail\[([0-9a-f]+)\] succeeded")
RECEIVED = re.compile(rb"Task shadergen\.render_thumbnail\[([0-9a-f]+)\] received")
GOLD = ROOT / "service" / "static" / "editor" / "examples" / "gold.mtlx"


class Worker:
    """`shadergen worker` in a session of its own, so that killing it takes its whole process
    tree at once, as losing its host would."""

    def __init__(self, name: str, env: dict, tmp: Path):
        self.name = name
        self.log = tmp / f"{name}.log"
        with open(self.log, "wb") as out:
            self.proc = subprocess.Popen([sys.executable, "-m", "shadergen.cli", "worker", "--concurrency", "1"],
                                         cwd=ROOT, env=env, stdout=out, stderr=subprocess.STDOUT,
                                         start_new_session=True)
        wait_until(lambda: self.proc.poll() is not None or b" ready." in self.log.read_bytes(), 90, name)
        assert self.proc.poll() is None, self.log.read_text()

    def jobs(self, pattern=SUCCEEDED) -> set[str]:
        return {m.decode() for m in pattern.findall(self.log.read_bytes())}

    def kill_host(self) -> None:
        os.killpg(self.proc.pid, signal.SIGKILL)
        self.proc.wait()

    def close(self) -> None:
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGTERM)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.kill_host()


@pytest.fixture(scope="module")
def hosts(redis_server, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("scale-out")
    shared = redis_server.url.rsplit("/", 1)[0] + "/3"  # a database of its own: no other test's jobs
    env = {**os.environ, "SHADERGEN_BROKER": shared, "SHADERGEN_CACHE": shared,
           "SHADERGEN_RENDER_QUEUE_SIZE": "64", "SHADERGEN_RENDER_TIMEOUT_S": str(RENDER_TIMEOUT_S)}
    started = []
    try:
        for name in ("api-a", "api-b"):
            started.append(Server(tmp_path_factory.mktemp(name), workers=1, env=env))
        for name in ("worker-a", "worker-b"):
            started.append(Worker(name, env, tmp))
        yield started
    finally:
        for thing in reversed(started):
            thing.close()


def test_the_shared_cache_serves_a_record_generated_by_the_other_api(hosts):
    api_a, api_b = hosts[0], hosts[1]
    text = document("ramp.mtlx").replace("0.5", "0.4375")
    first = api_a.client.post("/v1/generate", json={"document": text}).json()
    second = api_b.client.post("/v1/generate", json={"document": text}).json()
    assert first["cached"] is False and second["cached"] is True
    assert second["hash"] == first["hash"] and second["stages"] == first["stages"]


def test_twenty_thumbnails_are_shared_by_both_workers(hosts):
    api_a, api_b, worker_a, worker_b = hosts
    ids = []
    for i in range(THUMBNAILS):
        api = (api_a, api_b)[i % 2]
        text = document("ramp.mtlx").replace("0.5", f"{0.3 + i / 100:.2f}")  # a job each, no PNG cache hit
        answer = api.client.post("/v1/thumbnails?async=true", json={"document": text, "size": 64})
        assert answer.status_code == 202, answer.text
        ids.append(answer.json()["id"])
    for i, job_id in enumerate(ids):
        client = (api_a, api_b)[(i + 1) % 2].client  # each job is followed on the API that did not take it
        status = wait_for_job(client, job_id, timeout_s=180)
        assert status["state"] == "done", status
        assert is_png(client.get(status["thumbnail_url"]).content, 64)
    ran_a, ran_b = worker_a.jobs() & set(ids), worker_b.jobs() & set(ids)
    print(f"\nper-worker jobs of {THUMBNAILS}: worker-a {len(ran_a)}, worker-b {len(ran_b)}")
    assert ran_a and ran_b, "one worker took every job"
    assert ran_a | ran_b == set(ids) and not ran_a & ran_b


def test_a_job_of_a_lost_worker_is_run_by_the_other(hosts):
    api_a, _, worker_a, worker_b = hosts
    client = api_a.client
    job_id = None
    # a job big enough to be caught running; the worker holding it is lost with its whole host
    for _ in range(10):
        job_id = client.post("/v1/thumbnails?async=true", json={"document": GOLD.read_text(), "size": 256}).json()["id"]
        wait_until(lambda: client.get(f"/v1/jobs/{job_id}").json()["state"] != "queued", 60, "the job to start")
        holder = next((w for w in (worker_a, worker_b) if job_id in w.jobs(RECEIVED)), None)
        if holder is not None and client.get(f"/v1/jobs/{job_id}").json()["state"] == "running":
            break
        wait_for_job(client, job_id)
    else:
        pytest.fail("no job was caught running")
    other = worker_b if holder is worker_a else worker_a
    ran_before = other.jobs()
    holder.kill_host()
    status = wait_for_job(client, job_id, timeout_s=4 * RENDER_TIMEOUT_S + 60)
    assert status["state"] == "done" and status["attempts"] == 2, status
    # the holder's own queue died with it: the API sent the job again, as a task of the other's
    assert other.jobs() - ran_before and job_id not in holder.jobs()
    print(f"\njob {job_id} lost with {holder.name}, done by {other.name} on attempt {status['attempts']}")
