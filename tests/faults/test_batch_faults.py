"""A thumbnail batch runs in the API worker that accepted it. Killed (kill -9) mid-batch, that
worker takes no document with it: uvicorn starts another, the next poll finds the batch's lease
lapsed, claims it and runs the documents that had no result yet; those done keep theirs."""
import httpx
import pytest

from faults_testing import kill, wait_ready
from service_testing import Server, children, cmdline, wait_until

pytestmark = pytest.mark.usefixtures("renderer_required")
DOCUMENTS = 24


def material(i: int) -> str:
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <multiply name="colour_{i}" type="color3">
    <input name="in1" type="color3" value="{i / DOCUMENTS:.3f}, 0.3, 0.5" /><input name="in2" type="float" value="0.9" />
  </multiply>
  <surface_unlit name="shader_{i}" type="surfaceshader"><input name="emission_color" type="color3" nodename="colour_{i}" /></surface_unlit>
  <surfacematerial name="material_{i}" type="material"><input name="surfaceshader" type="surfaceshader" nodename="shader_{i}" /></surfacematerial>
</materialx>"""


def api_workers(server) -> list[int]:
    """uvicorn's worker processes: the children its supervisor spawned (not the render pool's)."""
    return [pid for pid in children(server.proc.pid) if "spawn_main" in cmdline(pid)]


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    # one thumbnail at a time, a short lease: the batch is still running when its worker dies,
    # and is taken over soon after
    srv = Server(tmp_path_factory.mktemp("batch-faults"), workers=2,
                 env={"SHADERGEN_BATCH_CONCURRENCY": "1", "SHADERGEN_BATCH_LEASE_S": "2"})
    yield srv
    srv.close()


def test_an_api_worker_killed_mid_batch_loses_no_document(server):
    client = server.client
    wait_ready(client)
    r = client.post("/v1/thumbnails/batch",
                    json={"documents": [{"document": material(i), "name": f"m{i}"} for i in range(DOCUMENTS)],
                          "size": 256})
    assert r.status_code == 202, r.text
    url = r.json()["status_url"]
    wait_until(lambda: client.get(url).json()["done"] >= 2, 300, "the batch under way")
    workers = api_workers(server)
    assert len(workers) == 2
    kill(workers)  # whichever runs the batch: both
    polls = []

    def finished():
        try:
            answer = client.get(url)
        except httpx.TransportError:  # the connection was the killed worker's: the client retries
            return None
        if answer.status_code != 200:  # no worker yet to answer
            return None
        polls.append(answer.json())
        return polls[-1] if polls[-1]["state"] == "done" else None

    done = wait_until(finished, 600, "the batch after its worker died", pause_s=0.2)
    assert polls[0]["done"] < DOCUMENTS, "the batch ended before the kill: nothing was tested"
    assert (done["total"], done["done"], done["failed"]) == (DOCUMENTS, DOCUMENTS, 0), \
        [x for x in done["results"] if x.get("error")]
    assert [x["name"] for x in done["results"]] == [f"m{i}" for i in range(DOCUMENTS)]
    pngs = [client.get(x["thumbnail_url"]).content for x in done["results"]]
    assert all(p[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs) and len(set(pngs)) == DOCUMENTS
    assert not set(workers) & set(api_workers(server)), "the killed workers were replaced"
