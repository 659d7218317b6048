"""Issue 23: thumbnails routed by topology over three render workers. A library of a few
topologies compiles about one program per topology, not one per worker and topology; a render
worker killed (kill -9) in the middle of a batch loses nothing: its running job is run again by
its replacement, its share goes to the others meanwhile, and every document gets its PNG."""
import re

import pytest

from faults_testing import kill, processes, wait_ready
from service_testing import Server, wait_until

RENDER = "service.workers.render_worker"
TOPOLOGIES = ("multiply", "add", "subtract")
pytestmark = pytest.mark.usefixtures("renderer_required")


def material(i: int) -> str:
    """Material i: one of three topologies (the node that makes its colour), its own names and values."""
    op = TOPOLOGIES[i % len(TOPOLOGIES)]
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <{op} name="colour_{i}" type="color3">
    <input name="in1" type="color3" value="{0.05 + i % 36 / 40:.3f}, 0.3, 0.5" /><input name="in2" type="float" value="0.2" />
  </{op}>
  <surface_unlit name="shader_{i}" type="surfaceshader"><input name="emission_color" type="color3" nodename="colour_{i}" /></surface_unlit>
  <surfacematerial name="material_{i}" type="material"><input name="surfaceshader" type="surfaceshader" nodename="shader_{i}" /></surfacematerial>
</materialx>"""


def programs(client) -> dict[str, float]:
    text = client.get("/metrics").text
    return {m.group(1): float(m.group(2)) for m in re.finditer(r'shadergen_programs_total\{result="(\w+)"\} (\S+)', text)}


def run_batch(client, documents: list[str], size: int) -> str:
    r = client.post("/v1/thumbnails/batch", json={"documents": [{"document": d} for d in documents], "size": size})
    assert r.status_code == 202, r.text
    return r.json()["status_url"]


def status(client, url: str) -> dict:
    return client.get(url).json()


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("routing"), workers=2, render_workers=3)
    yield srv
    srv.close()


def test_a_library_compiles_about_one_program_per_topology(server):
    client = server.client
    wait_ready(client)
    wait_until(lambda: len(processes(server, RENDER)) == 3, 90, "three render workers")
    before = programs(client)
    url = run_batch(client, [material(i) for i in range(30)], 32)
    done = wait_until(lambda: (s := status(client, url))["state"] == "done" and s, 300, "the batch")
    assert done["failed"] == 0, done
    after = programs(client)
    compiled = after.get("compiled", 0) - before.get("compiled", 0)
    reused = after.get("reused", 0) - before.get("reused", 0)
    print(f"routing: 30 materials, 3 topologies, 3 workers: {compiled:.0f} compiled, {reused:.0f} reused")
    assert compiled + reused == 30
    # shared queues compile each topology on every worker that meets it (up to 9); bounded loads
    # may hand a busy worker's topology to one more worker
    assert compiled <= 2 * len(TOPOLOGIES)


def test_a_render_worker_killed_mid_batch_loses_no_document(server):
    client = server.client
    wait_ready(client)
    documents = [material(100 + i) for i in range(36)]
    url = run_batch(client, documents, 512)
    wait_until(lambda: status(client, url)["done"] >= 3, 300, "the batch under way")
    workers = processes(server, RENDER)
    assert len(workers) == 3
    kill(workers[:1])
    at_kill = status(client, url)
    assert at_kill["done"] < len(documents), "the batch ended before the kill: nothing was tested"
    done = wait_until(lambda: (s := status(client, url))["state"] == "done" and s, 600, "the batch")
    assert (done["total"], done["done"], done["failed"]) == (36, 36, 0), [r for r in done["results"] if r.get("error")]
    assert all(r["state"] == "done" for r in done["results"])
    pngs = [client.get(r["thumbnail_url"]).content for r in done["results"]]
    assert all(p[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs)
    fresh = wait_until(lambda: len(p := processes(server, RENDER)) == 3 and p, 90, "the worker replaced")
    assert workers[0] not in fresh
    assert "Traceback" not in server.log_text()
