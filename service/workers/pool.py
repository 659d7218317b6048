"""A bounded pool of child processes, each running `python -m <module>` and answering framed
requests on its stdin/stdout (see protocol.py and child.py).

Why processes: generation and rendering are CPU-bound Python or GL work; in a child they never
hold the event loop, a runaway job can be killed at its time limit, and a crash (a segfault in a
GL driver, the OOM killer) costs one child, which is replaced. A job whose child crashed is tried
once more on the fresh child, then failed with a clear error: a job that kills every process it
touches must not take the whole pool down one child at a time.

Supervision is ours rather than a library's (loky's reusable executor was weighed): a job past its
time limit must be killed alone while the other children go on, which loky cannot do without
shutting the whole executor down and failing every job in flight; and children speak JSON frames,
never pickles. So each slot watches its child even while idle (one that dies is replaced before a
job finds it dead), a slot task that fails is started again, and every wait has a deadline."""
import asyncio
import logging
import os
import signal
import sys
import time
import uuid
from dataclasses import dataclass, field

from . import protocol

log = logging.getLogger(__name__)

START_TIMEOUT_S = 180.0  # a cold child loads the node libraries (or an EGL driver) first
RESPAWN_BACKOFF_S = (1.0, 30.0)  # first and longest pause before starting a failed child again


class PoolError(Exception):
    """Base of what a job can fail with besides its own reply."""


class QueueFull(PoolError):
    pass


class JobTimeout(PoolError):
    pass


class WorkerCrashed(PoolError):
    pass


