"""Celery on Redis, for render workers on several machines. The API sends tasks by name; the
task itself is registered only in `shadergen worker` processes (register_tasks)."""
import base64
import os

import redis
from celery import Celery
from celery.signals import worker_process_init, worker_process_shutdown

from .celery_child import ProcessGuard

TASK = "shadergen.render_thumbnail"
QUEUE = "shadergen-render"
ATTEMPTS_KEY = "shadergen:attempts:"
ATTEMPTS_TTL_S = 3600


def make_celery(settings) -> Celery:
    app = Celery("shadergen", broker=settings.broker, backend=settings.broker)
    app.conf.update(
        task_serializer="json", result_serializer="json", accept_content=["json"],
        task_default_queue=QUEUE, task_track_started=True, result_expires=3600,
        # a job is acknowledged only once done, and put back when its worker process dies, so a
        # crash costs one attempt, not the job; render_thumbnail bounds the attempts at two
        task_acks_late=True, task_reject_on_worker_lost=True, worker_prefetch_multiplier=1,
        task_time_limit=settings.render_timeout_s,
        broker_connection_retry_on_startup=True,
        broker_transport_options=redelivery_options(settings.render_timeout_s),
    )
    return app


def redelivery_options(render_timeout_s: float) -> dict:
    """When a whole worker dies (its machine or container gone, not one of its processes), the jobs
    it held are acknowledged by no one; Redis gives them to another worker once they are older than
    the visibility timeout. No job runs past its time limit, so twice that limit only ever catches
    abandoned jobs (kombu's default, an hour, would leave the job waiting that long); every worker
    looks for them every few seconds."""
    return {"visibility_timeout": max(2 * render_timeout_s, 10.0),
            "unacked_restore_interval": 5, "unacked_restore_throttle": 1}


def register_tasks(app: Celery, settings, processes: int) -> None:
    attempts = redis.Redis.from_url(settings.broker)
    renderer = None  # one per worker process, made on its first job: EGL contexts do not survive fork
    guard = ProcessGuard(attempts, settings)
    worker_process_init.connect(lambda **_: guard.start(), weak=False)
    worker_process_shutdown.connect(lambda **_: guard.stop(), weak=False)

    @app.task(name=TASK, bind=True)
    def render_thumbnail(task, request: dict) -> dict:
        nonlocal renderer
        key = ATTEMPTS_KEY + task.request.id
        attempt = attempts.incr(key)
        attempts.expire(key, ATTEMPTS_TTL_S)
        too_large = guard.over_limit_before(task.request.id) if attempt > 1 else None
        if too_large is not None:  # its last attempt went over the memory limit: not tried again
            return {"error": {"code": "too_large", "message": too_large, "where": None}}
        if attempt > 2:
            return {"error": {"code": "worker_crashed",
                              "message": "render worker died on this job twice; giving up", "where": None}}
        task.update_state(state="STARTED", meta={"pid": os.getpid(), "attempt": attempt})
        from ..workers.render_worker import programs_kept, render

        if renderer is None:
            from shadergen.render import Renderer
            from shadergen.render.worker import lp_threads_for

            renderer = Renderer(texture_roots=settings.texture_roots, search_paths=settings.texture_roots,
                                max_programs=programs_kept(settings), lp_threads=lp_threads_for(processes))

        guard.begin(task.request.id)
        try:
            reply, png = render(renderer, request)
        finally:
            guard.end()
        if "error" in reply:
            return reply
        return {**reply, "png": base64.b64encode(png).decode(), "attempt": attempt}
