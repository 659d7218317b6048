"""The containers, built and run: the image of docker/Dockerfile (built by docker/build.sh on a local
Debian 12 base), then the stack of docker/compose.yaml on the host's network, on free 127.0.0.1
ports: the API, two Celery render workers and two Redis servers, all from that one image. The
commands are those of the README's Docker section. A Docker engine that is not running is started
here (`dockerd --bridge=none --iptables=false`, as root) and stopped at the end; under CI=true a
missing engine fails the test instead of skipping it."""
import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import httpx
import pytest

from required_tools import missing, tool_path
from service_testing import ROOT, HOST, document, free_port, is_png, stop, wait_until

BUILD = "bash docker/build.sh"
COMPOSE_FILE = "docker/compose.yaml"
UP = "up -d --scale worker=2"
DOWN = "down --volumes"
IMAGE = "shadergen:latest"
RENDER_TIMEOUT_S = 15  # a killed worker's job goes to the other after twice this (celery_app)
BUILD_TIMEOUT_S = 1200

pytestmark = pytest.mark.timeout(BUILD_TIMEOUT_S + 600)


def docker(*args: str, timeout_s: float = 120, **kwargs) -> subprocess.CompletedProcess:
    return subprocess.run(["docker", *args], capture_output=True, text=True, timeout=timeout_s, **kwargs)


def engine_answers() -> bool:
    return docker("info", timeout_s=30).returncode == 0


@pytest.fixture(scope="module")
def engine(tmp_path_factory):
    tool_path("docker")
    if engine_answers():
        yield
        return
    dockerd = shutil.which("dockerd")
    if dockerd is None or os.geteuid() != 0:
        missing("a Docker engine", "none answers, and only root may start dockerd here")
    log = open(tmp_path_factory.mktemp("dockerd") / "dockerd.log", "wb")
    proc = subprocess.Popen([dockerd, "--bridge=none", "--iptables=false"], stdout=log, stderr=subprocess.STDOUT)
    try:
        wait_until(lambda: proc.poll() is not None or engine_answers(), 90, "dockerd", pause_s=0.5)
        assert proc.poll() is None, Path(log.name).read_text()[-3000:]
        remove_left_stacks()
        yield
    finally:
        stop(proc, timeout_s=60)
        log.close()


def remove_left_stacks() -> None:
    """The stacks of earlier runs that never came down (a run killed before its teardown) restart
    with the engine (compose's `restart: unless-stopped`), each an API and workers competing with
    this run's for the machine: they are removed, whoever left them."""
    listed = docker("ps", "-a", "--filter", "label=com.docker.compose.project",
                    "--format", '{{.ID}} {{.Label "com.docker.compose.project"}}').stdout.split("\n")
    left = [line.split()[0] for line in listed if " shadergen-test-" in line]
    if left:
        docker("rm", "--force", *left, timeout_s=300)


@pytest.fixture(scope="module")
def compose_command() -> list[str]:
    if shutil.which("docker-compose"):
        return ["docker-compose"]
    if docker("compose", "version").returncode == 0:
        return ["docker", "compose"]
    missing("docker-compose (or the compose plugin)", "scripts/system-packages.sh --containers installs it")


@pytest.fixture(scope="module")
def build(engine) -> str:
    """The output of docker/build.sh: the image is built once for the module."""
    started = time.monotonic()
    done = subprocess.run(BUILD.split(), cwd=ROOT, capture_output=True, text=True, timeout=BUILD_TIMEOUT_S)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    print(f"docker/build.sh: {time.monotonic() - started:.0f} s")
    return done.stdout


@pytest.fixture(scope="module")
def stack(build, compose_command, tmp_path_factory):
    """docker/compose.yaml up, on free ports, under a project name of its own; down at the end."""
    port = free_port()
    env = {**os.environ, "COMPOSE_PROJECT_NAME": f"shadergen-test-{os.getpid()}", "SHADERGEN_PORT": str(port),
           "SHADERGEN_CACHE_PORT": str(free_port()), "SHADERGEN_BROKER_PORT": str(free_port()),
           "SHADERGEN_RENDER_TIMEOUT_S": str(RENDER_TIMEOUT_S)}

    def compose(args: str, timeout_s: float = 300) -> subprocess.CompletedProcess:
        return subprocess.run(compose_command + ["-f", COMPOSE_FILE] + args.split(), cwd=ROOT, env=env, capture_output=True, text=True,
                              timeout=timeout_s)

    client = httpx.Client(base_url=f"http://{HOST}:{port}", timeout=120)
    try:
        up = compose(UP)
        assert up.returncode == 0, up.stdout[-3000:] + up.stderr[-3000:]
        wait_until(lambda: healthy(client), 120, "the API container", pause_s=0.5)
        yield compose, client
    finally:
        client.close()
        try:  # the logs are kept for a failure's diagnosis; not getting them must not leave the stack up
            logs = tmp_path_factory.mktemp("compose") / "compose.log"
            logs.write_text(compose("logs --no-color", timeout_s=120).stdout)
        finally:
            compose(DOWN + " --timeout 10")


