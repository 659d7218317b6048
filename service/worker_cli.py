"""`shadergen worker`: a Celery render worker for SHADERGEN_BROKER=redis://... Each of its
processes creates its own EGL context on its first job (prefork children, after the fork)."""
import sys

from .config import get_settings


def add_arguments(parser) -> None:
    parser.add_argument("--concurrency", type=int, default=None, metavar="N",
                        help="render processes (default: SHADERGEN_RENDER_WORKERS or 1)")
    parser.add_argument("--loglevel", default="info", help="Celery log level: debug, info, warning or error")


def run(args) -> int:
    settings = get_settings()
    if not settings.broker:
        print("shadergen worker: set SHADERGEN_BROKER=redis://host:port/db", file=sys.stderr)
        return 2
    from .jobs.celery_app import QUEUE, make_celery, register_tasks

    concurrency = args.concurrency or settings.render_workers
    app = make_celery(settings)
    register_tasks(app, settings, processes=concurrency)
    app.worker_main(["worker", f"--concurrency={concurrency}", "--pool=prefork", f"--queues={QUEUE}",
                     f"--loglevel={args.loglevel}", "--without-gossip", "--without-mingle"])
    return 0
