"""The generator's digests, without hashlib: hashlib starts OpenSSL to offer every algorithm, about
2.5 ms of every process (a twentieth of a cold `generate`); CPython builds these in.

`sha256`: SHA-256, for the keys of the generator's caches and the names it shortens (a digest in
a name is part of the source). `graph_digest`: BLAKE2b-256 (RFC 7693), for the graph hashes
(hashing.py), the one digest of every request: tens of kilobytes for a material, which CPython's
BLAKE2b reads three times as fast as its SHA-256 (OpenSSL's SHA-256 is faster still, and costs
that start-up)."""
try:
    from _blake2 import blake2b as _blake2b
except ImportError:  # pragma: no cover (a Python without CPython's module: hashlib's)
    from hashlib import blake2b as _blake2b
try:
    from _sha256 import sha256  # CPython 3.11
except ImportError:  # pragma: no cover (3.12 renamed it; any other Python: hashlib's)
    try:
        from _sha2 import sha256
    except ImportError:
        from hashlib import sha256

__all__ = ["sha256", "graph_digest"]


def graph_digest(data: bytes = b""):
    """A BLAKE2b hash object of 32 bytes (64 hex digits, as SHA-256's)."""
    return _blake2b(data, digest_size=32)
