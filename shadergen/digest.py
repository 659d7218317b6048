"""SHA-256 for the generator's keys and names, without hashlib: hashlib starts OpenSSL to offer
every algorithm, about 2.5 ms of every process (a twentieth of a cold `generate`); CPython builds
this one in. The digests are SHA-256's, whichever implementation computes them; OpenSSL's is
faster on megabytes, which only a process that hashes the generator's files after an edit reads."""
try:
    from _sha256 import sha256  # CPython 3.11
except ImportError:  # pragma: no cover (3.12 renamed it; any other Python: hashlib's)
    try:
        from _sha2 import sha256
    except ImportError:
        from hashlib import sha256

__all__ = ["sha256"]
