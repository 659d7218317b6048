"""What the pools read about a child from /proc: its resident memory (what the memory limits
bound: resident, not virtual, since an EGL context on llvmpipe, the JIT and thread stacks map far
more address space than they touch) and whether it is stopped."""
import os

PAGE = os.sysconf("SC_PAGE_SIZE")


def resident_bytes(pid: int | str = "self") -> int | None:
    """None once the process is gone."""
    try:
        with open(f"/proc/{pid}/statm") as f:
            return int(f.read().split()[1]) * PAGE
    except (OSError, ValueError, IndexError):
        return None


def stopped(pid: int) -> bool:
    """Stopped by a signal (T) or a tracer (t); False once the process is gone."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] in ("T", "t")
    except (OSError, IndexError):
        return False
