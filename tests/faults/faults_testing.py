"""What the fault tests share: finding a server's processes, and waiting for answers that a
client told to retry (503 with Retry-After) would wait for."""
import os
import signal
import time

from service_testing import cmdline, descendants, wait_until


def processes(server, module: str) -> list[int]:
    return [pid for pid in descendants(server.proc.pid) if f"-m {module}" in cmdline(pid)]


def kill(pids: list[int]) -> None:
    assert pids, "no process to kill"
    for pid in pids:
        os.kill(pid, signal.SIGKILL)


def readiness(client) -> tuple[int, dict]:
    r = client.get("/readyz")
    return r.status_code, r.json()


def wait_ready(client, timeout_s: float = 90) -> dict:
    return wait_until(lambda: readiness(client)[0] == 200 and readiness(client)[1], timeout_s, "readiness")


def poll_job(client, job_id: str, timeout_s: float = 120) -> dict:
    """A job's final state, polling through 503s (the pool restarting) as Retry-After asks."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        r = client.get(f"/v1/jobs/{job_id}")
        if r.status_code == 503:
            assert "Retry-After" in r.headers
        else:
            assert r.status_code == 200, r.text
            if r.json()["state"] in ("done", "failed"):
                return r.json()
        time.sleep(0.05)
    raise TimeoutError(f"job {job_id} not finished within {timeout_s:g} s")
