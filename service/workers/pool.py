"""A bounded pool of child processes, each running `python -m <module>` and answering framed
requests on its stdin/stdout (see protocol.py and child.py).

Why processes: generation and rendering are CPU-bound Python or GL work; in a child they never
hold the event loop, a runaway job can be killed at its time limit, and a crash (a segfault in a
GL driver, the OOM killer) costs one child, which is replaced. A job whose child crashed is tried
once more on the fresh child, then failed with a clear error: a job that kills every process it
touches must not take the whole pool down one child at a time.

Each child is also bounded in memory (its RSS, watched from here: see ChildProcess; a job over it
is answered `too_large`, not retried), answers heartbeats (a pool whose every child is silent,
stopped or wedged, refuses jobs at once with Unavailable instead of queueing them behind it, and
a child silent as long as a job's time limit is replaced), and writes its temporary files in a
folder of its own that goes with it (scratch.py).

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

from . import memory, protocol, scratch
from .child import HEARTBEAT

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


class Unavailable(PoolError):
    """No child answers its heartbeats: the job is refused at once rather than queued behind a hung child."""


class MemoryExceeded(PoolError):
    """The child went over its memory limit and was killed: the job's own doing, never retried."""

    def __init__(self, limit_bytes: int, rss_bytes: int):
        super().__init__(f"{rss_bytes >> 20} MiB, over the limit of {limit_bytes >> 20} MiB")
        self.limit_bytes, self.rss_bytes = limit_bytes, rss_bytes


@dataclass(frozen=True)
class ChildLimits:
    memory_bytes: int = 0  # resident memory a child may reach before it is killed; 0: unbounded
    silent_s: float = 10.0  # a child with no heartbeat or reply for this long is not answering
    memory_poll_s: float = 0.05  # how often the child's RSS is read


class _EndOfStream(Exception):
    pass


_END = None  # what the reader queues once the child's stdout is closed


