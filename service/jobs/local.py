"""The local back end: a client of the render pool server (pool_server.py) on a Unix socket.
Under `shadergen serve` the serve command starts one pool for all API workers; an app started
any other way (`uvicorn service.main:app`, tests) starts its own. Either way a supervisor starts
the pool server again whenever it exits, and the jobs it held are submitted again by the API
worker that accepted them (under the same id, so polling goes on), once."""
import asyncio
import logging
import os
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from pathlib import Path

from ..workers import protocol
from ..workers.child import HEARTBEAT
from . import JobBackend, JobError, JobState, RenderResult

log = logging.getLogger(__name__)

READY_TIMEOUT_S = 60.0  # a fresh pool (and its first render worker) at start-up
RETURN_TIMEOUT_S = 15.0  # how long a request waits for a restarted pool before answering 503
RESTART_BACKOFF_S = (0.2, 30.0)  # first and longest pause before starting a failed pool again
STABLE_S = 10.0  # a pool that ran this long before exiting is restarted after the shortest pause
QUERY_TIMEOUT_S = 5.0  # questions about the pool (depth, a job's state) are answered at once, or never


class PoolServerSupervisor:
    """Keeps one render pool server process running on one socket, until stop().

    A thread of the process that owns the pool (`shadergen serve`, or an app that started its
    own) waits on the child and starts it again, with a pause that grows while it keeps failing.
    A supervisor such as supervisord or circus would be one more daemon with its own config for
    one child whose life must follow the serve command's; this is the wait loop they would run."""

    def __init__(self, settings, socket_path: str | None = None):
        if socket_path is None:
            socket_path = str(Path(tempfile.mkdtemp(prefix="shadergen-pool-")) / "render.sock")
        self.socket_path = socket_path
        self.env = {**os.environ, **settings.to_env()}
        self.restarts = 0
        self._lock = threading.Lock()
        self._stopping = threading.Event()
        self.process = self._start()
        self._thread = threading.Thread(target=self._watch, name="render-pool-supervisor", daemon=True)
        self._thread.start()

    def _start(self) -> subprocess.Popen:
        restarted = ["--restarted"] if self.restarts else []
        return subprocess.Popen([sys.executable, "-m", "service.jobs.pool_server", self.socket_path, *restarted],
                                env=self.env)

    def _watch(self) -> None:
        pause = RESTART_BACKOFF_S[0]
        while True:
            started = time.monotonic()
            status = self.process.wait()
            if self._stopping.is_set():
                return
            if time.monotonic() - started > STABLE_S:
                pause = RESTART_BACKOFF_S[0]
            log.warning("render pool exited with status %s; starting it again in %.1f s", status, pause)
            if self._stopping.wait(pause):
                return
            pause = min(pause * 2, RESTART_BACKOFF_S[1])
            with self._lock:
                if self._stopping.is_set():
                    return
                self.restarts += 1
                self.process = self._start()

    def stop(self) -> None:
        with self._lock:
            self._stopping.set()
            proc = self.process
        if proc.poll() is None:
            proc.terminate()
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        self._thread.join(timeout=5)
        Path(self.socket_path).unlink(missing_ok=True)
        try:
            Path(self.socket_path).parent.rmdir()
        except OSError:
            pass


class PoolGone(JobError):
    """The pool could not be reached, or closed the connection before answering."""

    def __init__(self, message: str):
        super().__init__("unavailable", message)


