"""Celery render jobs routed by topology (issue 23): each `shadergen worker` consumes the shared
queue and a queue of its own, which it announces on Redis while its main process lives (a key
renewed every heartbeat, expiring `ready_deadline_s` after the last); the API sends a thumbnail to
the queue of the worker that holds its program (consistent hashing over the announced queues,
service/workers/routing.py), so adding a worker moves only its share. A job whose worker stopped
announcing before the job finished is sent again, to the next worker on the ring: a worker lost
with its machine loses none of its jobs."""
import json
import math
import os
import socket
import threading

from ..workers.routing import HashRing, route_key
from .celery_app import QUEUE

QUEUES_KEY = "shadergen:render-queues"  # every queue announced, until seen expired
ALIVE_KEY = "shadergen:render-queue-alive:"  # + a queue: present while its worker announces it


def worker_queue(name: str | None = None) -> str:
    """A worker's own queue: named by `name`, else by its host and process (never reused)."""
    return f"{QUEUE}.{name or f'{socket.gethostname()}-{os.getpid()}'}"


class QueueAnnouncer:
    """The worker side: a thread of the worker's main process (prefork children do not inherit
    it) that keeps its queue announced."""

    def __init__(self, redis_client, queue: str, settings):
        self.redis, self.queue = redis_client, queue
        self.heartbeat_s = settings.heartbeat_s
        self.ttl_s = max(1, math.ceil(settings.ready_deadline_s))
        self._stop = threading.Event()

    def start(self) -> None:
        threading.Thread(target=self._beat, name="queue-announcer", daemon=True).start()

    def stop(self) -> None:
        self._stop.set()
        try:
            self.redis.delete(ALIVE_KEY + self.queue)
        except Exception:  # Redis away: the key expires on its own
            pass

    def _beat(self) -> None:
        while not self._stop.is_set():
            try:
                with self.redis.pipeline() as pipe:
                    pipe.set(ALIVE_KEY + self.queue, "1", ex=self.ttl_s).sadd(QUEUES_KEY, self.queue).execute()
            except Exception:  # Redis away: the API cannot route to anyone meanwhile either
                pass
            self._stop.wait(self.heartbeat_s)


async def live_queues(redis_client) -> list[str]:
    """The API side: the queues whose workers announce them now (expired ones leave the set)."""
    names = await redis_client.smembers(QUEUES_KEY)
    if not names:
        return []
    alive = await redis_client.mget([ALIVE_KEY.encode() + name for name in names])
    dead = [name for name, value in zip(names, alive) if value is None]
    if dead:
        await redis_client.srem(QUEUES_KEY, *dead)
    return sorted(name.decode() for name, value in zip(names, alive) if value is not None)


def queue_for(request: dict, queues: list[str]) -> str:
    """The live worker queue that holds the request's program, else the shared queue."""
    return HashRing(queues).order(route_key(request))[0] if queues else QUEUE


def route_record(task_id: str, queue: str, tries: int = 0) -> str:
    """What the API keeps of a job: the task now running it, the queue it was sent to, and the
    attempts earlier tasks of the job made (its `attempts` counts them too)."""
    return json.dumps({"task": task_id, "queue": queue, "tries": tries})
