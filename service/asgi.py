"""What the service's ASGI middlewares share."""


class StatusRecorder:
    """An ASGI `send` that passes every message on and remembers the status of the response
    (500 until one is sent: a request that ends without an answer is the server's failure)."""

    def __init__(self, send):
        self.send = send
        self.status = 500

    async def __call__(self, message) -> None:
        if message["type"] == "http.response.start":
            self.status = message["status"]
        await self.send(message)
