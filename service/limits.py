"""What a request body may cost, enforced before any handler sees it: the body is read here,
whole, under a size limit and a deadline, and handed on as one message.

A declared Content-Length over the limit is refused before a byte is read, a chunked body is cut
off at the first chunk that crosses it (413 on every route), a body that does not arrive within
the deadline is refused (408), so no client can make a worker buffer more than the limit or hold
it open for ever. A client that goes away while sending is logged in one line and counted as
status 499 (nginx's "client closed request"), not as a server error."""
import asyncio
import logging

from .errors import ServiceError, error_response
from .metrics import DISCONNECTED

log = logging.getLogger("uvicorn.error")  # the server's own log, configured by uvicorn in every worker


class ClientDisconnected(Exception):
    pass


def declares_body(headers) -> tuple[bool, bytes | None]:
    """(whether a body follows, the declared Content-Length)."""
    length, chunked = None, False
    for name, value in headers:
        if name == b"content-length":
            length = value
        elif name == b"transfer-encoding":
            chunked = True
    return chunked or (length is not None and length != b"0"), length


async def _read_body(receive, max_bytes: int) -> bytes:
    chunks, seen = [], 0
    while True:
        message = await receive()
        if message["type"] == "http.disconnect":
            raise ClientDisconnected
        body = message.get("body", b"")
        seen += len(body)
        if seen > max_bytes:
            raise ServiceError("too_large", f"request body over the limit of {max_bytes} bytes",
                               headers={"Connection": "close"})
        chunks.append(body)
        if not message.get("more_body"):
            return b"".join(chunks)


class BodyLimitMiddleware:
    """`path_limits`: paths with a limit of their own (a thumbnail batch carries a library)."""

    def __init__(self, app, max_bytes: int, read_timeout_s: float, path_limits: dict[str, int] | None = None):
        self.app = app
        self.max_bytes = max_bytes
        self.read_timeout_s = read_timeout_s
        self.path_limits = path_limits or {}

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        has_body, length = declares_body(scope["headers"])
        if not has_body:
            return await self.app(scope, receive, send)
        max_bytes = self.path_limits.get(scope["path"], self.max_bytes)
        try:
            if length is not None and (not length.isdigit() or int(length) > max_bytes):
                raise ServiceError("too_large", f"request body over the limit of {max_bytes} bytes",
                                   headers={"Connection": "close"})
            async with asyncio.timeout(self.read_timeout_s):
                body = await _read_body(receive, max_bytes)
        except ServiceError as exc:
            return await error_response(exc)(scope, receive, send)
        except TimeoutError:
            exc = ServiceError("request_timeout", f"the body did not arrive within {self.read_timeout_s:g} s",
                               headers={"Connection": "close"})
            return await error_response(exc)(scope, receive, send)
        except ClientDisconnected:
            client = "%s:%s" % tuple(scope["client"]) if scope.get("client") else "a client"
            log.info("%s disconnected while sending the body of %s %s", client, scope["method"], scope["path"])
            scope[DISCONNECTED] = True
            return
        replayed = False

        async def replay():
            nonlocal replayed
            if replayed:
                return await receive()
            replayed = True
            return {"type": "http.request", "body": body, "more_body": False}

        await self.app(scope, replay, send)
