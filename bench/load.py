"""Load test of the HTTP service on this machine: concurrent clients against a live
`shadergen serve` on 127.0.0.1, cached and uncached, for /v1/generate and /v1/thumbnails.
Prints requests/s, p50/p99 latency, errors and record cache hits (of the answers that are shader
records, those that say "cached": true) per scenario, and each p50 as a ratio of the /healthz p50
measured in the same run (these machines are noisy; ratios travel better). Uncached scenarios send
a document no earlier request of the run sent, every time: their hits must be 0.

    .venv/bin/python bench/load.py                     # starts its own server (2 API workers)
    .venv/bin/python bench/load.py --url http://127.0.0.1:8000 --seconds 5

Clients speak HTTP/1.1 with keep-alive over raw asyncio streams, so the client's own cost per
request stays small next to the server's. Every scenario is bounded in time and in requests.

The last pair of scenarios measures what clients sending expensive bad documents (issue 8: deep
XML and JSON, self-inheriting nodedefs, self-instantiating graphs, undecodable encodings, ...)
cost everyone else: three quarters of the clients send uncached documents, alone and then beside
a quarter that send the bad ones; the pair runs twice, interleaved, and the well-behaved clients'
p50/p99 beside the bad ones are printed as ratios of their p50/p99 alone (goal: within 2x). The bad
clients connect from another loopback address (127.0.0.2), as another machine would, and send
again as soon as they are answered, Retry-After or not."""
import argparse
import asyncio
import itertools
import json
import multiprocessing
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import urlsplit

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "tests" / "service" / "documents"
MAX_REQUESTS = 200_000
# how a record (compact JSON) says whether it came from the cache; thumbnails and others say neither
CACHED, NOT_CACHED = b'"cached":true', b'"cached":false'
BAD_CLIENT_ADDRESS = "127.0.0.2"


def ramp(value: float) -> str:
    return (DOCS / "ramp.mtlx").read_text().replace('value="0.5"', f'value="{value!r}"')


def request_bytes(host: str, method: str, path: str, body: dict | None = None) -> bytes:
    return raw_request(host, method, path, json.dumps(body).encode() if body is not None else None)


def raw_request(host: str, method: str, path: str, payload: bytes | None,
                content_type: str = "application/json") -> bytes:
    head = f"{method} {path} HTTP/1.1\r\nHost: {host}\r\nContent-Length: {len(payload or b'')}\r\n"
    if payload is not None:
        head += f"Content-Type: {content_type}\r\n"
    return (head + "\r\n").encode() + (payload or b"")


def bad_documents(host: str) -> list[bytes]:
    """Cheap to send, once expensive to refuse (issue 8); each must get a 4xx, cheaply."""
    def xml(text: str) -> bytes:
        return raw_request(host, "POST", "/v1/generate", text.encode(), "application/xml")

    head = '<?xml version="1.0"?><materialx version="1.39">'
    return [
        xml(head + '<nodedef name="ND_a" node="a" inherit="ND_a"><output name="out" type="float"/></nodedef>'
            '<a name="n" type="float"/><output name="o" type="float" nodename="n"/></materialx>'),
        xml(head + '<nodedef name="ND_a" node="a" inherit="ND_b"><output name="out" type="float"/></nodedef>'
            '<nodedef name="ND_b" node="b" inherit="ND_a"><output name="out" type="float"/></nodedef>'
            '<a name="n" type="float"/><output name="o" type="float" nodename="n"/></materialx>'),
        xml(head + '<nodedef name="ND_loop" node="loop"><output name="out" type="float"/></nodedef>'
            '<nodegraph name="NG_loop" nodedef="ND_loop"><loop name="inner" type="float"/>'
            '<output name="out" type="float" nodename="inner"/></nodegraph>'
            '<loop name="n" type="float"/><output name="o" type="float" nodename="n"/></materialx>'),
        xml('<materialx version="1.39">' + "<a>" * 200_000 + "</a>" * 200_000 + "</materialx>"),
        raw_request(host, "POST", "/v1/generate", b'{"document": ' + b"[" * 100_000 + b"]" * 100_000 + b"}"),
        xml('<?xml version="1.0" encoding="x-bogus"?><materialx version="1.39"/>'),
        request_bytes(host, "POST", "/v1/generate", {"document": head + "\ud800</materialx>"}),
    ]


