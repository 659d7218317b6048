"""What each Celery prefork process of `shadergen worker` sets up for itself when it starts: a
private temporary folder (see service/workers/scratch.py; the folders of processes no longer
running are removed first) and a watchdog of its own resident memory.

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
import os
import signal
import tempfile
import threading
import time

from ..workers import memory, scratch
from ..workers.pool import MemoryExceeded, too_large

log = logging.getLogger(__name__)

TOO_LARGE_KEY = "shadergen:too_large:"
TOO_LARGE_TTL_S = 3600


class ProcessGuard:
    def __init__(self, redis_client, memory_bytes: int, poll_s: float):
        self.redis, self.memory_bytes, self.poll_s = redis_client, memory_bytes, poll_s
        self.folder: str | None = None
        self.task_id: str | None = None  # the task running now, named in the record if it goes over

    def start(self) -> None:
        """In the prefork process, before its first task."""
        scratch.sweep()
        self.folder = scratch.make()
        os.environ.update(scratch.env_for(self.folder))
        tempfile.tempdir = self.folder  # tempfile read TMPDIR once already, in the parent
        if self.memory_bytes:
            threading.Thread(target=self._watch, name="memory-watchdog", daemon=True).start()

    def stop(self) -> None:
        scratch.remove(self.folder)

    def _watch(self) -> None:
        while True:
            rss = memory.resident_bytes()
            if rss is not None and rss > self.memory_bytes:
                self._die(rss)
            time.sleep(self.poll_s)

    def _die(self, rss: int) -> None:
        message = too_large(MemoryExceeded(self.memory_bytes, rss), "render")["message"]
        log.warning("render process %s: %s; killed", os.getpid(), message)
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
