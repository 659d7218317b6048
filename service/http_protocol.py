"""uvicorn's httptools protocol with limits on the request head (request line and headers).

httptools sets no bound of its own: a client could send a 200 MB header, which a worker would
read and hold for as long as the client cares to trickle it. Here the head may be at most
`head_max_bytes` (431) and must arrive within `head_timeout_s` of its first byte (408); either
way the connection is closed after the answer. Bodies are bounded in the app (limits.py)."""
import json

from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol

from .config import get_settings
from .errors import error_body


def _answer(status: int, reason: str, code: str, message: str) -> bytes:
    body = json.dumps(error_body(code, message)).encode()
    head = (f"HTTP/1.1 {status} {reason}\r\ncontent-type: application/json\r\n"
            f"content-length: {len(body)}\r\nconnection: close\r\n\r\n")
    return head.encode() + body


class BoundedHttpToolsProtocol(HttpToolsProtocol):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        settings = get_settings()
        self.head_max_bytes = settings.head_max_bytes
        self.head_timeout_s = settings.head_timeout_s
        self.head_bytes = 0  # bytes received since the current request began, until its headers end
        self.in_head = True
        self.head_deadline = None

    def data_received(self, data: bytes) -> None:
        if self.in_head:
            self.head_bytes += len(data)
            if self.head_deadline is None:
                self.head_deadline = self.loop.call_later(self.head_timeout_s, self._head_too_slow)
        super().data_received(data)
        # checked after parsing: a packet may hold the end of the head and the start of the body
        if self.in_head and self.head_bytes > self.head_max_bytes and not self.transport.is_closing():
            self._refuse(431, "Request Header Fields Too Large", "too_large",
                         f"request line and headers over the limit of {self.head_max_bytes} bytes")

    def on_headers_complete(self) -> None:
        self.in_head = False
        self._cancel_deadline()
        super().on_headers_complete()

    def on_message_complete(self) -> None:
        super().on_message_complete()
        self.in_head, self.head_bytes = True, 0

    def connection_lost(self, exc) -> None:
        self._cancel_deadline()
        super().connection_lost(exc)

    def _cancel_deadline(self) -> None:
        if self.head_deadline is not None:
            self.head_deadline.cancel()
            self.head_deadline = None

    def _head_too_slow(self) -> None:
        self.head_deadline = None
        if self.in_head and not self.transport.is_closing():
            self._refuse(408, "Request Timeout", "request_timeout",
                         f"request headers did not arrive within {self.head_timeout_s:g} s")

    def _refuse(self, status: int, reason: str, code: str, message: str) -> None:
        self.logger.info("%s refused: %s", "%s:%d" % self.client if self.client else "a client", message)
        self.transport.write(_answer(status, reason, code, message))
        self.transport.close()
