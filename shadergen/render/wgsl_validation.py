"""WGSL validation in a child process: naga (inside wgpu-native) sometimes panics on a module it
should reject, and a panic across wgpu-native's C interface aborts the whole process. Run in a
child, a panic costs one module (rejected with naga's own message) and a new child for the next.

The child (`python -m shadergen.render.wgsl_validation`) reads one JSON request a line on stdin,
`{"name", "source"}`, creates the shader module on the process's WebGPU device and answers one
JSON line, `{"error": message or null}`. Its stderr goes to a file, where a panic's message is
read back from.
"""
import json
import os
import re
import select
import subprocess
import sys
import tempfile

from .errors import RenderError

TIMEOUT_S = 120  # one module: validation takes milliseconds, device creation a few seconds


class Validator:
    """The parent's end: one child, started on first use and again after it died."""

    def __init__(self):
        self.child: subprocess.Popen | None = None
        self.stderr = None

    def errors(self, sources: dict[str, str]) -> dict[str, str]:
        """name -> the validator's message, for every module it rejects (an empty dict: all valid)."""
        found = {}
        for name, source in sources.items():
            message = self.check(name, source)
            if message is not None:
                found[name] = message
        return found

    def check(self, name: str, source: str) -> str | None:
        child = self._child()
        start = self.stderr.seek(0, os.SEEK_END)
        try:
            child.stdin.write(json.dumps({"name": name, "source": source}) + "\n")
            child.stdin.flush()
            ready, _, _ = select.select([child.stdout], [], [], TIMEOUT_S)
            answer = child.stdout.readline() if ready else ""
        except BrokenPipeError:
            answer = ""
        if answer:
            reply = json.loads(answer)
            if "unavailable" in reply:
                self.close()
                raise RenderError("no_wgpu_device", reply["unavailable"])
            return reply["error"]
        self.close()  # dead (a panic) or stuck: the next module gets a new child
        self.stderr.seek(start)
        reason = panic_message(self.stderr.read()) if ready else f"the validator took over {TIMEOUT_S} s"
        return f"WGSL {name} stage rejected: {reason}"

    def _child(self) -> subprocess.Popen:
        if self.child is None or self.child.poll() is not None:
            if self.stderr is None:
                self.stderr = tempfile.TemporaryFile("w+", encoding="utf-8", errors="replace")
            env = dict(os.environ, RUST_BACKTRACE="0")  # the panic's message, not its stack
            self.child = subprocess.Popen([sys.executable, "-m", __name__], stdin=subprocess.PIPE,
                                          stdout=subprocess.PIPE, stderr=self.stderr, env=env, text=True)
        return self.child

    def close(self) -> None:
        if self.child is not None:
            self.child.kill()
            self.child.wait()
            self.child.stdin.close()
            self.child.stdout.close()
            self.child = None


def panic_message(stderr: str) -> str:
    """naga's panic as one rejection: `thread ... panicked at FILE:LINE:COL:` then its message."""
    lines = stderr.splitlines()
    for k, line in enumerate(lines):
        if " panicked at " in line:
            where = re.sub(r".*/(?=[\w-]+-\d+\.\d+\.\d+/)", "", line.split(" panicked at ", 1)[1].rstrip(":"))
            what = lines[k + 1].strip() if k + 1 < len(lines) else ""
            return f"the validator panicked: {what} (at {where})"
    tail = " ".join(ln.strip() for ln in lines[-3:])
    return f"the validator's process died: {tail or 'no message'}"


def serve() -> None:
    from .wgpu_device import shader_module, wgpu_device
    try:
        device = wgpu_device()
    except RenderError as exc:
        device, unavailable = None, exc.message
    for line in sys.stdin:
        request = json.loads(line)
        if device is None:
            reply = {"unavailable": unavailable}
        else:
            try:
                shader_module(device, request["source"], request["name"])
                reply = {"error": None}
            except RenderError as exc:
                reply = {"error": exc.message}
        sys.stdout.write(json.dumps(reply) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    serve()
