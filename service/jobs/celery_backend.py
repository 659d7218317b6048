"""The Celery back end, API side: sends render tasks by name over Redis and reads their results.
Celery's client calls block on Redis, so they run in threads, off the event loop. A broker that
cannot be reached is a JobError ("unavailable": 503 with Retry-After), never a server error.
Each job goes to the queue of the worker that holds its program, and again to another when that
worker is gone before the job is done (celery_routing.py)."""
import asyncio
import base64
import json
import time
import uuid
from contextlib import contextmanager

import redis.asyncio
from celery.result import AsyncResult
from kombu.exceptions import OperationalError

from ..metrics import PROGRAMS
from . import JobBackend, JobError, JobState, RenderResult
from .celery_app import QUEUE, TASK, make_celery
from .celery_child import ALIVE_KEY, PROCESSES_KEY
from .celery_routing import live_queues, queue_for, route_record

JOB_KEY = "shadergen:job:"  # + a job id: its route (celery_routing.route_record)
REQUEST_KEY = "shadergen:job-request:"  # + a job id: its request, to send again if its worker is lost
JOB_TTL_S = 3600
POLL_S = (0.01, 0.25)  # first and longest pause between polls of a job being waited for


@contextmanager
def broker_errors():
    try:
        yield
    except (redis.RedisError, OperationalError, OSError) as exc:
        raise JobError("unavailable", f"the job broker is not reachable: {type(exc).__name__}: {exc}") from None


class CeleryJobs(JobBackend):
    name = "celery"

    def __init__(self, settings):
        self.app = make_celery(settings)
        self.redis = redis.asyncio.Redis.from_url(settings.broker)
        self.max_depth = settings.render_queue_size
        # queueing, a lost worker's job coming back (twice the time limit), and the render itself
        self.wait_s = settings.render_timeout_s * 4
        self.deadline_s = settings.ready_deadline_s

    async def depth(self) -> int:
        with broker_errors():
            queues = [QUEUE, *await live_queues(self.redis)]
            return sum([await self.redis.llen(queue) for queue in queues])

    async def answering_processes(self) -> int:
        """Render processes whose heartbeat has not expired (celery_child.py); the names of the
        others are dropped from the set."""
        names = await self.redis.smembers(PROCESSES_KEY)
        if not names:
            return 0
        alive = await self.redis.mget([ALIVE_KEY.encode() + name for name in names])
        dead = [name for name, value in zip(names, alive) if value is None]
        if dead:
            await self.redis.srem(PROCESSES_KEY, *dead)
        return len(names) - len(dead)

    async def health(self) -> tuple[bool, str]:
        """Ready while the broker answers and some render process sent a heartbeat: jobs still
        queue without one (a worker may be on its way), but nothing would render them now."""
        try:
            with broker_errors():
                depth = await self.depth()
                answering = await self.answering_processes()
        except JobError as exc:
            return False, exc.message
        return answering > 0, (f"{answering} render processes answering within {self.deadline_s:g} s, "
                               f"{depth} jobs queued")

    async def submit(self, request: dict) -> str:
        if await self.depth() >= self.max_depth:
            raise JobError("queue_full", f"render queue full: {self.max_depth} jobs already waiting")
        job_id = uuid.uuid4().hex
        with broker_errors():
            queue = queue_for(request, await live_queues(self.redis))
            # known ids, so that an unknown one is a 404 and not Celery's eternal PENDING
            await self.redis.set(REQUEST_KEY + job_id, json.dumps(request), ex=JOB_TTL_S)
            await self.redis.set(JOB_KEY + job_id, route_record(job_id, queue), ex=JOB_TTL_S)
            await asyncio.to_thread(self.app.send_task, TASK, args=[request], task_id=job_id, queue=queue)
        return job_id

    async def _rerouted(self, job_id: str, route: dict, attempts: int) -> dict:
        """The job sent again, under a new task, if the worker whose queue it was sent to stopped
        announcing it: to the next worker on the ring, or the shared queue. `attempts`: what the
        lost task made of it (none while it was queued)."""
        queues = await live_queues(self.redis)
        if route["queue"] == QUEUE or route["queue"] in queues:
            return route
        raw = await self.redis.get(REQUEST_KEY + job_id)
        if raw is None:
            return route
        request = json.loads(raw)
        task_id, queue = uuid.uuid4().hex, queue_for(request, queues)
        await asyncio.to_thread(self.app.send_task, TASK, args=[request], task_id=task_id, queue=queue)
        tries = route.get("tries", 0) + attempts
        await self.redis.set(JOB_KEY + job_id, route_record(task_id, queue, tries), ex=JOB_TTL_S)
        return {"task": task_id, "queue": queue, "tries": tries}

    async def _state(self, job_id: str) -> JobState | None:
        raw = await self.redis.get(JOB_KEY + job_id)
        if raw is None:
            return None
        route = json.loads(raw)
        state = await asyncio.to_thread(self._read, route["task"])
        if state.state in ("queued", "running"):
            rerouted = await self._rerouted(job_id, route, state.attempts)
            if rerouted is not route:
                return JobState(job_id, "queued", attempts=rerouted["tries"])
        state.id = job_id
        state.attempts += route.get("tries", 0)
        return state

    def _read(self, job_id: str) -> JobState:
        result = AsyncResult(job_id, app=self.app)
        state, value = result.state, result.result
        if state in ("PENDING", "RECEIVED"):
            return JobState(job_id, "queued")
        if state in ("STARTED", "RETRY"):
            attempts = value.get("attempt", 1) if isinstance(value, dict) else 1
            return JobState(job_id, "running", attempts=attempts)
        if state == "SUCCESS":
            if "error" in value:
                return JobState(job_id, "failed", value["error"])
            result = RenderResult(base64.b64decode(value["png"]), value.get("timings_ms", {}),
                                  value.get("warnings", []), value.get("program_reused"))
            return JobState(job_id, "done", result=result, attempts=value.get("attempt", 1))
        code = "timeout" if type(value).__name__ == "TimeLimitExceeded" else "worker_crashed"
        return JobState(job_id, "failed", {"code": code, "message": f"render failed: {value!r}", "where": None})

    async def status(self, job_id: str) -> JobState | None:
        with broker_errors():
            return await self._state(job_id)

    async def render(self, request: dict) -> RenderResult:
        job_id = await self.submit(request)
        deadline = time.monotonic() + self.wait_s
        pause = POLL_S[0]
        while time.monotonic() < deadline:
            with broker_errors():
                state = await self._state(job_id)
            if state is None:  # expired meanwhile
                raise JobError("unavailable", f"job {job_id} was forgotten by the broker")
            if state.state == "done":
                # Celery workers are not scraped (they may be on other machines): their program
                # cache is counted here, where the result arrives
                if state.result.program_reused is not None:
                    PROGRAMS.labels("reused" if state.result.program_reused else "compiled").inc()
                return state.result
            if state.state == "failed":
                raise JobError(**state.error)
            await asyncio.sleep(pause)
            pause = min(pause * 2, POLL_S[1])
        raise JobError("timeout", f"no render worker finished the job within {self.wait_s:g} s")

    async def close(self) -> None:
        await self.redis.aclose()
