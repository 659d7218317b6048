"""What a sound cache entry looks like. A shared cache can hold anything (a half-written value, a
key another program reused, `not json {{{`): a value that fails these checks is a miss, and the
fresh answer overwrites it. The checks are cheap enough for every cached request: no parsing."""
import json
import re

_GRAPH_HASH = re.compile(rb"[0-9a-f]{8,128}")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def is_graph_hash(value: bytes | None) -> bool:
    """A `req:` entry: the graph hash the request resolved to."""
    return value is not None and _GRAPH_HASH.fullmatch(value) is not None


def is_record(value: bytes | None, graph_hash: str) -> bool:
    """A `rec:` entry: a JSON object that names its own hash."""
    return (value is not None and value.startswith(b"{") and value.endswith(b"}")
            and b'"hash":"%s"' % graph_hash.encode() in value)


def has_no_warnings(record: bytes) -> bool:
    """Whether a sound `rec:` entry (compact JSON, as the generator writes it) lists no warnings.
    A record is stored once per graph hash, but its warnings are those of the document that
    stored it: only a record without any is every document's answer as it is."""
    return b'"warnings":[]' in record


def refusal(value: bytes | None) -> dict | None:
    """An `err:` entry: the generator's error object for a request it refused, or None."""
    if value is None or not value.startswith(b"{"):
        return None
    try:
        error = json.loads(value)
    except ValueError:
        return None
    sound = isinstance(error, dict) and isinstance(error.get("code"), str) and isinstance(error.get("message"), str)
    return error if sound else None


def is_png(value: bytes | None) -> bool:
    return value is not None and value.startswith(PNG_SIGNATURE)
