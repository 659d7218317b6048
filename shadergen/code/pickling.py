"""pickle's C implementation, which is what `pickle` runs on CPython, imported without pickle.py:
that module's own import (its pure-Python fallback, never used where the C one is there) was 2 ms
of a cold `generate`, which reads the library's caches (code/cachefile.py, targets/printed.py)."""
try:
    from _pickle import Pickler, Unpickler, UnpicklingError, dumps, loads
except ImportError:  # a Python without the accelerator
    from pickle import Pickler, Unpickler, UnpicklingError, dumps, loads

__all__ = ["Pickler", "Unpickler", "UnpicklingError", "dumps", "loads", "PROTOCOL"]

PROTOCOL = 5  # pickle.HIGHEST_PROTOCOL (since Python 3.8)