class ChildProcess:
    """One child, its pipes, its private temporary folder, and two watchers: a reader that takes
    heartbeats and replies off its stdout, and a watchdog of its resident memory.

    The memory limit is watched from this side rather than set in the child (RLIMIT_AS): an EGL
    context on llvmpipe, the JIT and the generator's 512 MiB thread stack map far more address
    space than they touch (a render worker that drew one 1024 px thumbnail maps 905 MB for
    228 MB resident), so an address-space limit either refuses normal jobs or bounds nothing;
    and a parent that did the killing knows why its child died, and can say so."""

    def __init__(self, module: str, env: dict[str, str] | None = None, limits: ChildLimits = ChildLimits()):
        self.module = module
        self.env = env
        self.limits = limits
        self.proc: asyncio.subprocess.Process | None = None
        self.hello: dict = {}
        self.folder: str | None = None
        self.last_answer = 0.0
        self.over_memory: int | None = None  # the RSS the watchdog killed it at
        self.busy = False  # a job was sent and its reply has not come
        self._replies: asyncio.Queue = asyncio.Queue()
        self._answered = asyncio.Event()
        self._watchers: list[asyncio.Task] = []

    @property
    def pid(self) -> int | None:
        return self.proc.pid if self.proc else None

    async def start(self) -> dict:
        self.folder = scratch.make()
        env = {**os.environ, **(self.env or {}), **scratch.env_for(self.folder)}
        self.proc = await asyncio.create_subprocess_exec(
            sys.executable, "-m", self.module,
            stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE, env=env,
        )
        # the watchdog runs from the first instant: loading libraries or a driver counts too
        self._watchers = [asyncio.create_task(self._read()), asyncio.create_task(self._watch_memory())]
        try:
            self.hello, _ = await asyncio.wait_for(self._reply(), START_TIMEOUT_S)
        except (_EndOfStream, asyncio.TimeoutError) as exc:
            await self.kill()
            raise WorkerCrashed(f"{self.module} did not start ({_describe_exit(self.proc.returncode)})") from exc
        return self.hello

    async def _read(self) -> None:
        try:
            while True:
                message, payload = await protocol.read_frame(self.proc.stdout)
                self.last_answer = time.monotonic()
                self._answered.set()
                if message != HEARTBEAT:
                    self._replies.put_nowait((message, payload))
        except (asyncio.IncompleteReadError, ConnectionError, protocol.ProtocolError, ValueError):
            self._replies.put_nowait(_END)  # gone, or writing garbage: either way no more answers

    async def _reply(self) -> tuple[dict, bytes]:
        item = await self._replies.get()
        if item is _END:
            self._replies.put_nowait(_END)  # for whoever waits next
            raise _EndOfStream
        return item

    async def _watch_memory(self) -> None:
        limit = self.limits.memory_bytes
        if not limit:
            return
        while self.proc.returncode is None:
            rss = memory.resident_bytes(self.proc.pid)
            if rss is None:
                return  # reaped meanwhile
            if rss > limit:
                self.over_memory = rss
                log.warning("%s child %s at %d MiB, over its limit of %d MiB: killed", self.module,
                            self.proc.pid, rss >> 20, limit >> 20)
                _sigkill(self.proc.pid)
                return
            await asyncio.sleep(self.limits.memory_poll_s)

    @property
    def alive(self) -> bool:
        return self.proc is not None and self.proc.returncode is None

    @property
    def answering(self) -> bool:
        """Alive, and heard from (a heartbeat or a reply) within the silence deadline; or busy
        with a job and not stopped. A job that holds the GIL in C delays the heartbeat thread
        (compiling a complete standard_surface on llvmpipe: 4.1 s without one, measured): such a
        child is at work, bounded by the job's time limit, not hung. Stopped (SIGSTOP, a
        debugger) it answers nothing and is not."""
        if not self.alive:
            return False
        if time.monotonic() - self.last_answer <= self.limits.silent_s:
            return True
        return self.busy and not memory.stopped(self.proc.pid)

    async def wait_answering(self, timeout_s: float) -> bool:
        """Wait until the child is heard from again; False if it is not within `timeout_s`."""
        self._answered.clear()
        try:
            await asyncio.wait_for(self._answered.wait(), timeout_s)
        except asyncio.TimeoutError:
            return False
        return self.alive

    async def wait_silent(self) -> None:
        """Return once the child has been silent past the deadline."""
        while self.answering:
            await asyncio.sleep(max(self.last_answer + self.limits.silent_s - time.monotonic(), 0.1) + 0.01)

    async def call(self, message: dict, payload: bytes, timeout_s: float) -> tuple[dict, bytes]:
        assert self.proc is not None
        try:
            if not self.alive:
                raise ConnectionError
            self.busy = True
            self.proc.stdin.write(protocol.encode(message, payload))
            # the limit covers the write too: a job larger than the pipe (a usdz upload) waits on a
            # hung child to read it, and that child must be killed at the limit like any other
            async with asyncio.timeout(timeout_s):
                await self.proc.stdin.drain()
                return await self._reply()
        except asyncio.TimeoutError:
            await self.kill()
            raise JobTimeout(f"the job ran past its time limit of {timeout_s:g} s") from None
        # uvloop raises RuntimeError (not BrokenPipeError) on a write to the closed pipe of a dead child
        except (_EndOfStream, ConnectionError, RuntimeError):
            status = await self.kill()
            if self.over_memory is not None:
                raise MemoryExceeded(self.limits.memory_bytes, self.over_memory) from None
            raise WorkerCrashed(f"the worker process died ({_describe_exit(status)})") from None
        finally:
            self.busy = False

    async def kill(self) -> int | None:
        """Kill (if still running), reap, and remove the child's temporary folder."""
        if self.proc is None:
            return None
        if self.proc.returncode is None:
            _sigkill(self.proc.pid)
        status = await self.proc.wait()
        for task in self._watchers:
            task.cancel()
        if self.folder is not None:
            folder, self.folder = self.folder, None
            await asyncio.to_thread(scratch.remove, folder)
        return status


