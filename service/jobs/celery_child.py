"""What each Celery prefork process of `shadergen worker` sets up for itself when it starts: a
private temporary folder (see service/workers/scratch.py; the folders of processes no longer
running are removed first), heartbeats on Redis, and a watchdog of its own resident memory.

Heartbeats: a key per process that expires unless renewed, `ready_deadline_s` after the last
beat while idle, and only at the job's time limit while a job runs (a job holding the GIL in C
delays the beats; Celery kills a job at its time limit anyway), and the process's name in a set
that the API reads for its readiness (celery_backend.answering_processes).

Celery's prefork pool has no per-process memory bound that acts during a task
(worker_max_memory_per_child replaces a process only after its task ends), so the watchdog is a
thread of the process: past the limit it records on Redis that this task went over it, removes
the folder and kills its own process. Celery replaces the process and, the task being
acknowledged late, hands it out again; the second attempt finds the record and answers
`too_large` at once instead of running again. Being a thread, it needs the GIL: a C call that
allocates without releasing it is seen when it returns (the local pool's watchdog is in another
process and has no such blind spot)."""
import json
import logging
import math
import os
import signal
import socket
import tempfile
import threading
import time

from ..workers import memory, scratch
from ..workers.pool import MemoryExceeded, too_large

log = logging.getLogger(__name__)

TOO_LARGE_KEY = "shadergen:too_large:"
TOO_LARGE_TTL_S = 3600
ALIVE_KEY = "shadergen:render-alive:"  # + a process's name: present while it beats
PROCESSES_KEY = "shadergen:render-processes"  # the names of every process that ever beat, until seen dead


def process_name(pid: int) -> str:
    return f"{socket.gethostname()}:{pid}"


class ProcessGuard:
    def __init__(self, redis_client, settings):
        self.redis = redis_client
        self.memory_bytes, self.poll_s = settings.render_memory_mib << 20, settings.memory_poll_s
        self.heartbeat_s = settings.heartbeat_s
        self.idle_ttl_s = max(1, math.ceil(settings.ready_deadline_s))
        self.busy_ttl_s = math.ceil(settings.render_timeout_s + settings.ready_deadline_s)
        self.folder: str | None = None
        self.name = ""
        self.task_id: str | None = None  # the task running now, named in the record if it goes over

    def start(self) -> None:
        """In the prefork process, before its first task."""
        dead = scratch.sweep()
        self.folder = scratch.make()
        os.environ.update(scratch.env_for(self.folder))
        tempfile.tempdir = self.folder  # tempfile read TMPDIR once already, in the parent
        self.name = process_name(os.getpid())
        # a process killed mid-job left a heartbeat that lasts to the job's time limit: not alive
        self._forget(*(process_name(pid) for pid in dead))
        threading.Thread(target=self._watch, name="process-guard", daemon=True).start()

    def stop(self) -> None:
        scratch.remove(self.folder)
        self._forget(self.name)

    def _forget(self, *names: str) -> None:
        if not names:
            return
        try:
            self.redis.delete(*(ALIVE_KEY + name for name in names))
        except Exception:  # Redis away: the keys expire on their own
            pass

    def begin(self, task_id: str) -> None:
        self.task_id = task_id
        self.beat()

    def end(self) -> None:
        self.task_id = None
        self.beat()

    def beat(self) -> None:
        ttl_s = self.busy_ttl_s if self.task_id else self.idle_ttl_s
        try:
            with self.redis.pipeline() as pipe:
                pipe.set(ALIVE_KEY + self.name, self.task_id or "", ex=ttl_s).sadd(PROCESSES_KEY, self.name).execute()
        except Exception:  # Redis away: readiness says the broker is down anyway
            pass

    def _watch(self) -> None:
        last_beat = 0.0
        while True:
            rss = memory.resident_bytes() if self.memory_bytes else None
            if rss is not None and rss > self.memory_bytes:
                self._die(rss)
            if time.monotonic() - last_beat >= self.heartbeat_s:
                self.beat()
                last_beat = time.monotonic()
            time.sleep(min(self.poll_s, self.heartbeat_s))

    def _die(self, rss: int) -> None:
        message = too_large(MemoryExceeded(self.memory_bytes, rss), "render")["message"]
        log.warning("render process %s: %s; killed", os.getpid(), message)
        self._forget(self.name)
        if self.task_id is not None:
            try:
                self.redis.set(TOO_LARGE_KEY + self.task_id, json.dumps(message), ex=TOO_LARGE_TTL_S)
            except Exception:  # Redis away: the task is tried again, as after a crash
                log.exception("could not record the task over its memory limit")
        scratch.remove(self.folder)
        os.kill(os.getpid(), signal.SIGKILL)

    def over_limit_before(self, task_id: str) -> str | None:
        """The message recorded when an earlier attempt of this task went over the limit."""
        recorded = self.redis.get(TOO_LARGE_KEY + task_id)
        return json.loads(recorded) if recorded else None
