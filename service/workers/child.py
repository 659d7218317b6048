"""The child side of a pool: read a request, call the handler, write the reply, until the parent
closes the pipe. The protocol runs on a private copy of fd 1 and fd 1 itself is pointed at
stderr, so a stray print from a library (or a GL driver) cannot corrupt the stream.

Beside the replies, a thread writes a heartbeat frame every `heartbeat_s` seconds, busy or idle:
the parent's only evidence that the child still runs (a stopped or wedged child keeps its pipes
open and would otherwise look alive). The heartbeat is a thread of this process, so it is as
alive as the process: a job that holds the GIL in C for longer than the parent's deadline makes
the child look silent, which is why that deadline is several heartbeats long."""
import logging
import os
import sys
import threading
import time
import traceback

from . import protocol

HEARTBEAT = {"heartbeat": True}


class _Out:
    """fd 1's private copy, shared by the replies and the heartbeats: one frame at a time."""

    def __init__(self):
        self.stream = os.fdopen(os.dup(1), "wb")
        self.lock = threading.Lock()

    def write(self, message: dict, payload: bytes = b"") -> None:
        with self.lock:
            protocol.write_frame_sync(self.stream, message, payload)


def _beat(out: _Out, interval_s: float) -> None:
    while True:
        time.sleep(interval_s)
        try:
            out.write(HEARTBEAT)
        except (BrokenPipeError, ValueError, OSError):
            return  # the parent is gone (or the stream closed): the main loop ends too


def serve(handler, hello: dict, heartbeat_s: float | None = None) -> None:
    """handler(message, payload) -> (reply, payload); an exception becomes {"error": ...}.
    heartbeat_s: default SHADERGEN_HEARTBEAT_S (see service/config.py)."""
    if heartbeat_s is None:
        from ..config import get_settings

        heartbeat_s = get_settings().heartbeat_s
    out = _Out()
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    inp = sys.stdin.buffer
    logging.basicConfig(level=logging.INFO, format=f"[{os.getpid()}] %(name)s: %(message)s")
    out.write(hello)
    threading.Thread(target=_beat, args=(out, heartbeat_s), name="heartbeat", daemon=True).start()
    while (frame := protocol.read_frame_sync(inp)) is not None:
        message, payload = frame
        try:
            reply, blob = handler(message, payload)
        except Exception as exc:  # the parent turns this into a clear error, the child lives on
            traceback.print_exc()
            reply, blob = {"error": {"code": "internal_error", "message": f"{type(exc).__name__}: {exc}"}}, b""
        try:
            out.write(reply, blob)
        except BrokenPipeError:
            return  # the parent died while this job ran (its supervisor starts a new one): nobody to answer