@dataclass
class Result:
    name: str
    clients: int
    latencies: list[float] = field(default_factory=list)
    errors: int = 0
    seconds: float = 0.0
    statuses: dict[int, int] = field(default_factory=dict)
    refusals_expected: bool = False  # bad documents: a 4xx is the right answer, not an error
    records: int = 0  # answers that are shader records (JSON), which say whether they came from the cache
    hits: int = 0  # records with "cached": true

    def failed(self, status: int) -> bool:
        return status >= 300 and not (self.refusals_expected and 400 <= status < 500)


async def one_request(reader, writer, data: bytes) -> tuple[int, bool, bool | None]:
    """(the status, whether the server closes the connection after this answer, whether the answer
    is a record served from the cache: None when it is no record)."""
    writer.write(data)
    head = await reader.readuntil(b"\r\n\r\n")
    status = int(head[9:12])
    length, closes = 0, False
    for line in head.split(b"\r\n")[1:]:
        name, _, value = line.partition(b":")
        name = name.lower()
        if name == b"content-length":
            length = int(value)
        elif name == b"connection":
            closes = b"close" in value.lower()
    body = await reader.readexactly(length)
    return status, closes, True if CACHED in body else False if NOT_CACHED in body else None


class Fresh:
    """Requests no earlier request of the run has sent, made as they are sent, from a counter all
    Fresh series share: an uncached scenario misses the cache however many requests its window
    holds (a fixed list, cycled, would come round to documents it had already sent)."""
    counter = itertools.count()

    def __init__(self, make: Callable[[int], bytes]):
        self.make = make

    def __next__(self) -> bytes:
        return self.make(next(self.counter))


Requests = list[bytes] | Fresh


async def client(host: str, port: int, requests: Requests, offset: int, stride: int, deadline: float,
                 result: Result, budget: list[int], local_addr: tuple[str, int] | None = None) -> None:
    reader, writer = await asyncio.open_connection(host, port, local_addr=local_addr)
    i = offset
    try:
        while time.perf_counter() < deadline and budget[0] > 0:
            budget[0] -= 1
            data = next(requests) if isinstance(requests, Fresh) else requests[i % len(requests)]
            i += stride
            started = time.perf_counter()
            try:
                status, closes, cached = await one_request(reader, writer, data)
            except (asyncio.IncompleteReadError, ConnectionError):
                result.errors += 1
                writer.close()
                reader, writer = await asyncio.open_connection(host, port, local_addr=local_addr)
                continue
            result.latencies.append(time.perf_counter() - started)
            result.statuses[status] = result.statuses.get(status, 0) + 1
            if cached is not None:
                result.records += 1
                result.hits += cached
            if result.failed(status):
                result.errors += 1
            if closes:  # as any HTTP client does: the next request goes on a new connection
                writer.close()
                reader, writer = await asyncio.open_connection(host, port, local_addr=local_addr)
    finally:
        writer.close()


async def mixed(host: str, port: int, groups: list[tuple[Result, Requests]], seconds: float,
                max_requests: int = MAX_REQUESTS, local_addr: tuple[str, int] | None = None) -> list[Result]:
    """Groups of clients at once, each group with its own requests and its own Result."""
    budget = [max_requests]
    started = time.perf_counter()
    await asyncio.gather(*(client(host, port, requests, k, result.clients, started + seconds, result, budget,
                                  local_addr)
                           for result, requests in groups for k in range(result.clients)))
    for result, _ in groups:
        result.seconds = time.perf_counter() - started
    return [result for result, _ in groups]


async def scenario(name: str, host: str, port: int, requests: Requests, clients: int, seconds: float) -> Result:
    return (await mixed(host, port, [(Result(name, clients), requests)], seconds))[0]


