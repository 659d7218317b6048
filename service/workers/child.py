"""The child side of a pool: read a request, call the handler, write the reply, until the parent
closes the pipe. The protocol runs on a private copy of fd 1 and fd 1 itself is pointed at
stderr, so a stray print from a library (or a GL driver) cannot corrupt the stream."""
import logging
import os
import sys
import traceback

from . import protocol


def serve(handler, hello: dict) -> None:
    """handler(message, payload) -> (reply, payload); an exception becomes {"error": ...}."""
    out = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    inp = sys.stdin.buffer
    logging.basicConfig(level=logging.INFO, format=f"[{os.getpid()}] %(name)s: %(message)s")
    protocol.write_frame_sync(out, hello)
    while (frame := protocol.read_frame_sync(inp)) is not None:
        message, payload = frame
        try:
            reply, blob = handler(message, payload)
        except Exception as exc:  # the parent turns this into a clear error, the child lives on
            traceback.print_exc()
            reply, blob = {"error": {"code": "internal_error", "message": f"{type(exc).__name__}: {exc}"}}, b""
        try:
            protocol.write_frame_sync(out, reply, blob)
        except BrokenPipeError:
            return  # the parent died while this job ran (its supervisor starts a new one): nobody to answer
