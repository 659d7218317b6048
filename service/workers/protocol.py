"""Framing shared by the pools, their child processes and the render-pool socket: a JSON header
and an optional binary payload (PNG bytes), each length-prefixed. JSON only, never pickle: a
message can be read by anything without running code."""
import asyncio
import json
import struct
from typing import BinaryIO

HEADER = struct.Struct(">II")
MAX_FRAME = 256 * 1024 * 1024


class ProtocolError(Exception):
    pass


def encode(message: dict, payload: bytes = b"") -> bytes:
    body = json.dumps(message, separators=(",", ":")).encode()
    return HEADER.pack(len(body), len(payload)) + body + payload


def _decode(head: bytes) -> tuple[int, int]:
    n_json, n_blob = HEADER.unpack(head)
    if n_json + n_blob > MAX_FRAME:
        raise ProtocolError(f"frame of {n_json + n_blob} bytes")
    return n_json, n_blob


async def read_frame(reader: asyncio.StreamReader) -> tuple[dict, bytes]:
    """Raises asyncio.IncompleteReadError at end of stream (the other side is gone)."""
    n_json, n_blob = _decode(await reader.readexactly(HEADER.size))
    body = await reader.readexactly(n_json)
    payload = await reader.readexactly(n_blob) if n_blob else b""
    return json.loads(body), payload


def read_frame_sync(stream: BinaryIO) -> tuple[dict, bytes] | None:
    """Blocking read for child processes; None at end of stream (the parent is gone)."""
    head = stream.read(HEADER.size)
    if len(head) < HEADER.size:
        return None
    n_json, n_blob = _decode(head)
    body = stream.read(n_json)
    payload = stream.read(n_blob) if n_blob else b""
    return json.loads(body), payload


def write_frame_sync(stream: BinaryIO, message: dict, payload: bytes = b"") -> None:
    stream.write(encode(message, payload))
    stream.flush()