class ChildProcess:
    """One child and its pipes."""

    def __init__(self, module: str, env: dict[str, str] | None = None):
        self.module = module
        self.env = env
        self.proc: asyncio.subprocess.Process | None = None
        self.hello: dict = {}

    @property
    def pid(self) -> int | None:
        return self.proc.pid if self.proc else None

    async def start(self) -> dict:
        env = {**os.environ, **(self.env or {})}
        self.proc = await asyncio.create_subprocess_exec(
            sys.executable, "-m", self.module,
            stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE, env=env,
        )
        try:
            self.hello, _ = await asyncio.wait_for(protocol.read_frame(self.proc.stdout), START_TIMEOUT_S)
        except (asyncio.IncompleteReadError, asyncio.TimeoutError, protocol.ProtocolError) as exc:
            await self.kill()
            raise WorkerCrashed(f"{self.module} did not start (exit status {self.proc.returncode})") from exc
        return self.hello

    @property
    def alive(self) -> bool:
        return self.proc is not None and self.proc.returncode is None

    async def call(self, message: dict, payload: bytes, timeout_s: float) -> tuple[dict, bytes]:
        assert self.proc is not None
        try:
            if not self.alive:
                raise ConnectionError
            self.proc.stdin.write(protocol.encode(message, payload))
            await self.proc.stdin.drain()
            return await asyncio.wait_for(protocol.read_frame(self.proc.stdout), timeout_s)
        except asyncio.TimeoutError:
            await self.kill()
            raise JobTimeout(f"the job ran past its time limit of {timeout_s:g} s") from None
        # uvloop raises RuntimeError (not BrokenPipeError) on a write to the closed pipe of a dead child
        except (asyncio.IncompleteReadError, ConnectionError, RuntimeError, protocol.ProtocolError):
            status = await self.kill()
            raise WorkerCrashed(f"the worker process died ({_describe_exit(status)})") from None

    async def kill(self) -> int | None:
        if self.proc is None:
            return None
        if self.proc.returncode is None:
            # os.kill, not proc.kill(): Popen's send_signal polls first and may reap a child that
            # just died, stealing its exit status from asyncio's watcher (which then reports 255)
            try:
                os.kill(self.proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        return await self.proc.wait()


def _describe_exit(status: int | None) -> str:
    if status is not None and status < 0:
        return f"killed by {signal.Signals(-status).name}"
    return f"exit status {status}"


@dataclass
class Job:
    message: dict
    payload: bytes = b""
    id: str = field(default_factory=lambda: uuid.uuid4().hex)  # unguessable: results are clients' data
    state: str = "queued"  # queued, running, done, failed
    attempts: int = 0
    created: float = field(default_factory=time.time)
    future: asyncio.Future = field(default_factory=lambda: asyncio.get_running_loop().create_future())


class ProcessPool:
    def __init__(self, module: str, size: int, queue_size: int, timeout_s: float,
                 env: dict[str, str] | None = None, on_result=None, wait_s: float | None = None):
        self.module, self.size, self.timeout_s, self.env = module, size, timeout_s, env
        # the longest a caller of run() waits: queueing, a crash, a fresh child and the retry
        self.wait_s = wait_s if wait_s is not None else 3 * timeout_s + 30
        self.queue: asyncio.Queue[Job] = asyncio.Queue(maxsize=queue_size)
        self.hello: dict = {}
        self.children: list[ChildProcess | None] = [None] * size
        self._tasks: list[asyncio.Task] = []
        self._on_result = on_result  # called with (job, seconds, reply) when a job finishes well
        self._ready = asyncio.Event()

    async def start(self, wait: bool = True) -> None:
        """wait: return once every child has started (and loaded what it loads first)."""
        self._tasks = [asyncio.create_task(self._supervise(i)) for i in range(self.size)]
        if wait:
            await self._ready.wait()

    @property
    def depth(self) -> int:
        return self.queue.qsize()

    @property
    def alive(self) -> int:
        """Children running now (a dead one counts until its replacement has started)."""
        return sum(1 for child in self.children if child is not None and child.alive)

    def submit(self, message: dict, payload: bytes = b"", job_id: str | None = None, attempts: int = 0) -> Job:
        """attempts: tries the job already had elsewhere (a pool that died while running it)."""
        job = Job(message, payload, attempts=attempts)
        if job_id is not None:
            job.id = job_id
        try:
            self.queue.put_nowait(job)
        except asyncio.QueueFull:
            raise QueueFull(f"{self.queue.maxsize} jobs already waiting") from None
        return job

    async def run(self, message: dict, payload: bytes = b"") -> tuple[dict, bytes]:
        job = self.submit(message, payload)
        done, _ = await asyncio.wait((job.future,), timeout=self.wait_s)
        if not done:
            # a job still queued is skipped by the slot that takes it; a running one ends at its time limit
            self._finish(job, PoolError(f"no answer within {self.wait_s:g} s"))
        return job.future.result()

    async def _spawn(self, index: int) -> ChildProcess:
        pause = RESPAWN_BACKOFF_S[0]
        while True:
            child = ChildProcess(self.module, self.env)
            try:
                self.hello = await child.start()
            except WorkerCrashed as exc:
                log.error("%s; trying again in %.0f s", exc, pause)
                await asyncio.sleep(pause)
                pause = min(pause * 2, RESPAWN_BACKOFF_S[1])
                continue
            self.children[index] = child
            if all(self.children):
                self._ready.set()
            return child

    async def _supervise(self, index: int) -> None:
        """Run slot `index`, and start it again should it ever fail: a slot that dies silently
        would leave its jobs waiting for ever."""
        while True:
            running: list[Job] = []
            try:
                await self._slot(index, running)
            except Exception:
                log.exception("%s slot %d failed; starting it again", self.module, index)
                for job in running:
                    self._finish(job, PoolError("the pool slot running this job failed"))
                child = self.children[index]
                if child is not None:
                    await child.kill()
                await asyncio.sleep(RESPAWN_BACKOFF_S[0])

    async def _next_job(self, child: ChildProcess) -> Job | None:
        """The next job, or None if the idle child died first."""
        get = asyncio.ensure_future(self.queue.get())
        died = asyncio.ensure_future(child.proc.wait())
        try:
            await asyncio.wait((get, died), return_when=asyncio.FIRST_COMPLETED)
        finally:
            died.cancel()
            if not get.done():
                get.cancel()
        return get.result() if get.done() and not get.cancelled() else None

    async def _slot(self, index: int, running: list[Job]) -> None:
        child = await self._spawn(index)
        while True:
            job = await self._next_job(child)
            if job is None:
                log.warning("%s child %s died while idle (%s); replacing it", self.module, child.pid,
                            _describe_exit(child.proc.returncode))
                child = await self._spawn(index)
                continue
            if job.future.done():  # its caller went away while it waited
                continue
            job.state = "running"
            running[:] = [job]
            while True:
                job.attempts += 1
                started = time.perf_counter()
                try:
                    reply = await child.call(job.message, job.payload, self.timeout_s)
                except JobTimeout as exc:
                    child = await self._spawn(index)
                    self._finish(job, exc)
                    break
                except WorkerCrashed as exc:
                    log.warning("%s on job %s (attempt %d)", exc, job.id, job.attempts)
                    child = await self._spawn(index)
                    if job.attempts >= 2:
                        self._finish(job, WorkerCrashed(f"{exc}, on this job twice: giving up"))
                        break
                    continue
                if self._on_result is not None:
                    self._on_result(job, time.perf_counter() - started, reply)
                self._finish(job, reply)
                break
            running.clear()

    @staticmethod
    def _finish(job: Job, outcome) -> None:
        if job.future.done():
            return
        failed = isinstance(outcome, BaseException)
        job.state = "failed" if failed else "done"
        if failed:
            job.future.set_exception(outcome)
            job.future.exception()  # retrieved: a job nobody waits for must not log "never retrieved"
        else:
            job.future.set_result(outcome)

    async def close(self) -> None:
        for task in self._tasks:
            task.cancel()
        await asyncio.gather(*self._tasks, return_exceptions=True)
        for child in self.children:
            if child is not None:
                await child.kill()
        while not self.queue.empty():
            job = self.queue.get_nowait()
            if not job.future.done():
                job.future.set_exception(PoolError("the pool shut down"))
                job.future.exception()
