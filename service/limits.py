"""The request body limit, enforced while the body streams in: a declared Content-Length over the
limit is refused before a byte is read, and a chunked body is cut off at the first chunk that
crosses it, so no client can make a worker buffer more than the limit."""
import json

from .errors import ServiceError, error_body


class BodyTooLarge(ServiceError):
    def __init__(self, limit: int):
        super().__init__("too_large", f"request body over the limit of {limit} bytes")


class BodyLimitMiddleware:
    def __init__(self, app, max_bytes: int):
        self.app = app
        self.max_bytes = max_bytes

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        for name, value in scope["headers"]:
            if name == b"content-length":
                if not value.isdigit() or int(value) > self.max_bytes:
                    return await self._refuse(send)
        seen = 0

        async def limited_receive():
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.max_bytes:
                    raise BodyTooLarge(self.max_bytes)  # the app's error handler answers 413
            return message

        await self.app(scope, limited_receive, send)

    async def _refuse(self, send) -> None:
        exc = BodyTooLarge(self.max_bytes)
        body = json.dumps(error_body(exc.code, exc.message)).encode()
        await send({"type": "http.response.start", "status": 413,
                    "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode()),
                                (b"connection", b"close")]})
        await send({"type": "http.response.body", "body": body})
