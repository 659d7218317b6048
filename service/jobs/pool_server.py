"""The local render pool: M render-worker processes behind one bounded queue, served on a Unix
socket so that every API worker process of `shadergen serve` shares the same pool and the same
job table (an async job submitted through one API worker can be polled through another).

Run as `python -m service.jobs.pool_server SOCKET [--restarted]`; settings come from SHADERGEN_*
variables. `--restarted`: a supervisor started it again after the last one died; the API workers
are submitting the jobs that died with it again, so for a grace period an unknown job id is
"unavailable, try again" (503) rather than "no such job" (404).

A submit that waits for its render is answered when the render ends, seconds later; meanwhile the
connection carries a heartbeat frame every SHADERGEN_HEARTBEAT_S, so that the API worker can tell
a pool that is rendering from one that is stopped or wedged (whose socket still accepts), and
answer its client 503 within the readiness deadline instead of waiting out the job's."""
import asyncio
import logging
import os
import signal
import sys
import time

from ..config import get_settings
from ..metrics import PROGRAMS, RENDER_SECONDS
from ..workers import protocol
from ..workers.child import HEARTBEAT
from ..workers.pool import Job, JobTimeout, PoolError, ProcessPool, QueueFull, Unavailable, WorkerCrashed
from ..workers.routing import RoutedPools

log = logging.getLogger("service.render_pool")

JOB_TTL_S = 600.0  # finished async jobs (and their PNG) are kept this long for polling
MAX_JOBS = 1024
RESUBMIT_GRACE_S = 10.0


def _error_of(exc: BaseException) -> dict:
    code = "timeout" if isinstance(exc, JobTimeout) else "worker_crashed" if isinstance(exc, WorkerCrashed) \
        else "unavailable"
    return {"code": code, "message": f"render job failed: {exc}", "where": None}


class PoolServer:
    def __init__(self, pool: ProcessPool, restarted: bool = False, heartbeat_s: float = 1.0):
        self.pool = pool
        self.heartbeat_s = heartbeat_s
        self.jobs: dict[str, Job] = {}
        self.grace_until = time.monotonic() + RESUBMIT_GRACE_S if restarted else 0.0

    def _forget_old(self) -> None:
        cutoff = time.time() - JOB_TTL_S
        for job_id in [i for i, j in self.jobs.items() if j.state in ("done", "failed") and j.created < cutoff]:
            del self.jobs[job_id]
        while len(self.jobs) > MAX_JOBS:  # oldest first: dicts keep insertion order
            del self.jobs[next(iter(self.jobs))]

    @staticmethod
    def _outcome(job: Job) -> tuple[dict, bytes]:
        """The reply for a job: its state, and the PNG when done."""
        head = {"id": job.id, "state": job.state, "attempts": job.attempts}
        if job.state == "failed":
            return {**head, "error": _error_of(job.future.exception())}, b""
        if job.state == "done":
            reply, png = job.future.result()
            if "error" in reply:  # the renderer refused the material: a failed job, not a done one
                return {**head, "state": "failed", "error": reply["error"]}, b""
            return {**head, "timings_ms": reply.get("timings_ms", {}), "warnings": reply.get("warnings", [])}, png
        return head, b""

    async def handle(self, message: dict) -> tuple[dict, bytes]:
        op = message.get("op")
        if op == "depth":
            return {"depth": self.pool.depth, "workers": self.pool.size, "alive": self.pool.alive,
                    "answering": self.pool.answering, "deadline_s": self.pool.limits.silent_s}, b""
        if op == "status":
            job = self.jobs.get(message.get("id", ""))
            if job is not None:
                return self._outcome(job)
            if time.monotonic() < self.grace_until:
                return {"error": {"code": "unavailable", "message": "the render pool restarted; its jobs are "
                                  "being submitted again", "where": None}}, b""
            return {"state": "unknown"}, b""
        if op == "submit":
            # the client names the job, so that after a restart of this pool it can submit the
            # same job again under the same id; a job submitted twice to one pool runs once
            job = self.jobs.get(message["id"])
            if job is None:
                self._forget_old()
                try:
                    job = self.pool.submit({"op": "render", **message["request"]}, job_id=message["id"],
                                           attempts=message.get("attempts", 0))
                except QueueFull as exc:
                    return {"error": {"code": "queue_full", "message": f"render queue full: {exc}"}}, b""
                except Unavailable as exc:
                    return {"error": {"code": "unavailable", "message": f"render refused: {exc}"}}, b""
                self.jobs[job.id] = job
            if not message.get("wait"):
                return {"id": job.id, "state": job.state}, b""
            try:
                await asyncio.shield(job.future)
            except PoolError:
                pass
            return self._outcome(job)
        return {"error": {"code": "invalid_request", "message": f"unknown op {op!r}"}}, b""

    async def serve_connection(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        answer = None
        try:
            message, _ = await protocol.read_frame(reader)
            answer = asyncio.ensure_future(self.handle(message))
            while not (await asyncio.wait((answer,), timeout=self.heartbeat_s))[0]:
                writer.write(protocol.encode(HEARTBEAT))
                await writer.drain()
            reply, payload = answer.result()
            writer.write(protocol.encode(reply, payload))
            await writer.drain()
        except (asyncio.IncompleteReadError, ConnectionError):
            pass  # the API worker went away (its client disconnected): the job still completes
        finally:
            if answer is not None:
                answer.cancel()  # a waiting submit stops waiting; the job is shielded and runs on
            writer.close()


def observe_render(job, seconds: float, reply) -> None:
    RENDER_SECONDS.observe(seconds)
    head = reply[0] if isinstance(reply, tuple) else {}
    if "program_reused" in head:
        PROGRAMS.labels("reused" if head["program_reused"] else "compiled").inc()


async def serve(socket_path: str, restarted: bool) -> None:
    settings = get_settings()
    # by topology: a worker per queue, each job to the worker holding its program (routing.py);
    # shared: one queue that the first free worker takes from
    pool_class = RoutedPools if settings.render_routing == "topology" else ProcessPool
    pool = pool_class("service.workers.render_worker", size=settings.render_workers,
                      queue_size=settings.render_queue_size, timeout_s=settings.render_timeout_s,
                      on_result=observe_render, limits=settings.child_limits(settings.render_memory_mib),
                      name="render")
    await pool.start(wait=False)
    server = PoolServer(pool, restarted, settings.heartbeat_s)
    unix = await asyncio.start_unix_server(server.serve_connection, path=socket_path)
    os.chmod(socket_path, 0o600)  # only this user's processes may submit renders
    log.info("render pool: %d workers on %s", pool.size, socket_path)
    stop = asyncio.Event()
    asyncio.get_running_loop().add_signal_handler(signal.SIGTERM, stop.set)
    watchdog = asyncio.create_task(_stop_when_orphaned(stop))
    try:
        async with unix:
            await stop.wait()
    finally:
        watchdog.cancel()
        await pool.close()  # kills the render workers: none outlives the pool


async def _stop_when_orphaned(stop: asyncio.Event) -> None:
    """A pool whose parent died (killed without the chance to stop us) must not live on."""
    parent = os.getppid()
    while os.getppid() == parent:
        await asyncio.sleep(1.0)
    stop.set()


def main() -> None:
    logging.basicConfig(level=logging.INFO, format="%(name)s: %(message)s")
    try:
        asyncio.run(serve(sys.argv[1], "--restarted" in sys.argv[2:]))
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
