"""Prometheus metrics. Under `shadergen serve` every process (API workers, the render pool)
writes to PROMETHEUS_MULTIPROC_DIR and /metrics adds them up; a single process uses the default
registry. prometheus_client picks its mode when first imported, so the serve command sets the
directory before any worker starts."""
import os
import time

from prometheus_client import CONTENT_TYPE_LATEST, CollectorRegistry, Counter, Gauge, Histogram, generate_latest
from prometheus_client import REGISTRY
from prometheus_client.multiprocess import MultiProcessCollector

from .asgi import StatusRecorder

LATENCY_BUCKETS = (0.001, 0.0025, 0.005, 0.01, 0.02, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 30.0, 60.0)

REQUESTS = Counter("shadergen_requests_total", "HTTP requests answered", ["method", "route", "status"])
LATENCY = Histogram("shadergen_request_seconds", "HTTP request latency", ["method", "route"], buckets=LATENCY_BUCKETS)
RATIONED = Counter("shadergen_rationed_total", "requests of clients out of failure allowance (fairness.py): held until "
                   "a turn came, or refused with 429", ["outcome"])
CACHE = Counter("shadergen_cache_total", "cache lookups", ["kind", "result"])
CACHE_ERRORS = Counter("shadergen_cache_errors_total", "cache operations that failed and were answered "
                       "without the cache", ["op"])
QUEUE_DEPTH = Gauge("shadergen_queue_depth", "jobs waiting for a worker", ["queue"], multiprocess_mode="mostrecent")
GENERATE_SECONDS = Histogram("shadergen_generate_seconds", "generation in a worker process (cache misses)",
                             buckets=LATENCY_BUCKETS)
PROGRAMS = Counter("shadergen_programs_total", "render programs a worker compiled, or reused for a record of "
                   "the same source (value-free sources: one program per topology)", ["result"])
RENDER_SECONDS = Histogram("shadergen_render_seconds", "thumbnail render in a render worker", buckets=LATENCY_BUCKETS)

CONTENT_TYPE = CONTENT_TYPE_LATEST
# where a middleware that answers by itself names the route it answered for
ROUTE_KEY = "shadergen.route"
# set when the client went away before a response: counted as status 499, not as a server error
DISCONNECTED = "shadergen.disconnected"
CLIENT_CLOSED = 499


def exposition() -> bytes:
    if os.environ.get("PROMETHEUS_MULTIPROC_DIR"):
        registry = CollectorRegistry()
        MultiProcessCollector(registry)
        return generate_latest(registry)
    return generate_latest(REGISTRY)


class MetricsMiddleware:
    """Counts and times every request by route template (not raw path, which would let clients
    create unbounded label values)."""

    def __init__(self, app):
        self.app = app
        self._series = {}  # (method, route, status) -> its two series: labels() is a locked lookup

    def _observe(self, method: str, route: str, status: int, seconds: float) -> None:
        key = (method, route, status)
        series = self._series.get(key)
        if series is None:
            series = self._series[key] = (REQUESTS.labels(method, route, str(status)), LATENCY.labels(method, route))
        series[0].inc()
        series[1].observe(seconds)

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        started = time.perf_counter()
        recorder = StatusRecorder(send)
        try:
            await self.app(scope, receive, recorder)
        finally:
            status = CLIENT_CLOSED if scope.get(DISCONNECTED) else recorder.status
            route = scope.get(ROUTE_KEY) or getattr(scope.get("route"), "path", "unmatched")
            self._observe(scope["method"], route, status, time.perf_counter() - started)
