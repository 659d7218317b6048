"""Resident memory of a process, from /proc: what the memory limits of child processes bound.
Resident, not virtual: an EGL context on llvmpipe, the JIT and thread stacks map far more address
space than they touch."""
import os

PAGE = os.sysconf("SC_PAGE_SIZE")


def resident_bytes(pid: int | str = "self") -> int | None:
    """None once the process is gone."""
    try:
        with open(f"/proc/{pid}/statm") as f:
            return int(f.read().split()[1]) * PAGE
    except (OSError, ValueError, IndexError):
        return None
