"""Issue 21, items 2 and 5, for Celery's render workers (`shadergen worker`): a render over the
memory limit answers 413 `too_large` (its process killed, replaced, the task not run again), a
process killed mid-job (SIGKILL) leaves nothing in its temporary folder once a new one starts, and
readiness follows the processes' heartbeats (SIGSTOP: 503 within the deadline; SIGCONT: ready)."""
import os
import signal
import subprocess
import sys
import threading

import pytest

from faults_testing import kill, readiness, wait_ready
from service_testing import (DOCS, ROOT, RedisServer, Server, assert_error, cmdline, descendants, document,
                             is_png, stop, wait_until)
from test_child_memory import USDZ, big_texture, temporary_files, textured_usdz

RENDER_MIB, DEADLINE_S = 600, 2
pytestmark = pytest.mark.usefixtures("renderer_required")


@pytest.fixture(scope="module")
def stack(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("celerymemory")
    textures = tmp / "textures"
    textures.mkdir()
    (textures / "big.png").write_bytes(big_texture())
    (textures / "checker.png").write_bytes((DOCS / "checker.png").read_bytes())
    (tmp / "tmp").mkdir()
    redis_server = RedisServer(tmp)
    env = {"SHADERGEN_BROKER": redis_server.url, "SHADERGEN_CACHE": redis_server.url,
           "SHADERGEN_RENDER_MEMORY_MIB": str(RENDER_MIB), "SHADERGEN_TEXTURE_ROOTS": str(textures),
           "TMPDIR": str(tmp / "tmp"), "SHADERGEN_READY_DEADLINE_S": str(DEADLINE_S), "SHADERGEN_HEARTBEAT_S": "0.25"}
    srv = Server(tmp, workers=1, env=env)
    srv.tmp = tmp / "tmp"
    log = tmp / "worker.log"
    with open(log, "wb") as out:
        worker = subprocess.Popen([sys.executable, "-m", "shadergen.cli", "worker", "--concurrency", "1"],
                                  cwd=ROOT, env=srv.env, stdout=out, stderr=subprocess.STDOUT)
    try:
        wait_until(lambda: worker.poll() is not None or b" ready." in log.read_bytes(), 60, "shadergen worker")
        assert worker.poll() is None, log.read_text()
        srv.worker, srv.worker_log = worker, log
        yield srv
    finally:
        stop(worker)
        srv.close()
        stop(redis_server.proc)


def render_processes(stack) -> list[int]:
    """The prefork processes of the worker (its main process's children)."""
    return [p for p in descendants(stack.worker.pid) if "shadergen.cli worker" in cmdline(p)]


def test_celery_render_over_its_limit_answers_413(stack):
    client = stack.client
    before = wait_until(lambda: render_processes(stack), 30, "a render process")
    big = document("textured.mtlx").replace("checker.png", "big.png")
    r = client.post("/v1/thumbnails", json={"document": big, "size": 32}, timeout=180)
    err = assert_error(r, 413, "too_large")
    assert f"limit of {RENDER_MIB} MiB" in err["message"], err
    assert stack.worker_log.read_text().count("MiB; killed") == 1  # the second attempt did not render
    r = client.post("/v1/thumbnails", json={"document": document("textured.mtlx"), "size": 32}, timeout=180)
    assert r.status_code == 200 and is_png(r.content, 32), r.text
    assert not set(render_processes(stack)) & set(before)
    assert not temporary_files(stack), temporary_files(stack)


def test_celery_render_process_killed_mid_job_leaves_nothing(stack, tmp_path):
    client = stack.client
    package = textured_usdz(tmp_path / "textured")
    answer = {}
    thread = threading.Thread(target=lambda: answer.update(r=client.post(
        "/v1/thumbnails", params={"size": 48}, content=package, headers=USDZ, timeout=180)))
    thread.start()
    try:
        # the job's folder, in the folder of the process that runs it: shadergen-child-<pid>-*/shadergen-job-*
        left = wait_until(lambda: [p for p in temporary_files(stack) if "/shadergen-job-" in p], 60, "a job's files",
                          pause_s=0.002)
        owner = int(left[0].split("/")[0][len("shadergen-child-"):].split("-")[0])
        assert owner in render_processes(stack)
        kill([owner])
    finally:
        thread.join(timeout=200)
    # tried again on a fresh process, which goes over the limit decoding the 4096 px texture
    assert_error(answer["r"], 413, "too_large")
    wait_until(lambda: not temporary_files(stack), 30, "the killed process's files removed")


def test_celery_readiness_follows_the_render_processes_heartbeats(stack):
    client = stack.client
    body = wait_ready(client)
    assert body["render"]["detail"].startswith("1 render processes answering"), body
    (process,) = render_processes(stack)
    os.kill(process, signal.SIGSTOP)
    try:
        body = wait_until(lambda: (r := readiness(client))[0] == 503 and r[1], 5 * DEADLINE_S, "readiness 503")
        assert not body["render"]["ready"] and body["render"]["detail"].startswith("0 render processes"), body
        assert body["generator"]["ready"] and body["cache"]["ready"], body
    finally:
        os.kill(process, signal.SIGCONT)
    wait_ready(client)
    r = client.post("/v1/thumbnails", json={"document": document("textured.mtlx"), "size": 24}, timeout=180)
    assert r.status_code == 200 and is_png(r.content, 24), r.text