def _sigkill(pid: int) -> None:
    # os.kill, not proc.kill(): Popen's send_signal polls first and may reap a child that just
    # died, stealing its exit status from asyncio's watcher (which then reports 255)
    try:
        os.kill(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def _describe_exit(status: int | None) -> str:
    if status is not None and status < 0:
        return f"killed by {signal.Signals(-status).name}"
    return f"exit status {status}"


def too_large(exc: MemoryExceeded, name: str) -> dict:
    """The error reply of a job whose child went over its memory limit."""
    return {"code": "too_large", "where": None,
            "message": f"the job needed more memory than a {name} process may use: {exc}"}


@dataclass
class Job:
    message: dict
    payload: bytes = b""
    id: str = field(default_factory=lambda: uuid.uuid4().hex)  # unguessable: results are clients' data
    state: str = "queued"  # queued, running, done, failed
    attempts: int = 0
    created: float = field(default_factory=time.time)
    future: asyncio.Future = field(default_factory=lambda: asyncio.get_running_loop().create_future())

    def forget_request(self) -> None:
        """A job that is over is kept for its outcome alone (the render pool keeps jobs for polling,
        for minutes): its request, which may carry a client's usdz package of megabytes, is never
        needed again."""
        self.message, self.payload = {}, b""


class ProcessPool:
    def __init__(self, module: str, size: int, queue_size: int, timeout_s: float,
                 env: dict[str, str] | None = None, on_result=None, wait_s: float | None = None,
                 limits: ChildLimits = ChildLimits(), name: str | None = None):
        self.module, self.size, self.timeout_s, self.env, self.limits = module, size, timeout_s, env, limits
        self.name = name or module.rsplit(".", 1)[-1]  # what messages call a child: "generator", "render"
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
        dead = await asyncio.to_thread(scratch.sweep)  # what children of killed pools left behind
        if dead:
            log.info("removed the temporary folders of %d processes no longer running", len(set(dead)))
        self._tasks = [asyncio.create_task(self._supervise(i)) for i in range(self.size)]
        self._tasks.append(asyncio.create_task(self._refuse_while_hung()))
        if wait:
            await self._ready.wait()

    @property
    def depth(self) -> int:
        return self.queue.qsize()

    @property
    def alive(self) -> int:
        """Children running now (a dead one counts until its replacement has started)."""
        return sum(1 for child in self.children if child is not None and child.alive)

    @property
    def answering(self) -> int:
        """Children heard from within the silence deadline."""
        return sum(1 for child in self.children if child is not None and child.answering)

    @property
    def hung(self) -> bool:
        """Every slot holds a running child and none of them answers: nothing queued would be
        taken before a time limit kills one (a child that is starting or being replaced is not hung)."""
        return bool(self.children) and all(child is not None and child.alive and not child.answering
                                           for child in self.children)

    def _unavailable(self) -> Unavailable:
        return Unavailable(f"no {self.name} process answered within {self.limits.silent_s:g} s")

    def submit(self, message: dict, payload: bytes = b"", job_id: str | None = None, attempts: int = 0) -> Job:
        """attempts: tries the job already had elsewhere (a pool that died while running it)."""
        if self.hung:
            raise self._unavailable()
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

    async def _refuse_while_hung(self) -> None:
        """Fail what waits in the queue once every child has gone silent, so that callers hear
        503 now instead of a time-out later (submit refuses new jobs for the same reason)."""
        pause = min(0.25, self.limits.silent_s / 4)
        while True:
            await asyncio.sleep(pause)
            if self.hung and not self.queue.empty():
                exc = self._unavailable()
                while not self.queue.empty():
                    self._finish(self.queue.get_nowait(), exc)

    async def _spawn(self, index: int) -> ChildProcess:
        pause = RESPAWN_BACKOFF_S[0]
        while True:
            child = ChildProcess(self.module, self.env, self.limits)
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
        """The next job, taken only while the child answers; None if the idle child died, or
        stayed silent (stopped, wedged) as long as a job's time limit, and was killed for it."""
        while True:
            if not child.answering and not await child.wait_answering(self.timeout_s):
                await child.kill()
                return None
            get = asyncio.ensure_future(self.queue.get())
            died = asyncio.ensure_future(child.proc.wait())
            silent = asyncio.ensure_future(child.wait_silent())
            try:
                await asyncio.wait((get, died, silent), return_when=asyncio.FIRST_COMPLETED)
            finally:
                died.cancel()
                silent.cancel()
                if not get.done():
                    get.cancel()
            if get.done() and not get.cancelled():
                return get.result()
            if not child.alive:
                return None

    async def _slot(self, index: int, running: list[Job]) -> None:
        child = await self._spawn(index)
        while True:
            job = await self._next_job(child)
            if job is None:
                log.warning("%s child %s died or went silent while idle (%s); replacing it", self.module,
                            child.pid, _describe_exit(await child.kill()))
                child = await self._spawn(index)
                continue
            if job.future.done():  # its caller went away while it waited
                job.forget_request()
                continue
            job.state = "running"
            running[:] = [job]
            while True:
                job.attempts += 1
                started = time.perf_counter()
                try:
                    reply = await child.call(job.message, job.payload, self.timeout_s)
                except JobTimeout as exc:
                    self._finish(job, exc)  # answered before the replacement has loaded
                    child = await self._spawn(index)
                    break
                except MemoryExceeded as exc:
                    # the job's own doing: answered as too large, not tried again on a fresh child
                    self._finish(job, ({"error": too_large(exc, self.name)}, b""))
                    child = await self._spawn(index)
                    break
                except WorkerCrashed as exc:
                    log.warning("%s on job %s (attempt %d)", exc, job.id, job.attempts)
                    if job.attempts >= 2:
                        self._finish(job, WorkerCrashed(f"{exc}, on this job twice: giving up"))
                        child = await self._spawn(index)
                        break
                    child = await self._spawn(index)
                    continue
                if self._on_result is not None:
                    self._on_result(job, time.perf_counter() - started, reply)
                self._finish(job, reply)
                break
            running.clear()

    @staticmethod
    def _finish(job: Job, outcome) -> None:
        job.forget_request()
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
