"""The processes of a test's server, read from /proc: who started whom, their command lines and
peak memory (Linux, as the service's own limits are)."""
from pathlib import Path


def parent(pid: int) -> int | None:
    """The parent process of `pid`, from /proc; None once it is gone."""
    try:
        stat = (Path("/proc") / str(pid) / "stat").read_text()
    except OSError:
        return None
    return int(stat.rsplit(")", 1)[1].split()[1])  # the name in parentheses may hold spaces


def parents() -> dict[int, int | None]:
    """Every process's parent, from one reading of /proc."""
    return {int(e.name): parent(int(e.name)) for e in Path("/proc").iterdir() if e.name.isdigit()}


def children(pid: int, known: dict[int, int | None] | None = None) -> list[int]:
    """The processes `pid` started itself (from `known`, a reading of parents(), when given)."""
    return [child for child, ppid in (known or parents()).items() if ppid == pid]


def descendants(pid: int) -> list[int]:
    """Every process below `pid`, from one reading of /proc."""
    known = parents()
    found, todo = [], [pid]
    while todo:
        for child in children(todo.pop(), known):
            found.append(child)
            todo.append(child)
    return found


def cmdline(pid: int) -> str:
    try:
        return (Path("/proc") / str(pid) / "cmdline").read_bytes().replace(b"\0", b" ").decode()
    except OSError:
        return ""


def peak_rss_kib(pid: int) -> int | None:
    """The peak resident memory (VmHWM) of `pid` so far; None once it is gone."""
    try:
        status = (Path("/proc") / str(pid) / "status").read_text()
    except OSError:
        return None
    return int(status.split("VmHWM:")[1].split()[0])
