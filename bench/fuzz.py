"""Long fuzz runs against a live `shadergen serve` on 127.0.0.1 (which this starts and stops):
every case of a kind is sent, and every answer must keep the contract (no 5xx; a refusal is the
error object with a code, a message and a where). Prints each case that broke it, then one line:

    fuzz: N cases | 5xx 0 | max time X s | max child RSS Y MiB

(`max time`: the slowest answer; `max child RSS`: the largest peak resident size any generator
child reached during the run), after a line of how many answers had each status. Exits 1 when a
case broke the contract.

    .venv/bin/python bench/fuzz.py --kind crate --cases 2000 --seed 21

Kinds (KINDS): `crate`, real .usdc files truncated and with bytes flipped, each the root layer of
a usdz upload (tests/fuzz_testing.py, which the fault test in tests/faults shares); `names`,
MaterialX and USD documents of hostile names (Unicode, digits first, every target's reserved and
built-in words, names that collide once cleaned), each sent for glsl, essl and wgsl in complete and
specialized, every record compiled by its target's checker (tests/name_cases.py, which
tests/core/test_name_fuzz.py shares). A kind is its
case generator (count, seed -> (label, case) pairs), its runner (client, case -> an answer with a
status_code) and its judge (answer -> why it broke the contract, or None).
"""
import argparse
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import NamedTuple

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests"), str(ROOT / "tests" / "service")]

from fuzz_testing import USDZ, ChildPeakMemory, crate_cases, judge  # noqa: E402
from name_cases import http_cases, judge_answer, post_case  # noqa: E402
from service_testing import Server  # noqa: E402

ANSWER_TIMEOUT_S = 120  # a case unanswered by then counts as broken (the client gives up)


class Kind(NamedTuple):
    cases: Callable[[int, int], Iterator[tuple[str, object]]]  # (count, seed) -> (label, case) pairs
    run: Callable[[object, object], object]  # (client, case) -> an answer with a status_code
    judge: Callable[[object], str | None]  # answer -> why it broke the contract, None when it kept it


def post_usdz(client, body: bytes):
    return client.post("/v1/generate", content=body, headers=USDZ, timeout=ANSWER_TIMEOUT_S)


KINDS: dict[str, Kind] = {
    "crate": Kind(crate_cases, post_usdz, judge),
    "names": Kind(http_cases, post_case, judge_answer),
}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--kind", choices=sorted(KINDS), default="crate")
    parser.add_argument("--cases", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=21)
    parser.add_argument("--clients", type=int, default=2, help="cases in flight at once")
    parser.add_argument("--workers", type=int, default=2, help="the server's API workers")
    args = parser.parse_args()
    kind = KINDS[args.kind]
    with tempfile.TemporaryDirectory(prefix="shadergen-fuzz-") as folder:
        server = Server(Path(folder), workers=args.workers, render_workers=1)
        try:
            broken, statuses, slowest = [], Counter(), 0.0

            def one(case):
                label, body = case
                started = time.monotonic()
                try:
                    response = kind.run(server.client, body)
                except Exception as exc:  # a time-out or a dropped connection: the contract broken
                    return label, time.monotonic() - started, None, f"no answer: {type(exc).__name__}: {exc}"
                return label, time.monotonic() - started, response.status_code, kind.judge(response)

            with ChildPeakMemory(server.proc.pid) as memory, ThreadPoolExecutor(args.clients) as pool:
                for label, seconds, status, why in pool.map(one, kind.cases(args.cases, args.seed)):
                    slowest = max(slowest, seconds)
                    statuses[status or "none"] += 1
                    if why:
                        broken.append(label)
                        print(f"{label}: {why}", flush=True)
        finally:
            server.close()
    print("statuses: " + ", ".join(f"{status} x {n}" for status, n in sorted(statuses.items(), key=str)))
    five_xx = sum(n for status, n in statuses.items() if status != "none" and status >= 500)
    print(f"fuzz: {args.cases} cases | 5xx {five_xx} | max time {slowest:.2f} s | "
          f"max child RSS {memory.peak_mib:.0f} MiB")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
