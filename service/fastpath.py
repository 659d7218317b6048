"""Plainly valid POST /v1/generate requests answered below the framework.

A byte-identical request to one answered before is two key lookups in the shared store; going
through FastAPI's routing, dependency injection and validation would cost several times that
and would put the cached p99 at 32 concurrent clients far over its 20 ms goal on two cores
(bench/load.py measures it). So this middleware reads the body, and when the parameters are
plainly valid it calls the generation service itself, as the route would with the same
parameters: a stored record, a refusal given before (a client repeating a bad document costs
one parse of the body, not two), or a fresh generation. Any parameter it does not plainly accept
goes on to the route with the body replayed, and the route decides: this path never produces an
answer the route would not."""
import json
from urllib.parse import parse_qsl

from .errors import ServiceError, error_response
from .generation import GenerateParams
from .metrics import ROUTE_KEY

PATH = "/v1/generate"
INTERFACES = frozenset(("complete", "reduced", "specialized"))
JSON_FIELDS = frozenset(("document", "target", "element", "interface", "source"))
XML_TYPES = (b"application/xml", b"text/xml")


def _text(value, max_length: int) -> bool:
    return isinstance(value, str) and len(value) <= max_length and value.isascii()


def _plain(target, element, interface, source) -> GenerateParams | None:
    """Parameters exactly as the route's models would read them, or None to let the route judge."""
    if not (_text(target, 64) and isinstance(interface, str) and interface in INTERFACES and isinstance(source, bool)):
        return None
    if element is not None and not _text(element, 1024):
        return None
    return GenerateParams(target, element, interface, source)


def parse(content_type: bytes, query: bytes, body: bytes) -> tuple[bytes, GenerateParams] | None:
    media_type = content_type.split(b";")[0].strip().lower()
    if media_type in XML_TYPES:
        pairs = parse_qsl(query.decode("latin-1"), keep_blank_values=True)
        query_params = dict(pairs)
        if len(query_params) != len(pairs) or not set(query_params) <= JSON_FIELDS - {"document"}:
            return None
        source = {"true": True, "false": False}.get(query_params.get("source", "true"))
        params = _plain(query_params.get("target", "glsl"), query_params.get("element"),
                        query_params.get("interface", "complete"), source)
        return (body, params) if params else None
    if media_type != b"application/json":
        return None
    try:
        # decoded first: json.loads would read UTF-16 and UTF-32 too, which the route's model refuses
        data = json.loads(body.decode())
    except (ValueError, RecursionError):  # RecursionError: arrays nested thousands deep
        return None
    if not (isinstance(data, dict) and isinstance(data.get("document"), str) and set(data) <= JSON_FIELDS):
        return None
    if not data["document"]:  # the model's min_length
        return None
    params = _plain(data.get("target", "glsl"), data.get("element"), data.get("interface", "complete"),
                    data.get("source", True))
    try:
        document = data["document"].encode()
    except UnicodeEncodeError:  # a lone surrogate: the route's model words the refusal
        return None
    return (document, params) if params else None


async def read_body(receive) -> tuple[bytes, list[dict]]:
    """The whole body, and the messages it came in (to replay them to the route)."""
    chunks, messages = [], []
    while True:
        message = await receive()
        messages.append(message)
        if message["type"] != "http.request":
            break
        chunks.append(message.get("body", b""))
        if not message.get("more_body"):
            break
    return b"".join(chunks), messages


class GenerateFastPath:
    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http" or scope["path"] != PATH or scope["method"] != "POST":
            return await self.app(scope, receive, send)
        body, messages = await read_body(receive)  # bounded in size and time by BodyLimitMiddleware
        services = getattr(scope["app"].state, "services", None)
        content_type = next((v for k, v in scope["headers"] if k == b"content-type"), b"application/json")
        parsed = parse(content_type, scope["query_string"], body)
        if services is not None and parsed is not None:
            scope[ROUTE_KEY] = PATH  # labelled in the metrics like the route's own answers
            try:
                record = await services.generation.generate(*parsed)
            except ServiceError as exc:  # the app's handler is the route's, not this middleware's
                return await error_response(exc)(scope, receive, send)
            await send({"type": "http.response.start", "status": 200,
                        "headers": [(b"content-type", b"application/json"),
                                    (b"content-length", str(len(record)).encode())]})
            await send({"type": "http.response.body", "body": record})
            return

        async def replay():
            return messages.pop(0) if messages else await receive()

        await self.app(scope, replay, send)
