"""Load test of the HTTP service on this machine: concurrent clients against a live
`shadergen serve` on 127.0.0.1, cached and uncached, for /v1/generate and /v1/thumbnails.
Prints requests/s, p50/p99 latency and errors per scenario, and each p50 as a ratio of the
/healthz p50 measured in the same run (these machines are noisy; ratios travel better).

    .venv/bin/python bench/load.py                     # starts its own server (2 API workers)
    .venv/bin/python bench/load.py --url http://127.0.0.1:8000 --seconds 5

Clients speak HTTP/1.1 with keep-alive over raw asyncio streams, so the client's own cost per
request stays small next to the server's. Every scenario is bounded in time and in requests."""
import argparse
import asyncio
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import urlsplit

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "tests" / "service" / "documents"
MAX_REQUESTS = 200_000


def ramp(value: float) -> str:
    return (DOCS / "ramp.mtlx").read_text().replace('value="0.5"', f'value="{value!r}"')


def request_bytes(host: str, method: str, path: str, body: dict | None = None) -> bytes:
    payload = json.dumps(body).encode() if body is not None else b""
    head = f"{method} {path} HTTP/1.1\r\nHost: {host}\r\nContent-Length: {len(payload)}\r\n"
    if body is not None:
        head += "Content-Type: application/json\r\n"
    return (head + "\r\n").encode() + payload


@dataclass
class Result:
    name: str
    clients: int
    latencies: list[float] = field(default_factory=list)
    errors: int = 0
    seconds: float = 0.0
    statuses: dict[int, int] = field(default_factory=dict)


async def one_request(reader, writer, data: bytes) -> int:
    writer.write(data)
    head = await reader.readuntil(b"\r\n\r\n")
    status = int(head[9:12])
    length = 0
    for line in head.split(b"\r\n")[1:]:
        if line[:15].lower() == b"content-length:":
            length = int(line[15:])
    await reader.readexactly(length)
    return status


async def client(host: str, port: int, requests: list[bytes], offset: int, stride: int, deadline: float,
                 result: Result, budget: list[int]) -> None:
    reader, writer = await asyncio.open_connection(host, port)
    i = offset
    try:
        while time.perf_counter() < deadline and budget[0] > 0:
            budget[0] -= 1
            data = requests[i % len(requests)]
            i += stride
            started = time.perf_counter()
            try:
                status = await one_request(reader, writer, data)
            except (asyncio.IncompleteReadError, ConnectionError):
                result.errors += 1
                writer.close()
                reader, writer = await asyncio.open_connection(host, port)
                continue
            result.latencies.append(time.perf_counter() - started)
            result.statuses[status] = result.statuses.get(status, 0) + 1
            if status >= 300:
                result.errors += 1
    finally:
        writer.close()


async def scenario(name: str, host: str, port: int, requests: list[bytes], clients: int, seconds: float,
                   max_requests: int = MAX_REQUESTS) -> Result:
    result = Result(name, clients)
    budget = [max_requests]
    started = time.perf_counter()
    await asyncio.gather(*(client(host, port, requests, k, clients, started + seconds, result, budget)
                           for k in range(clients)))
    result.seconds = time.perf_counter() - started
    return result


async def warm(host: str, port: int, requests: list[bytes]) -> None:
    reader, writer = await asyncio.open_connection(host, port)
    try:
        for data in requests:
            status = await one_request(reader, writer, data)
            if status >= 300:
                raise SystemExit(f"warm-up request failed with {status}")
    finally:
        writer.close()


def percentile(values: list[float], q: float) -> float:
    if not values:
        return float("nan")
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def start_server(workers: int, render_workers: int) -> tuple[subprocess.Popen, str, Path]:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    tmp = Path(tempfile.mkdtemp(prefix="shadergen-bench-"))
    env = {**os.environ, "SHADERGEN_CACHE": f"sqlite:///{tmp / 'cache.sqlite3'}",
           "SHADERGEN_TEXTURE_ROOTS": str(DOCS)}
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

    tag = time.time_ns()  # fresh values each run: "uncached" must miss even on a reused server
    unique = [ramp(0.5 + (tag % 10**9) * 1e-12 + i * 1e-6) for i in range(MAX_REQUESTS // 20)]
    cached_gen, cached_thumb = [gen(ramp(0.5))], [thumb(ramp(0.5), args.size)]
    await warm(host, port, cached_gen + cached_thumb)
    healthz = [request_bytes(hostport, "GET", "/healthz")]
    plan = [
        ("GET /healthz (baseline)", healthz, args.clients),
        ("generate cached", cached_gen, args.clients),
        ("generate uncached", [gen(d) for d in unique], args.clients),
        ("thumbnails cached", cached_thumb, args.clients),
        (f"thumbnails uncached ({args.size} px)", [thumb(d, args.size) for d in unique[len(unique) // 2:]],
         args.render_clients),
    ]
    results = []
    for name, requests, clients in plan:
        results.append(await scenario(name, host, port, requests, clients, args.seconds))
        await asyncio.sleep(0.5)
    return results


def table(results: list[Result]) -> str:
    base = percentile(results[0].latencies, 0.5)
    rows = [("scenario", "clients", "requests", "errors", "req/s", "p50 ms", "p99 ms", "p50 / baseline")]
    for r in results:
        p50, p99 = percentile(r.latencies, 0.5), percentile(r.latencies, 0.99)
        rows.append((r.name, str(r.clients), str(len(r.latencies)), str(r.errors),
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
    print(f"server {args.url}, {os.cpu_count()} cores, {args.seconds:g} s per scenario\n")
    print(table(results))
    for r in results:
        odd = {s: n for s, n in r.statuses.items() if s >= 300}
        if odd:
            print(f"{r.name}: statuses {odd}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