def merged(name: str, parts: list[Result]) -> Result:
    """Runs of one scenario taken as one (interleaved repeats of a pair)."""
    result = Result(name, parts[0].clients, refusals_expected=parts[0].refusals_expected)
    for part in parts:
        result.latencies += part.latencies
        result.errors += part.errors
        result.seconds += part.seconds
        result.records += part.records
        result.hits += part.hits
        for status, count in part.statuses.items():
            result.statuses[status] = result.statuses.get(status, 0) + count
    return result


async def warm(host: str, port: int, requests: list[bytes]) -> None:
    reader, writer = await asyncio.open_connection(host, port)
    try:
        for data in requests:
            status, _, _ = await one_request(reader, writer, data)
            if status >= 300:
                raise SystemExit(f"warm-up request failed with {status}")
    finally:
        writer.close()


def percentile(values: list[float], q: float) -> float:
    if not values:
        return float("nan")
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def start_server(workers: int, render_workers: int, env: dict[str, str] | None = None
                 ) -> tuple[subprocess.Popen, str, Path]:
    """A server on a free port with a fresh cache; `env`: further settings (SHADERGEN_*)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    tmp = Path(tempfile.mkdtemp(prefix="shadergen-bench-"))
    env = {**os.environ, "SHADERGEN_CACHE": f"sqlite:///{tmp / 'cache.sqlite3'}",
           "SHADERGEN_TEXTURE_ROOTS": str(DOCS), **(env or {})}
    log = open(tmp / "serve.log", "wb")
    proc = subprocess.Popen([sys.executable, "-m", "shadergen.cli", "serve", "--host", "127.0.0.1",
                             "--port", str(port), "--workers", str(workers), "--render-workers", str(render_workers)],
                            cwd=ROOT, env=env, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise SystemExit(f"server exited: {(tmp / 'serve.log').read_text()[-2000:]}")
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=1) as s:
                s.sendall(b"GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n")
                if s.recv(12).endswith(b"200"):
                    return proc, url, tmp
        except OSError:
            pass
        time.sleep(0.2)
    proc.terminate()
    raise SystemExit("server did not start")


async def run(args) -> list[Result]:
    parts = urlsplit(args.url)
    host, port = parts.hostname, parts.port
    if host not in ("127.0.0.1", "localhost", "::1"):
        raise SystemExit("bench/load.py only loads servers on this machine (127.0.0.1)")
    hostport = f"{host}:{port}"

    def gen(doc: str) -> bytes:
        return request_bytes(hostport, "POST", "/v1/generate", {"document": doc})

    def thumb(doc: str, size: int) -> bytes:
        return request_bytes(hostport, "POST", "/v1/thumbnails", {"document": doc, "size": size})

    # fresh values each run ("uncached" must miss even on a reused server): the run's tag lies below
    # the step between values, so two runs cannot meet
    tag = (time.time_ns() % 10**6) * 1e-13

    def fresh(n: int) -> str:
        return ramp(0.25 + n * 1e-7 + tag)

    cached_gen, cached_thumb = [gen(ramp(0.5))], [thumb(ramp(0.5), args.size)]
    await warm(host, port, cached_gen + cached_thumb)
    healthz = [request_bytes(hostport, "GET", "/healthz")]
    plan = [
        ("GET /healthz (baseline)", healthz, args.clients),
        ("generate cached", cached_gen, args.clients),
        ("generate uncached", Fresh(lambda n: gen(fresh(n))), args.clients),
        ("thumbnails cached", cached_thumb, args.clients),
        (f"thumbnails uncached ({args.size} px)", Fresh(lambda n: thumb(fresh(n), args.size)), args.render_clients),
    ]
    results = []
    for name, requests, clients in plan:
        results.append(await scenario(name, host, port, requests, clients, args.seconds))
        await asyncio.sleep(0.5)
    return results + await beside_bad_clients(host, port, args.clients, args.seconds, Fresh(lambda n: gen(fresh(n))))


def bad_clients_process(host: str, port: int, clients: int, seconds: float) -> tuple:
    """The bad clients, run in a process of their own (as other machines would be): in the
    measuring process their sends and reads would delay the well-behaved clients' own timing."""
    local_addr = (BAD_CLIENT_ADDRESS, 0) if host == "127.0.0.1" else None  # another client to the server
    result = asyncio.run(mixed(host, port, [(Result("", clients, refusals_expected=True),
                                             bad_documents(f"{host}:{port}"))], seconds, local_addr=local_addr))[0]
    return result.latencies, result.errors, result.seconds, result.statuses


