"""A child for the pool tests: the real child loop (service.workers.child.serve) around a handler
whose jobs sleep, crash or answer, so the pool's own logic can be tested on real processes."""
import ctypes
import os
import tempfile
import time
from pathlib import Path

from service.workers.child import serve


def handle(message: dict, payload: bytes):
    action = message.get("action")
    if action == "sleep":
        time.sleep(message["seconds"])
    elif action == "crash":
        os._exit(3)
    elif action == "crash_once":
        # crashes the first time it sees this marker path, answers afterwards
        marker = Path(message["marker"])
        if not marker.exists():
            marker.write_text("crashed")
            os._exit(3)
    elif action == "raise":
        raise ValueError("a bug in the handler")
    elif action == "allocate":
        held = b"\1" * (message["mib"] << 20)  # touched, so resident
        time.sleep(message.get("seconds", 5))
        del held
    elif action == "hold_gil":
        ctypes.PyDLL(None).usleep(int(message["seconds"] * 1e6))  # PyDLL: called without releasing the GIL
    elif action == "write_temp":
        with tempfile.NamedTemporaryFile(delete=False) as f:
            f.write(b"left behind unless the pool removes it")
        return {"pid": os.getpid(), "path": f.name}, b""
    elif action == "print":
        print("stray output that must not corrupt the protocol")
    return {"pid": os.getpid(), "echo": message.get("echo")}, payload[::-1]


if __name__ == "__main__":
    serve(handle, {"ready": True, "pid": os.getpid()})
