"""Private temporary folders for child processes, removed when the child is gone however it went.

A child killed at its memory or time limit, or by a signal, runs none of its own clean-up
(`finally`, TemporaryDirectory, atexit), so the files it was writing (a usdz unpacked by
parse_usd, a render job's package) would stay in /tmp for good. So every child gets a folder of
its own as TMPDIR, which Python's tempfile (and anything else honouring TMPDIR) writes under, and
the folder is removed by whoever outlives the child: the pool that started it, when it exits.
A folder's name carries the pid of its owner (the process whose death makes it garbage); a pool
that starts removes the folders of owners that are no longer running, which is what a pool that
was itself killed leaves behind."""
import os
import shutil
import tempfile
from pathlib import Path

PREFIX = "shadergen-child-"
ENV_NAMES = ("TMPDIR", "TMP", "TEMP")


def make(owner_pid: int | None = None) -> str:
    """A fresh folder owned by `owner_pid` (default: this process)."""
    return tempfile.mkdtemp(prefix=f"{PREFIX}{owner_pid or os.getpid()}-")


def env_for(folder: str) -> dict[str, str]:
    return {name: folder for name in ENV_NAMES}


def remove(folder: str | None) -> None:
    if folder:
        shutil.rmtree(folder, ignore_errors=True)


def _running(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # someone else's process: running
        return True
    return True


def sweep() -> list[int]:
    """Remove the folders whose owner is no longer running; returns those owners."""
    owners = []
    for folder in Path(tempfile.gettempdir()).glob(PREFIX + "*"):
        owner = folder.name[len(PREFIX):].split("-", 1)[0]
        if owner.isdigit() and not _running(int(owner)):
            shutil.rmtree(folder, ignore_errors=True)
            owners.append(int(owner))
    return owners
