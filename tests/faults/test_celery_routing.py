"""Issue 23 with Celery: two `shadergen worker`s, each with its own queue, thumbnails routed to the
worker that holds their program; a whole worker killed (kill -9, its main process and its
render processes, as its machine going away) in the middle of a batch loses nothing: its jobs are
sent again to the other worker once its queue's announcement expires."""
import subprocess
import sys

import pytest

from faults_testing import kill
from service_testing import ROOT, RedisServer, Server, descendants, stop, wait_until
from test_routing_faults import TOPOLOGIES, material, programs, run_batch, status

pytestmark = pytest.mark.usefixtures("renderer_required")


@pytest.fixture(scope="module")
def stack(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("celeryrouting")
    redis_server = RedisServer(tmp)
    env = {"SHADERGEN_BROKER": redis_server.url, "SHADERGEN_CACHE": redis_server.url,
           "SHADERGEN_READY_DEADLINE_S": "2", "SHADERGEN_HEARTBEAT_S": "0.25", "SHADERGEN_RENDER_QUEUE_SIZE": "64"}
    srv = Server(tmp, workers=1, env=env)
    srv.workers, logs = {}, {}
    try:
        for name in ("w0", "w1"):
            logs[name] = tmp / f"{name}.log"
            with open(logs[name], "wb") as out:
                srv.workers[name] = subprocess.Popen(
                    [sys.executable, "-m", "shadergen.cli", "worker", "--concurrency", "1", "--name", name],
                    cwd=ROOT, env=srv.env, stdout=out, stderr=subprocess.STDOUT)
        for name, log in logs.items():
            wait_until(lambda: srv.workers[name].poll() is not None or b" ready." in log.read_bytes(), 90, name)
            assert srv.workers[name].poll() is None, log.read_text()
        yield srv
    finally:
        for proc in srv.workers.values():
            stop(proc)
        srv.close()
        stop(redis_server.proc)


def test_thumbnails_are_routed_to_the_worker_holding_their_program(stack):
    client = stack.client
    before = programs(client)
    url = run_batch(client, [material(i) for i in range(18)], 32)
    done = wait_until(lambda: (s := status(client, url))["state"] == "done" and s, 300, "the batch")
    assert done["failed"] == 0, done
    after = programs(client)
    compiled = after.get("compiled", 0) - before.get("compiled", 0)
    reused = after.get("reused", 0) - before.get("reused", 0)
    print(f"celery routing: 18 materials, 3 topologies, 2 workers: {compiled:.0f} compiled, {reused:.0f} reused")
    assert compiled + reused == 18
    assert compiled <= len(TOPOLOGIES)  # each topology on one worker: a shared queue compiles up to 6


def test_a_worker_killed_mid_batch_loses_no_document(stack):
    client = stack.client
    documents = [material(200 + i) for i in range(24)]
    url = run_batch(client, documents, 256)
    wait_until(lambda: status(client, url)["done"] >= 2, 300, "the batch under way")
    victim = stack.workers["w0"]
    kill([*descendants(victim.pid), victim.pid])
    assert status(client, url)["done"] < len(documents), "the batch ended before the kill: nothing was tested"
    done = wait_until(lambda: (s := status(client, url))["state"] == "done" and s, 600, "the batch")
    assert (done["total"], done["done"], done["failed"]) == (24, 24, 0), [r for r in done["results"] if r.get("error")]
    pngs = [client.get(r["thumbnail_url"]).content for r in done["results"]]
    assert all(p[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs)