async def beside_bad_clients(host: str, port: int, clients: int, seconds: float, fresh: Fresh) -> list[Result]:
    bad_clients = max(1, clients // 4)
    good_clients = clients - bad_clients
    alone, beside, refused = [], [], []
    loop = asyncio.get_running_loop()
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        for repeat in range(2):  # interleaved: alone, beside, alone, beside
            alone += await mixed(host, port, [(Result("", good_clients), fresh)], seconds)
            await asyncio.sleep(0.5)
            bad_run = loop.run_in_executor(None, pool.apply, bad_clients_process, (host, port, bad_clients, seconds))
            beside += await mixed(host, port, [(Result("", good_clients), fresh)], seconds)
            latencies, errors, ran_s, statuses = await bad_run
            refused.append(Result("", bad_clients, latencies, errors, ran_s, statuses, refusals_expected=True))
            await asyncio.sleep(0.5)
    return [merged("generate uncached, alone", alone),
            merged(f"generate uncached, beside {bad_clients} bad clients", beside),
            merged("bad documents (4xx expected)", refused)]


def table(results: list[Result]) -> str:
    base = percentile(results[0].latencies, 0.5)
    rows = [("scenario", "clients", "requests", "record hits", "errors", "req/s", "p50 ms", "p99 ms", "p50 / baseline")]
    for r in results:
        p50, p99 = percentile(r.latencies, 0.5), percentile(r.latencies, 0.99)
        rows.append((r.name, str(r.clients), str(len(r.latencies)), f"{r.hits}/{r.records}" if r.records else "-",
                     str(r.errors),
                     f"{len(r.latencies) / r.seconds:.0f}", f"{p50 * 1e3:.2f}", f"{p99 * 1e3:.2f}",
                     f"{p50 / base:.1f}x"))
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    lines = ["| " + " | ".join(c.ljust(w) for c, w in zip(row, widths)) + " |" for row in rows]
    lines.insert(1, "|" + "|".join("-" * (w + 2) for w in widths) + "|")
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--url", help="a running server on this machine (default: start one)")
    parser.add_argument("--workers", type=int, default=2, help="API workers of the server started here")
    parser.add_argument("--render-workers", type=int, default=1)
    parser.add_argument("--clients", type=int, default=32)
    parser.add_argument("--render-clients", type=int, default=8,
                        help="clients for uncached thumbnails (the render queue holds 16 by default)")
    parser.add_argument("--size", type=int, default=128, help="thumbnail size")
    parser.add_argument("--seconds", type=float, default=10.0, help="per scenario")
    args = parser.parse_args()
    proc = tmp = None
    load_before = os.getloadavg()
    if args.url is None:
        proc, args.url, tmp = start_server(args.workers, args.render_workers)
    try:
        try:
            import uvloop

            uvloop.install()
        except ImportError:
            pass
        results = asyncio.run(run(args))
    finally:
        if proc is not None:
            proc.terminate()
            proc.wait(30)
            shutil.rmtree(tmp, ignore_errors=True)
    # other work on the machine shows in every figure: the load it was measured under goes with them
    loads = " -> ".join("/".join(f"{x:.1f}" for x in load) for load in (load_before, os.getloadavg()))
    print(f"server {args.url}, {os.cpu_count()} cores, load average (1/5/15 min) {loads}, "
          f"{args.seconds:g} s per scenario\n")
    print(table(results))
    alone, beside = results[-3], results[-2]
    ratios = [percentile(beside.latencies, q) / percentile(alone.latencies, q) for q in (0.5, 0.99)]
    print(f"\nwell-behaved clients beside bad ones, against alone: p50 {ratios[0]:.2f}x, "
          f"p99 {ratios[1]:.2f}x (goal: within 2x)")
    for r in results:
        odd = {s: n for s, n in r.statuses.items() if s >= 300}
        if odd:
            print(f"{r.name}: statuses {odd}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
