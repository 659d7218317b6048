#!/usr/bin/env python3
"""An editing session against live servers (issue 11): --requests edits of one material, each
changing one value, each sent as POST /v1/generate and then POST /v1/thumbnails, both in the
`complete` interface (every input live), as an editor dragging sliders does. Two servers run side by side on 127.0.0.1, each with its own fresh cache:
one with topology sharing (the default: an edit gets the earlier source rebound to its values,
and the render worker draws it with the program it compiled already) and one started with
SHADERGEN_TOPOLOGY_SHARING=false (every edit is emitted and every thumbnail compiles). The two
are sent the same edits, interleaved edit by edit (which server goes first alternates). Prints
p50/p99 of each request kind with the ratio shared / not shared, and the servers' program counts.
Before the session each server draws the unedited material once, untimed (a render worker's
first job creates its GL context).

  .venv/bin/python bench/editing.py ../shared/corpus/resources/Materials/Examples [--requests 200] [--size 128]
"""
import argparse
import http.client
import json
import os
import shutil
import time
from urllib.parse import urlsplit

from load import percentile, start_server
from topology import edits

MODES = {"shared topology": {}, "no sharing": {"SHADERGEN_TOPOLOGY_SHARING": "false"}}
# Mesa's own on-disk cache would hand the no-sharing server the program of an earlier edit of the
# same source: what a compile costs is measured with it off, on both servers; and a loaded machine
# may take longer than the service's default minute to compile and draw a thumbnail.
SERVER_ENV = {"MESA_SHADER_CACHE_DISABLE": "true", "SHADERGEN_RENDER_TIMEOUT_S": "300"}


class Client:
    """One keep-alive HTTP/1.1 connection to a server on this machine."""

    def __init__(self, url: str):
        parts = urlsplit(url)
        self.connection = http.client.HTTPConnection(parts.hostname, parts.port, timeout=600)

    def post(self, path: str, body: dict) -> tuple[float, bytes]:
        for attempt in (1, 2):  # the server closes a connection idle past its keep-alive: open it again
            started = time.perf_counter()
            try:
                self.connection.request("POST", path, json.dumps(body), {"Content-Type": "application/json"})
                response = self.connection.getresponse()
                payload = response.read()
                break
            except (ConnectionError, http.client.RemoteDisconnected):
                self.connection.close()
                if attempt == 2:
                    raise
        elapsed = (time.perf_counter() - started) * 1e3
        if response.status != 200:
            raise SystemExit(f"{path} answered {response.status}: {payload[:500]!r}")
        return elapsed, payload

    def metrics(self) -> str:
        self.connection.request("GET", "/metrics")
        return self.connection.getresponse().read().decode()


def program_counts(metrics: str) -> dict[str, float]:
    """shadergen_programs_total by result, from the Prometheus text."""
    counts = {}
    for line in metrics.splitlines():
        if line.startswith("shadergen_programs_total{"):
            labels, value = line.rsplit(" ", 1)
            counts[labels.split('result="')[1].split('"')[0]] = float(value)
    return counts


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("examples", help="the Examples folder of the corpus")
    ap.add_argument("--material", default="StandardSurface/standard_surface_carpaint.mtlx")
    ap.add_argument("--requests", type=int, default=200)
    ap.add_argument("--size", type=int, default=128, help="thumbnail size")
    args = ap.parse_args()
    text = open(os.path.join(args.examples, args.material)).read()
    servers = {}
    try:
        for mode, env in MODES.items():
            servers[mode] = start_server(1, 1, {**SERVER_ENV, **env})
        clients = {mode: Client(url) for mode, (_, url, _) in servers.items()}
        for client in clients.values():  # not timed: a render worker's first job starts its GL context
            client.post("/v1/thumbnails", {"document": text, "size": args.size, "interface": "complete"})
        times = {mode: {"generate": [], "thumbnail": []} for mode in MODES}
        for i, document in enumerate(edits(text, args.requests)):
            order = list(MODES) if i % 2 == 0 else list(reversed(MODES))
            thumbnail = {"document": document, "size": args.size, "interface": "complete"}
            for mode in order:
                generate_ms, _ = clients[mode].post("/v1/generate", {"document": document})
                thumbnail_ms, _ = clients[mode].post("/v1/thumbnails", thumbnail)
                times[mode]["generate"].append(generate_ms)
                times[mode]["thumbnail"].append(thumbnail_ms)
        counts = {mode: program_counts(client.metrics()) for mode, client in clients.items()}
    finally:
        for proc, _, tmp in servers.values():
            proc.terminate()
            proc.wait(30)
            shutil.rmtree(tmp, ignore_errors=True)
    print(f"editing session: {args.requests} edits of {os.path.basename(args.material)}, one value each, "
          f"thumbnails {args.size}x{args.size}, two servers (1 API worker, 1 render worker each), interleaved")
    print("programs compiled/reused by the render workers: "
          + "; ".join(f"{mode}: {counts[mode]}" for mode in MODES))
    print("| ms | shared topology | no sharing | ratio |\n| --- | --- | --- | --- |")
    for step in ("generate", "thumbnail"):
        for name, q in (("p50", 0.5), ("p99", 0.99)):
            shared, alone = (percentile(times[mode][step], q) for mode in MODES)
            print(f"| {step} {name} | {shared:.1f} | {alone:.1f} | {shared / alone:.2f} |")


if __name__ == "__main__":
    main()
