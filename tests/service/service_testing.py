"""Helpers that start real things on 127.0.0.1 (redis-server, `shadergen serve`) for the service
tests. Every process started here is stopped by its owner, and every wait is bounded."""
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import httpx
import pytest

from processes import children, cmdline, descendants  # noqa: F401 (the service tests' names for them)
from required_tools import tool_path

ROOT = Path(__file__).resolve().parents[2]
HOST = "127.0.0.1"
DOCS = Path(__file__).parent / "documents"


def free_port() -> int:
    with socket.socket() as s:
        s.bind((HOST, 0))
        return s.getsockname()[1]


def wait_until(predicate, timeout_s: float, what: str, pause_s: float = 0.05):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(pause_s)
    raise TimeoutError(f"{what} not within {timeout_s:g} s")


def stop(proc: subprocess.Popen, timeout_s: float = 20) -> None:
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=timeout_s)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


# -- redis ------------------------------------------------------------------------------------
class RedisServer:
    def __init__(self, tmp: Path):
        exe = tool_path("redis-server")
        self.exe, self.tmp = exe, tmp
        self.port = free_port()
        self.url = f"redis://{HOST}:{self.port}/0"
        self.start()

    def start(self) -> None:
        """Start (or, once stopped, start again) the server on its port, empty."""
        self.proc = subprocess.Popen(
            [self.exe, "--bind", HOST, "--port", str(self.port), "--save", "", "--appendonly", "no",
             "--dir", str(self.tmp), "--maxmemory", "256mb", "--maxmemory-policy", "allkeys-lru"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )
        wait_until(self._ping, 15, "redis-server")

    def _ping(self) -> bool:
        try:
            with socket.create_connection((HOST, self.port), timeout=1) as s:
                s.sendall(b"PING\r\n")
                return s.recv(16).startswith(b"+PONG")
        except OSError:
            return False

    def flush(self) -> None:
        import redis

        redis.Redis.from_url(self.url).flushall()



class Server:
    """`shadergen serve` on a free loopback port, with its own cache file and settings."""

    def __init__(self, tmp: Path, workers: int = 2, render_workers: int = 1, env: dict | None = None):
        self.port = free_port()
        self.url = f"http://{HOST}:{self.port}"
        self.log = open(tmp / "serve.log", "wb")
        self.cache_path = tmp / "cache.sqlite3"
        self.env = {
            **os.environ,
            "SHADERGEN_CACHE": f"sqlite:///{self.cache_path}",
            "SHADERGEN_TEXTURE_ROOTS": str(DOCS),
            # uploads may include the documents under included/ (and nothing else)
            "SHADERGEN_INCLUDE_ROOTS": str(DOCS / "included"),
            # every test client is one address that sends bad input on purpose, by the hundred: the
            # failure ledger (service/fairness.py) is off unless a test turns it on
            "SHADERGEN_CLIENT_FAILURE_BURST": "0",
            **(env or {}),
        }
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "shadergen.cli", "serve", "--host", HOST, "--port", str(self.port),
             "--workers", str(workers), "--render-workers", str(render_workers)],
            cwd=ROOT, env=self.env, stdout=self.log, stderr=subprocess.STDOUT,
        )
        self.client = httpx.Client(base_url=self.url, timeout=120)
        wait_until(self._healthy, 90, "shadergen serve")

    def _healthy(self) -> bool:
        if self.proc.poll() is not None:
            raise RuntimeError(f"shadergen serve exited with {self.proc.returncode}: {self.log_text()[-3000:]}")
        try:
            return self.client.get("/healthz").status_code == 200
        except httpx.TransportError:
            return False

    def log_text(self) -> str:
        self.log.flush()
        return Path(self.log.name).read_text(errors="replace")

    def close(self) -> None:
        self.client.close()
        stop(self.proc)
        self.log.close()


def assert_error(response, status: int, code: str) -> dict:
    """The contract's error object with this status and code; returns its `error`."""
    assert response.status_code == status, response.text
    body = response.json()
    assert set(body) == {"document", "element", "target", "error"}
    assert body["error"]["code"] == code and body["error"]["message"]
    return body["error"]


def document(name: str) -> str:
    return (DOCS / name).read_text()


def wait_for_job(client, job_id: str, timeout_s: float = 120) -> dict:
    def finished():
        body = client.get(f"/v1/jobs/{job_id}").json()
        return body if body["state"] in ("done", "failed") else None

    return wait_until(finished, timeout_s, f"job {job_id}", pause_s=0.05)


def kill_while_running(client, job_id: str, find_workers, kills: int, timeout_s: float = 60) -> list[int]:
    """Kill the process running job `job_id` `kills` times (each time a new one has taken it up)."""
    import signal

    killed: list[int] = []
    deadline = time.monotonic() + timeout_s
    while len(killed) < kills and time.monotonic() < deadline:
        status = client.get(f"/v1/jobs/{job_id}").json()
        if status["state"] in ("done", "failed"):
            break
        fresh = [p for p in find_workers() if p not in killed]
        # attempt n+1 has begun on a process that is not one of the n already killed
        if status["state"] == "running" and status["attempts"] == len(killed) + 1 and fresh:
            for pid in fresh:
                os.kill(pid, signal.SIGKILL)
            killed.extend(fresh)
        time.sleep(0.01)
    return killed


def receive_head(s: socket.socket) -> bytes:
    """The status line and headers of the answer on a raw socket."""
    response = b""
    while b"\r\n\r\n" not in response:
        data = s.recv(65536)
        if not data:
            break
        response += data
    return response


def is_png(data: bytes, side: int) -> bool:
    import struct

    return data[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", data[16:24]) == (side, side)
