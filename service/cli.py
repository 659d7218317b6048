"""`shadergen serve`: uvicorn on N worker processes, a shared render pool (unless Celery is
configured), and one Prometheus directory that every process writes to."""
import os
import shutil
import signal
import tempfile

import uvicorn

from .config import get_settings
from .http_protocol import BoundedHttpToolsProtocol


def add_arguments(parser) -> None:
    parser.add_argument("--host", default="127.0.0.1", help="address to listen on (default: loopback only)")
    parser.add_argument("--port", type=int, default=8000, help="TCP port to listen on")
    parser.add_argument("--workers", type=int, default=2, metavar="N", help="API worker processes")
    parser.add_argument("--render-workers", type=int, default=None, metavar="N",
                        help="render processes of the local pool (default: SHADERGEN_RENDER_WORKERS or 1)")
    parser.add_argument("--access-log", action="store_true", help="log every request")


def proxy_options(settings) -> dict:
    """X-Forwarded-For (and -Proto) are believed only from the proxies the operator names in
    SHADERGEN_TRUSTED_PROXIES. uvicorn alone believes them from 127.0.0.1 (or FORWARDED_ALLOW_IPS):
    any local client could then name the address that its failures count against (fairness.py)."""
    if not settings.trusted_proxies:
        return {"proxy_headers": False}
    return {"proxy_headers": True, "forwarded_allow_ips": settings.trusted_proxies}


def _exit(signum, frame):
    raise SystemExit(0)


def run(args) -> int:
    if args.render_workers is not None:
        os.environ["SHADERGEN_RENDER_WORKERS"] = str(args.render_workers)
    # prometheus_client reads this when first imported, so it is set before any worker starts
    metrics_dir = None
    if not os.environ.get("PROMETHEUS_MULTIPROC_DIR"):
        metrics_dir = tempfile.mkdtemp(prefix="shadergen-metrics-")
        os.environ["PROMETHEUS_MULTIPROC_DIR"] = metrics_dir
    get_settings.cache_clear()
    settings = get_settings()
    pool = None
    if not settings.broker:
        from .jobs.local import PoolServerSupervisor

        pool = PoolServerSupervisor(settings)  # started again whenever it exits
        os.environ["SHADERGEN_RENDER_SOCKET"] = pool.socket_path  # every API worker connects to this one pool
        get_settings.cache_clear()  # with one worker, uvicorn runs the app in this very process
    # uvicorn re-raises the SIGTERM it handled once it has stopped; as an exception instead of the
    # default action (death on the spot), it lets the pool and the metrics directory be cleaned up
    signal.signal(signal.SIGTERM, _exit)
    try:
        uvicorn.run("service.main:create_app", factory=True, host=args.host, port=args.port,
                    http=BoundedHttpToolsProtocol, workers=args.workers, access_log=args.access_log,
                    timeout_graceful_shutdown=10, **proxy_options(settings))
    finally:
        if pool is not None:
            pool.stop()
        if metrics_dir is not None:
            shutil.rmtree(metrics_dir, ignore_errors=True)
    return 0
