"""Fair shares beside clients whose requests keep failing.

Every refusal costs the server something (reading the body, the upload checks, the lookup of a
refusal it gave before), and a client that sends bad documents in a loop spends that again as soon
as each answer leaves. On a machine of a few cores that CPU is taken from the generator processes
that serve everyone else: bench/load.py measured the well-behaved clients' p99 ten times higher
beside eight such clients, with no request of theirs failing.

So each API worker keeps a ledger of failures per client address, a token bucket: a client may
fail `burst` times in a row, and then `rate` times a second. A client whose bucket is empty is
served once a token is back: its request waits (without its body being read) up to `hold_s` for
one, and if none comes in that time it is refused with 429 `too_many_failures` and Retry-After.
A client that ignores Retry-After and sends again at once thus costs a timer per connection and
hold, not a loop of cheap refusals at thousands a second; a client that fails now and then, or
waits as told, never notices the ledger. A request served on a token that did not fail gives it
back: only failures are rationed.

Only the API's work is rationed (paths under /v1/): health probes, metrics scrapes and the
editor's static files always answer. What counts as a failure is a 4xx the request caused, except
404 (asking for a shader or job that is not there is a normal question) and 429 (the ledger's own
refusals must not deepen the debt, or a client could never get out of it); the server's own
failures (5xx: a time-out is 504, a hung or busy pool 503) are never the client's. The address is the connection's peer, or behind a reverse
proxy the one its X-Forwarded-For names, believed only from the proxies the operator names in
SHADERGEN_TRUSTED_PROXIES (none by default: see service/cli.py). Each API worker keeps its own
ledger, so nothing is shared on the hot path; a client's allowance is per worker."""
import asyncio
import math
import time
from collections import OrderedDict
from dataclasses import dataclass

from .asgi import StatusRecorder
from .errors import ServiceError, error_response
from .limits import declares_body
from .metrics import RATIONED

RATIONED_PREFIX = "/v1/"
NOT_FAILURES = frozenset((404, 429))
# a loop's timers may fire a millisecond early (libuv keeps time in ms): a request held until its
# token is due sleeps this much more, so that it finds the token there
TIMER_SLACK_S = 0.005
MAX_CLIENTS = 100_000  # bound on the ledger: the clients that failed least recently are forgotten first


def is_failure(status: int) -> bool:
    return 400 <= status < 500 and status not in NOT_FAILURES


@dataclass
class Bucket:
    tokens: float
    updated: float


class FailureLedger:
    """Token buckets of failures, by client address; only clients that failed have one."""

    def __init__(self, burst: int, rate: float, clock=time.monotonic):
        self.burst, self.rate, self.clock = burst, rate, clock
        self._buckets: OrderedDict[str, Bucket] = OrderedDict()

    def _bucket(self, client: str) -> Bucket | None:
        bucket = self._buckets.get(client)
        if bucket is not None:
            now = self.clock()
            bucket.tokens = min(self.burst, bucket.tokens + (now - bucket.updated) * self.rate)
            bucket.updated = now
        return bucket

    def take(self, client: str) -> tuple[bool, float]:
        """(whether the request may go on holding a token, seconds until one is back if not).
        A client with no bucket goes on without taking anything."""
        bucket = self._bucket(client)
        if bucket is None:
            return False, 0.0
        if bucket.tokens >= 1:
            bucket.tokens -= 1
            return True, 0.0
        return False, (1 - bucket.tokens) / self.rate

    def settle(self, client: str, held_token: bool, failed: bool) -> None:
        """A request ended: a failure costs a token (the one it held, else one now), a success
        gives back the token it held. A bucket full again is forgotten."""
        if held_token == failed:
            return  # failed on its token, or succeeded holding none
        bucket = self._bucket(client)
        if bucket is None:
            bucket = self._buckets[client] = Bucket(self.burst, self.clock())
            if len(self._buckets) > MAX_CLIENTS:
                self._buckets.popitem(last=False)
        # a failure may run into debt (requests in flight when the tokens ran out), at most a burst deep
        bucket.tokens = max(-self.burst, bucket.tokens - 1) if failed else bucket.tokens + 1
        self._buckets.move_to_end(client)
        if bucket.tokens >= self.burst:
            del self._buckets[client]


class FairnessMiddleware:
    def __init__(self, app, ledger: FailureLedger, hold_s: float):
        self.app, self.ledger, self.hold_s = app, ledger, hold_s

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http" or not scope.get("client") or not scope["path"].startswith(RATIONED_PREFIX):
            return await self.app(scope, receive, send)
        client = scope["client"][0]
        held_token, wait_s = self.ledger.take(client)
        if wait_s > 0:
            await asyncio.sleep(min(wait_s + TIMER_SLACK_S, self.hold_s))
            held_token, wait_s = self.ledger.take(client)
            if wait_s > 0:
                RATIONED.labels("refused").inc()
                return await self._refuse(client, wait_s, scope, receive, send)
            RATIONED.labels("served").inc()
        recorder = StatusRecorder(send)
        try:
            await self.app(scope, receive, recorder)
        finally:
            self.ledger.settle(client, held_token, is_failure(recorder.status))

    async def _refuse(self, client: str, wait_s: float, scope, receive, send) -> None:
        retry_after = max(1, math.ceil(wait_s))
        headers = {"Retry-After": str(retry_after)}
        if declares_body(scope["headers"])[0]:
            headers["Connection"] = "close"  # the body was never read: the connection cannot carry another request
        exc = ServiceError("too_many_failures",
                           f"too many requests from {client} failed recently (more than {self.ledger.burst}, then "
                           f"{self.ledger.rate:g} a second): retry after {retry_after} s", headers=headers)
        await error_response(exc)(scope, receive, send)
