"""The local back end: a client of the render pool server (pool_server.py) on a Unix socket.
Under `shadergen serve` the serve command starts one pool for all API workers; an app started
any other way (`uvicorn service.main:app`, tests) starts its own."""
import asyncio
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ..workers import protocol
from . import JobBackend, JobError, JobState, RenderResult

READY_TIMEOUT_S = 60.0


def start_pool_server(settings, socket_path: str | None = None) -> tuple[subprocess.Popen, str]:
    """Start a render pool process; its socket lives in a private temporary directory."""
    if socket_path is None:
        socket_path = str(Path(tempfile.mkdtemp(prefix="shadergen-pool-")) / "render.sock")
    env = {**os.environ, **settings.to_env()}
    proc = subprocess.Popen([sys.executable, "-m", "service.jobs.pool_server", socket_path], env=env)
    return proc, socket_path


def stop_pool_server(proc: subprocess.Popen, socket_path: str) -> None:
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    Path(socket_path).unlink(missing_ok=True)
    try:
        Path(socket_path).parent.rmdir()
    except OSError:
        pass


class LocalJobs(JobBackend):
    name = "local"

    def __init__(self, socket_path: str, process: subprocess.Popen | None = None):
        self.socket_path = socket_path
        self.process = process  # set when this client started the pool and must stop it

    @classmethod
    async def connect(cls, settings) -> "LocalJobs":
        if settings.render_socket:
            jobs = cls(settings.render_socket)
        else:
            process, socket_path = start_pool_server(settings)
            jobs = cls(socket_path, process)
        await jobs._wait_ready()
        return jobs

    async def _wait_ready(self) -> None:
        deadline = time.monotonic() + READY_TIMEOUT_S
        while True:
            try:
                await self.depth()
                return
            except JobError:
                if self.process is not None and self.process.poll() is not None:
                    raise RuntimeError(f"render pool exited with status {self.process.returncode}") from None
                if time.monotonic() > deadline:
                    raise RuntimeError(f"render pool at {self.socket_path} silent for {READY_TIMEOUT_S:g} s") from None
                await asyncio.sleep(0.05)

    async def _request(self, message: dict) -> tuple[dict, bytes]:
        try:
            reader, writer = await asyncio.open_unix_connection(self.socket_path)
        except OSError as exc:
            raise JobError("unavailable", f"the render pool is not reachable: {exc.strerror}") from None
        try:
            writer.write(protocol.encode(message))
            await writer.drain()
            return await protocol.read_frame(reader)
        except (asyncio.IncompleteReadError, ConnectionError):
            raise JobError("unavailable", "the render pool closed the connection") from None
        finally:
            writer.close()

    @staticmethod
    def _state(reply: dict, png: bytes) -> JobState:
        result = None
        if reply["state"] == "done":
            result = RenderResult(png, reply.get("timings_ms", {}), reply.get("warnings", []))
        return JobState(reply["id"], reply["state"], reply.get("error"), result, reply.get("attempts", 0))

    async def render(self, request: dict) -> RenderResult:
        reply, png = await self._request({"op": "submit", "request": request, "wait": True})
        if "error" in reply and "state" not in reply:
            raise JobError(**reply["error"])
        state = self._state(reply, png)
        if state.state != "done":
            raise JobError(**state.error)
        return state.result

    async def submit(self, request: dict) -> str:
        reply, _ = await self._request({"op": "submit", "request": request, "wait": False})
        if "error" in reply:
            raise JobError(**reply["error"])
        return reply["id"]

    async def status(self, job_id: str) -> JobState | None:
        reply, png = await self._request({"op": "status", "id": job_id})
        return None if reply["state"] == "unknown" else self._state(reply, png)

    async def depth(self) -> int:
        reply, _ = await self._request({"op": "depth"})
        return reply["depth"]

    async def close(self) -> None:
        if self.process is not None:
            await asyncio.to_thread(stop_pool_server, self.process, self.socket_path)
