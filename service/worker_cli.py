"""`shadergen worker`: a Celery render worker for SHADERGEN_BROKER=redis://... Each of its
processes creates its own EGL context on its first job (prefork children, after the fork)."""
import sys

from .config import get_settings


def add_arguments(parser) -> None:
    parser.add_argument("--concurrency", type=int, default=None, metavar="N",
                        help="render processes (default: SHADERGEN_RENDER_WORKERS or 1)")
    parser.add_argument("--loglevel", default="info", help="Celery log level: debug, info, warning or error")
    parser.add_argument("--name", help="this worker's own queue is shadergen-render.NAME, which thumbnails of the "
                                       "topologies it is given are routed to (default: host and process id)")


def run(args) -> int:
    settings = get_settings()
    if not settings.broker:
        print("shadergen worker: set SHADERGEN_BROKER=redis://host:port/db", file=sys.stderr)
        return 2
    import redis

    from .jobs.celery_app import QUEUE, make_celery, register_tasks
    from .jobs.celery_routing import QueueAnnouncer, worker_queue

    concurrency = args.concurrency or settings.render_workers
    app = make_celery(settings)
    register_tasks(app, settings, processes=concurrency)
    # the shared queue, and this worker's own, where the API routes the topologies it holds
    own = worker_queue(args.name)
    announcer = QueueAnnouncer(redis.Redis.from_url(settings.broker), own, settings)
    announcer.start()
    try:
        app.worker_main(["worker", f"--concurrency={concurrency}", "--pool=prefork", f"--queues={QUEUE},{own}",
                         f"--loglevel={args.loglevel}", "--without-gossip", "--without-mingle"])
    finally:
        announcer.stop()
    return 0