class LocalJobs(JobBackend):
    name = "local"

    def __init__(self, socket_path: str, supervisor: PoolServerSupervisor | None = None, wait_s: float = 180.0,
                 silent_s: float = 10.0):
        self.socket_path = socket_path
        self.supervisor = supervisor  # set when this client started the pool and must stop it
        self.wait_s = wait_s  # the longest an answer about one job may take
        self.silent_s = silent_s  # the longest the pool may send nothing, not even a heartbeat
        self._followers: set[asyncio.Task] = set()

    @classmethod
    async def connect(cls, settings) -> "LocalJobs":
        wait_s = settings.render_timeout_s * 3  # queueing, one retry, and the render itself
        timing = {"wait_s": wait_s, "silent_s": settings.ready_deadline_s}
        if settings.render_socket:
            jobs = cls(settings.render_socket, **timing)
        else:
            supervisor = await asyncio.to_thread(PoolServerSupervisor, settings)
            jobs = cls(supervisor.socket_path, supervisor, **timing)
        if not await jobs._wait_ready(READY_TIMEOUT_S):
            await jobs.close()
            raise RuntimeError(f"render pool at {jobs.socket_path} silent for {READY_TIMEOUT_S:g} s")
        return jobs

    async def _wait_ready(self, timeout_s: float) -> bool:
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            try:
                await self.depth()
                return True
            except JobError:
                await asyncio.sleep(0.05)
        return False

    async def _request(self, message: dict, timeout_s: float | None = None) -> tuple[dict, bytes]:
        """One question to the pool. `timeout_s` bounds a question the pool answers at once (depth,
        a job's state): past it the pool is not answering (unavailable, 503); without it the job's
        wait bounds the answer, past which the job timed out (504). While a render is waited for,
        the pool sends heartbeats: silence past `silent_s` means a pool stopped or wedged, answered
        at once as unavailable rather than at the job's limit."""
        expired = "unavailable" if timeout_s else "timeout"
        timeout_s = timeout_s or self.wait_s
        try:
            reader, writer = await asyncio.open_unix_connection(self.socket_path)
        except OSError as exc:
            raise PoolGone(f"the render pool is not reachable: {exc.strerror}") from None
        try:
            writer.write(protocol.encode(message))
            try:  # a usdz job's package is more than the socket holds: a stopped pool never takes it
                await asyncio.wait_for(writer.drain(), self.silent_s)
            except TimeoutError:
                writer.transport.abort()  # the request unsent, rather than run once the pool wakes
                raise JobError("unavailable", f"the render pool read nothing for {self.silent_s:g} s") from None
            async with asyncio.timeout(timeout_s):
                while True:
                    try:
                        reply, payload = await asyncio.wait_for(protocol.read_frame(reader), self.silent_s)
                    except TimeoutError:
                        raise JobError("unavailable", f"the render pool has not answered for {self.silent_s:g} s")
                    if reply != HEARTBEAT:
                        return reply, payload
        except (asyncio.IncompleteReadError, ConnectionError):
            raise PoolGone("the render pool closed the connection") from None
        except TimeoutError:
            raise JobError(expired, f"the render pool gave no answer within {timeout_s:g} s") from None
        finally:
            writer.close()

    async def _submit(self, job_id: str, request: dict, wait: bool) -> tuple[dict, bytes]:
        """Submit (and with `wait`, run) a job; if the pool is gone (it died, the supervisor is
        starting it again) wait for it to return and submit the job once more, same id."""
        message = {"op": "submit", "id": job_id, "request": request, "wait": wait}
        try:
            reply, payload = await self._request(message)
        except PoolGone as exc:
            log.warning("%s; job %s is submitted again once the pool is back", exc.message, job_id)
            if not await self._wait_ready(RETURN_TIMEOUT_S):
                raise
            reply, payload = await self._request({**message, "attempts": 1})
        if "error" in reply and "state" not in reply:
            raise JobError(**reply["error"])
        return reply, payload

    @staticmethod
    def _state(reply: dict, png: bytes) -> JobState:
        result = None
        if reply["state"] == "done":
            result = RenderResult(png, reply.get("timings_ms", {}), reply.get("warnings", []))
        return JobState(reply["id"], reply["state"], reply.get("error"), result, reply.get("attempts", 0))

    async def render(self, request: dict) -> RenderResult:
        state = self._state(*await self._submit(uuid.uuid4().hex, request, wait=True))
        if state.state != "done":
            raise JobError(**state.error)
        return state.result

    async def submit(self, request: dict) -> str:
        job_id = uuid.uuid4().hex
        await self._submit(job_id, request, wait=False)
        # this worker follows the job to its end, to submit it again should the pool die meanwhile
        follower = asyncio.create_task(self._follow(job_id, request))
        self._followers.add(follower)
        follower.add_done_callback(self._followers.discard)
        return job_id

    async def _follow(self, job_id: str, request: dict) -> None:
        deadline = time.monotonic() + self.wait_s
        while True:
            try:
                await self._submit(job_id, request, wait=True)
                return
            except JobError as exc:
                # a silent pool may be stopped for a while and go on: follow it until the job's wait is over
                silent = exc.code == "unavailable" and not isinstance(exc, PoolGone)
                if not silent or time.monotonic() > deadline:
                    log.warning("job %s lost: %s", job_id, exc.message)
                    return

    async def status(self, job_id: str) -> JobState | None:
        reply, png = await self._request({"op": "status", "id": job_id}, QUERY_TIMEOUT_S)
        if "state" not in reply:  # the pool cannot tell yet (it has just restarted)
            raise JobError(**reply["error"])
        return None if reply["state"] == "unknown" else self._state(reply, png)

    async def depth(self) -> int:
        reply, _ = await self._request({"op": "depth"}, QUERY_TIMEOUT_S)
        return reply["depth"]

    async def health(self) -> tuple[bool, str]:
        try:
            reply, _ = await self._request({"op": "depth"}, QUERY_TIMEOUT_S)
        except JobError as exc:
            return False, exc.message
        detail = (f'{reply["alive"]}/{reply["workers"]} render processes, {reply["answering"]} answering '
                  f'within {reply["deadline_s"]:g} s, {reply["depth"]} jobs queued')
        return reply["alive"] == reply["workers"] and reply["answering"] > 0, detail

    async def close(self) -> None:
        for follower in list(self._followers):
            follower.cancel()
        await asyncio.gather(*self._followers, return_exceptions=True)
        if self.supervisor is not None:
            await asyncio.to_thread(self.supervisor.stop)
