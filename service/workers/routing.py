"""Render jobs routed by topology: each render worker keeps the programs it compiled (one per
topology), so a thumbnail goes to the worker that holds its program.

`HashRing`: consistent hashing of a job's topology hash over the workers' names (many points per
worker on a ring of SHA-256 values; a key belongs to the first point after it), so adding or losing
a worker moves only that worker's share of the topologies. `RoutedPools`: one single-process pool
(and queue) per render worker behind the ProcessPool interface the pool server uses; a job goes to
its topology's worker unless that worker is down (being replaced: its share goes to the next
workers on the ring until it is back) or already holds more than its share of the jobs in flight
and more than a compile's worth of them (bounded loads: one topology of a whole library must not
wait on one worker while the others idle). A job that was running when its worker died is run again by the pool that replaced it
(ProcessPool tries a crashed job twice), and the jobs queued behind it wait for the replacement:
none is lost.
"""
import bisect
import hashlib
import math

from .pool import ProcessPool

POINTS_PER_WORKER = 64  # a share within a few percent of 1/N for a handful of workers
LOAD_FACTOR = 1.25  # a worker takes a job while its load is within this of the mean (plus the new job)...
# ...or below this many jobs: a compile costs about as much as this many draws (a complete
# standard_surface: 3.4 s against 0.22 s at 64 px on llvmpipe), so waiting behind a few draws on
# the worker that holds the program is cheaper than compiling it on an idle one
SPILL_AT = 8


def _point(text: str) -> int:
    return int.from_bytes(hashlib.sha256(text.encode()).digest()[:8], "big")


class HashRing:
    def __init__(self, names: list[str], points: int = POINTS_PER_WORKER):
        ring = sorted((_point(f"{name}#{i}"), name) for name in names for i in range(points))
        self._points = [p for p, _ in ring]
        self._names = [n for _, n in ring]

    def order(self, key: str) -> list[str]:
        """Every worker once, in the order the ring meets them from `key`: its owner first, then
        who takes its share should the owner be down or full."""
        start = bisect.bisect(self._points, _point(key))
        seen: list[str] = []
        for k in range(len(self._names)):
            name = self._names[(start + k) % len(self._names)]
            if name not in seen:
                seen.append(name)
        return seen


def route_key(message: dict) -> str:
    """What a render job is routed by: its record's topology hash (its program), else its source."""
    record = message.get("record") or {}
    if record.get("topology_hash"):
        return record["topology_hash"]
    stages = record.get("stages") or {}
    return hashlib.sha256(repr(sorted(stages.items())).encode()).hexdigest()


class RoutedPools:
    """`size` ProcessPools of one child each, named render-0, render-1, ...; see the module."""

    def __init__(self, module: str, size: int, queue_size: int, timeout_s: float, **pool_options):
        self.names = [f"render-{i}" for i in range(size)]
        self.pools = {name: ProcessPool(module, 1, queue_size, timeout_s, **pool_options) for name in self.names}
        self.ring = HashRing(self.names)
        self.size = size
        self.limits = next(iter(self.pools.values())).limits
        self.routed = {name: 0 for name in self.names}  # jobs each worker was given

    async def start(self, wait: bool = True) -> None:
        for pool in self.pools.values():
            await pool.start(wait=wait)

    @property
    def depth(self) -> int:
        return sum(pool.depth for pool in self.pools.values())

    @property
    def alive(self) -> int:
        return sum(pool.alive for pool in self.pools.values())

    @property
    def answering(self) -> int:
        return sum(pool.answering for pool in self.pools.values())

    @property
    def hung(self) -> bool:
        return all(pool.hung for pool in self.pools.values())

    @staticmethod
    def _load(pool: ProcessPool) -> int:
        return pool.depth + sum(1 for child in pool.children if child is not None and child.busy)

    def choose(self, key: str) -> str:
        """The worker for a job of `key`: the first on the ring from it that is up and within its
        bounded share of the load; the first that is up if all are full; its owner if none is up
        (its queue waits for the replacement)."""
        order = self.ring.order(key)
        up = [name for name in order if self.pools[name].alive]
        if not up:
            return order[0]
        total = sum(self._load(self.pools[name]) for name in up)
        bound = max(SPILL_AT, math.ceil(LOAD_FACTOR * (total + 1) / len(up)))
        return next((name for name in up if self._load(self.pools[name]) < bound), up[0])

    def submit(self, message: dict, payload: bytes = b"", job_id: str | None = None, attempts: int = 0):
        name = self.choose(route_key(message))
        job = self.pools[name].submit(message, payload, job_id=job_id, attempts=attempts)
        self.routed[name] += 1
        return job

    async def close(self) -> None:
        for pool in self.pools.values():
            await pool.close()
