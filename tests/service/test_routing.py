"""Consistent hashing of render jobs over render workers (service/workers/routing.py): each
worker owns a share of the topologies near 1/N, adding a worker moves only the share it takes, and
losing one moves only its own share, each topology to the worker after it on the ring."""
import hashlib

from service.workers.routing import HashRing, RoutedPools, route_key

KEYS = [hashlib.sha256(str(i).encode()).hexdigest() for i in range(3000)]
NAMES = ["render-0", "render-1", "render-2"]


def owners(ring: HashRing) -> dict[str, str]:
    return {key: ring.order(key)[0] for key in KEYS}


def test_each_worker_owns_about_a_third():
    counts = {}
    for owner in owners(HashRing(NAMES)).values():
        counts[owner] = counts.get(owner, 0) + 1
    assert set(counts) == set(NAMES)
    assert all(abs(c / len(KEYS) - 1 / 3) < 0.1 for c in counts.values()), counts


def test_adding_a_worker_moves_only_what_it_takes():
    before, after = owners(HashRing(NAMES)), owners(HashRing(NAMES + ["render-3"]))
    moved = [key for key in KEYS if before[key] != after[key]]
    assert all(after[key] == "render-3" for key in moved)
    assert 0.15 < len(moved) / len(KEYS) < 0.35  # about a quarter, not a reshuffle


def test_losing_a_worker_moves_its_share_to_the_next_on_the_ring():
    ring = HashRing(NAMES)
    without = owners(HashRing(["render-0", "render-2"]))
    for key in KEYS:
        order = ring.order(key)
        assert sorted(order) == NAMES
        expected = order[1] if order[0] == "render-1" else order[0]
        assert without[key] == expected


def test_a_job_is_routed_by_its_topology_hash_else_its_source():
    record = {"topology_hash": "ab" * 32, "stages": {"pixel": "x"}}
    assert route_key({"record": record}) == "ab" * 32
    same = route_key({"record": {"stages": {"pixel": "x", "vertex": "y"}}})
    assert same == route_key({"record": {"stages": {"vertex": "y", "pixel": "x"}}}) != route_key({"record": record})


def test_with_no_worker_up_a_job_waits_for_its_owner():
    pools = RoutedPools("service.workers.render_worker", 3, 4, 10.0)  # not started: no child is up
    assert pools.choose(KEYS[0]) == pools.ring.order(KEYS[0])[0]
