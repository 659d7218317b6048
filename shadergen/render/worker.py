"""A Renderer in a process of its own, for services that render on several cores.

The child is started with the 'spawn' method (a GL context inherited through fork hangs: moderngl
issue 414) and creates its context on its first job, with LP_NUM_THREADS set so that the workers
of one machine share its cores instead of each starting one llvmpipe thread per core. A job that
runs past its timeout kills the worker; the next job starts a fresh one.
"""
import multiprocessing
import os

from .errors import RenderError
from .renderer import Renderer, RenderResult


def lp_threads_for(workers: int) -> int:
    """llvmpipe threads per worker when `workers` render at once on this machine's cores."""
    return max(1, (os.cpu_count() or 1) // max(1, workers))


def _serve(connection, lp_threads, renderer_options) -> None:
    renderer = Renderer(lp_threads=lp_threads, **renderer_options)
    while True:
        try:
            job = connection.recv()
        except EOFError:
            return
        if job is None:
            return
        record, options = job
        try:
            connection.send(("ok", renderer.render(record, **options)))
        except RenderError as exc:
            connection.send(("error", (exc.code, exc.message, exc.where)))
        except Exception as exc:  # a bug must not kill the worker silently: report it as data
            connection.send(("error", ("internal_error", f"{type(exc).__name__}: {exc}", None)))


class RenderWorker:
    """Renders records in a spawned child process that keeps its Renderer between jobs."""

    def __init__(self, lp_threads: int | None = None, **renderer_options):
        self._lp_threads = lp_threads
        self._options = renderer_options
        self._process = None
        self._connection = None

    def _start(self) -> None:
        spawn = multiprocessing.get_context("spawn")
        self._connection, child = spawn.Pipe()
        self._process = spawn.Process(target=_serve, args=(child, self._lp_threads, self._options),
                                      daemon=True, name="shadergen-render")
        self._process.start()
        child.close()

    def render(self, record: dict, timeout: float | None = None, **options) -> RenderResult:
        """Renderer.render in the worker; RenderError("timeout") if it takes longer than `timeout` s."""
        if self._process is None or not self._process.is_alive():
            self._start()
        try:
            self._connection.send((record, options))
            if not self._connection.poll(timeout):
                self.close(kill=True)
                raise RenderError("timeout", f"render took longer than {timeout} s; worker restarted",
                                  record.get("element") if isinstance(record, dict) else None)
            status, payload = self._connection.recv()
        except (EOFError, BrokenPipeError, ConnectionResetError) as exc:
            self.close(kill=True)
            raise RenderError("worker_died", f"the render worker exited unexpectedly ({exc or 'no reply'})") from exc
        if status == "error":
            raise RenderError(*payload)
        return payload

    def close(self, kill: bool = False) -> None:
        if self._process is None:
            return
        if kill:
            self._process.kill()
        else:
            try:
                self._connection.send(None)
            except (BrokenPipeError, OSError):
                pass
        self._process.join(timeout=5)
        if self._process.is_alive():
            self._process.kill()
            self._process.join()
        self._connection.close()
        self._process = self._connection = None

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()