def healthy(client: httpx.Client) -> bool:
    try:
        return client.get("/healthz").status_code == 200
    except httpx.TransportError:
        return False


def in_image(*command: str) -> subprocess.CompletedProcess:
    return docker("run", "--rm", "--network", "none", IMAGE, *command)


def readme_docker_section() -> str:
    text = (ROOT / "README.md").read_text()
    return re.search(r"^## Docker\n(.*?)(?=^## |\Z)", text, re.S | re.M).group(1)


def test_readme_docker_section_is_what_this_test_runs():
    section = readme_docker_section()
    for command in (BUILD, f"-f {COMPOSE_FILE} {UP}", f"-f {COMPOSE_FILE} {DOWN}"):
        assert command in section, command


def test_build_context_leaves_out_the_checkout(build):
    # the classic builder reports what it sent; a checkout's .venv alone is hundreds of MB
    sent = re.search(r"Sending build context to Docker daemon\s+([\d.]+)([kMG]?B)", build)
    size = float(sent.group(1)) * {"B": 1, "kB": 1e3, "MB": 1e6, "GB": 1e9}[sent.group(2)]
    assert size < 5e6, sent.group(0)


def test_image_runs_unprivileged_with_libgl_and_compiled_bytecode(build):
    probe = in_image("python", "-c", (
        "import ctypes, getpass, importlib.util, pathlib\n"
        "ctypes.CDLL('libGL.so.1')\n"
        "sources = [p for d in ('shadergen', 'service') for p in pathlib.Path('/app', d).rglob('*.py')]\n"
        "stale = [str(p) for p in sources if not pathlib.Path(importlib.util.cache_from_source(p)).exists()]\n"
        "print(getpass.getuser(), len(sources), stale)"))
    assert probe.returncode == 0, probe.stderr
    user, count, stale = probe.stdout.split(maxsplit=2)
    assert user == "shadergen" and int(count) > 50 and stale.strip() == "[]", probe.stdout


def test_thumbnails_and_shaders_through_the_stack(stack):
    compose, client = stack
    for name, size in (("marble.mtlx", 64), ("ramp.mtlx", 96)):
        r = client.post("/v1/thumbnails", json={"document": document(name), "size": size})
        assert r.status_code == 200, r.text
        assert is_png(r.content, size)
    health = client.get("/healthz").json()
    assert health["cache"] == "RedisStore" and health["jobs"] == "celery", health
    text = document("ramp.mtlx").replace("0.5", "0.375")
    first = client.post("/v1/generate", json={"document": text}).json()
    second = client.post("/v1/generate", json={"document": text}).json()
    assert first["cached"] is False and second["cached"] is True and second["hash"] == first["hash"]


def job_status(client: httpx.Client, job: str) -> dict:
    """A job's status as a polling client sees it: a 503 with Retry-After (the broker busy while a
    container dies) means ask again, and reads as no state yet; any other answer but 200 fails."""
    r = client.get(f"/v1/jobs/{job}")
    if r.status_code == 503 and "retry-after" in r.headers:
        return {}
    assert r.status_code == 200, (r.status_code, r.text)
    return r.json()


def test_job_of_a_killed_worker_container_completes(stack):
    compose, client = stack
    workers = compose("ps -q worker").stdout.split()
    assert len(workers) == 2, workers
    jobs = [client.post("/v1/thumbnails?async=true", json={"document": document("marble.mtlx"), "size": 1024}).json()["id"]
            for _ in range(2)]

    def both_running() -> bool:
        return all(job_status(client, job).get("state") == "running" for job in jobs)

    # each worker runs one job at a time: two jobs running means one in each container
    wait_until(both_running, 60, "both jobs running", pause_s=0.02)
    killed = docker("kill", workers[0])
    assert killed.returncode == 0, killed.stderr
    attempts = {job: 1 for job in jobs}

    def finished() -> bool:
        states = {}
        for job in jobs:
            status = job_status(client, job)
            states[job] = status.get("state")
            attempts[job] = max(attempts[job], status.get("attempts", 1))
        return all(state in ("done", "failed") for state in states.values()) and states

    states = wait_until(finished, 4 * RENDER_TIMEOUT_S + 30, "jobs after the kill", pause_s=0.05)
    assert set(states.values()) == {"done"}, states
    # the killed container's job ran a second time, in the other container
    assert sorted(attempts.values()) == [1, 2], attempts
    for job in jobs:
        assert is_png(client.get(f"/v1/jobs/{job}/thumbnail").content, 1024)
