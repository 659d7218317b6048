"""The cache stores on real back ends: SQLite files (bounded, LRU, shared by processes, rebuilt
when broken) and a real redis-server."""
import asyncio
import fcntl
import multiprocessing
import sqlite3
import threading
import time

import pytest

from service.cache import CacheUnavailable, SQLiteStore, open_store
from service.cache import sqlite as sqlite_module


def test_put_get_delete_and_json(tmp_path):
    store = SQLiteStore(tmp_path / "c.sqlite3")
    assert store.get("missing") is None
    store.put("k", b"\x00bytes\xff")
    assert store.get("k") == b"\x00bytes\xff"
    store.put_json("j", {"a": [1, 2]})
    assert store.get_json("j") == {"a": [1, 2]}
    assert asyncio.run(store.aget("k")) == b"\x00bytes\xff"
    store.put("k", b"replaced")
    assert store.get("k") == b"replaced"
    store.delete("k")
    assert store.get("k") is None
    assert store.total_bytes() == len(b'{"a":[1,2]}')


def test_bounded_with_least_recently_used_evicted(tmp_path, monkeypatch):
    monkeypatch.setattr(sqlite_module, "TOUCH_INTERVAL_S", 0.0)  # record every read, for a strict order
    store = SQLiteStore(tmp_path / "c.sqlite3", max_bytes=10_000)
    for i in range(10):
        store.put(f"k{i}", bytes(900))
        time.sleep(0.002)
    store.get("k0")  # k0 is now the most recent: k1 goes first
    store.put("k10", bytes(900))
    store.put("k11", bytes(900))
    assert store.total_bytes() <= 10_000
    assert store.get("k0") is not None and store.get("k11") is not None
    assert store.get("k1") is None
    assert store.total_bytes() == sum(len(store.get(f"k{i}") or b"") for i in range(12))
    store.put("huge", bytes(20_000))  # larger than the store: not kept, nothing evicted for it
    assert store.get("huge") is None and store.get("k11") is not None


def _writer(path: str, worker: int, count: int) -> None:
    store = SQLiteStore(path, max_bytes=200_000)
    for i in range(count):
        store.put(f"w{worker}-{i}", bytes([worker]) * 500)
        store.get(f"w{(worker + 1) % 4}-{i}")


def test_concurrent_writers_in_several_processes(tmp_path):
    path = str(tmp_path / "c.sqlite3")
    SQLiteStore(path)  # created once, as the service does before its workers start
    ctx = multiprocessing.get_context("spawn")
    procs = [ctx.Process(target=_writer, args=(path, w, 300)) for w in range(4)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
    assert [p.exitcode for p in procs] == [0, 0, 0, 0]
    store = SQLiteStore(path, max_bytes=200_000)
    with sqlite3.connect(path) as conn:
        actual = conn.execute("SELECT coalesce(sum(size), 0) FROM entries").fetchone()[0]
    assert store.total_bytes() == actual <= 200_000
    assert len(store) > 100


def test_corrupt_file_is_rebuilt(tmp_path):
    path = tmp_path / "c.sqlite3"
    path.write_bytes(b"this is not a database, just garbage " * 200)
    store = SQLiteStore(path)
    assert store.get("k") is None
    store.put("k", b"v")
    assert store.get("k") == b"v"


def test_file_corrupted_while_open_is_rebuilt(tmp_path):
    path = tmp_path / "c.sqlite3"
    store = SQLiteStore(path)
    for i in range(50):
        store.put(f"k{i}", bytes(4000))
    store.close()
    with open(path, "r+b") as f:  # trash every page after the header
        f.seek(4096)
        f.write(b"\xde\xad" * 100_000)
    for suffix in ("-wal", "-shm"):
        (tmp_path / f"c.sqlite3{suffix}").unlink(missing_ok=True)
    again = SQLiteStore(path)
    assert again.get("k3") is None
    again.put("new", b"v")
    assert again.get("new") == b"v"


def test_deleted_file_is_recreated(tmp_path, monkeypatch):
    monkeypatch.setattr(sqlite_module, "INODE_CHECK_S", 0.0)  # noticed at the next lookup, not a second later
    path = tmp_path / "sub" / "c.sqlite3"
    store = SQLiteStore(path)
    store.put("k", b"v")
    for p in path.parent.iterdir():
        p.unlink()
    assert store.get("k") is None  # a fresh, empty store, not an orphaned file
    store.put("k2", b"v2")
    assert SQLiteStore(path).get("k2") == b"v2"


def test_open_store_by_url(tmp_path):
    store = open_store(f"sqlite:///{tmp_path / 'x.sqlite3'}", 1000)
    assert isinstance(store.inner, SQLiteStore) and store.inner.path == tmp_path / "x.sqlite3"
    assert store.name == "SQLiteStore"


def test_redis_store(redis_server):
    store = open_store(redis_server.url, 0)
    try:
        store.put("k", b"\x00v")
        assert store.get("k") == b"\x00v"
        assert asyncio.run(_aget_and_close(store, "k")) == b"\x00v"
        store.put_json("j", [1, "a"])
        assert store.get_json("j") == [1, "a"]
        store.delete("k")
        assert store.get("k") is None
    finally:
        store.close()


async def _aget_and_close(store, key):
    try:
        return await store.aget(key)
    finally:
        await store.aclose()


@pytest.mark.parametrize("url", ["redis://127.0.0.1:1/0"])
def test_redis_store_unreachable_is_a_miss_not_an_error_nor_a_hang(url):
    store = open_store(url, 0)
    started = time.monotonic()
    assert store.get("k") is None
    store.put("k", b"v")  # skipped, not raised
    assert asyncio.run(store.aget("k")) is None
    with pytest.raises(CacheUnavailable):
        asyncio.run(store.aread("k"))
    assert "ConnectionError" in store.last_error and time.monotonic() - started < 10


def test_file_truncated_to_zero_under_open_connections_heals(tmp_path):
    """Issue 8: a 0-byte file passes `PRAGMA quick_check`; stale connections kept failing."""
    path = tmp_path / "c.sqlite3"
    store = open_store(f"sqlite:///{path}", 64 * 1024 * 1024)
    other = open_store(f"sqlite:///{path}", 64 * 1024 * 1024)  # as another process would hold it
    for i in range(16):  # enough for SQLite to checkpoint the WAL into the main file
        store.put(f"k{i}", bytes([i]) * 400_000)
    assert other.get("k3") == bytes([3]) * 400_000
    with open(path, "r+b") as f:
        f.truncate(0)
    for s in (store, other):
        s.get("k5")  # a miss or the value, never an exception
    store.put("fresh", b"x")
    assert store.get("fresh") == b"x" and other.get("fresh") == b"x"
    assert asyncio.run(other.aread("fresh")) == b"x"


def test_entries_that_are_not_what_their_key_promises_are_misses():
    from service.cache.entries import is_graph_hash, is_png, is_record, refusal

    garbage = b"not json {{{"
    assert not is_graph_hash(garbage) and is_graph_hash(b"0123abcd" * 8)
    assert not is_record(garbage, "ab12" * 16) and not is_record(b'{"hash":"other"}', "ab12" * 16)
    assert is_record(b'{"element":"x","hash":"' + b"ab12" * 16 + b'"}', "ab12" * 16)
    assert refusal(garbage) is None and refusal(b'{"code": 1}') is None and refusal(b"[1]") is None
    assert refusal(b'{"code":"cycle","message":"m","where":null}') == {"code": "cycle", "message": "m", "where": None}
    assert not is_png(garbage) and is_png(b"\x89PNG\r\n\x1a\n...")


def test_a_read_does_not_wait_for_the_write_lock_to_record_recency(tmp_path, monkeypatch):
    monkeypatch.setattr(sqlite_module, "TOUCH_INTERVAL_S", 0.0)  # every read records recency
    path = tmp_path / "c.sqlite3"
    store = SQLiteStore(path)
    store.put("k", b"v")
    writer = sqlite3.connect(path, isolation_level=None)
    writer.execute("BEGIN IMMEDIATE")  # another process in the middle of a write
    try:
        started = time.monotonic()
        assert store.get("k") == b"v"
        assert time.monotonic() - started < 1.0  # not the 10 s busy timeout
    finally:
        writer.execute("ROLLBACK")
        writer.close()
    store.put("k2", b"w")  # writes still wait for the lock as before, and go through
    assert store.get("k2") == b"w"


TICKS = 20


async def read_while_ticking(store, key: str, then) -> tuple[bytes | None, int]:
    """Read `key` while the loop counts ticks of 10 ms; `then` is called at the 20th (it lets the
    read go on). Returns the value and the ticks counted before the read ended."""
    ticks = 0

    async def tick():
        nonlocal ticks
        while True:
            await asyncio.sleep(0.01)
            ticks += 1
            if ticks == TICKS:
                then()
    ticker = asyncio.create_task(tick())
    try:
        return await store.aget(key), ticks
    finally:
        ticker.cancel()


def test_reads_from_an_event_loop_leave_it_running_and_still_heal_the_file(tmp_path):
    """A read that must wait (here on another process rebuilding the broken file) waits in the
    store's thread: the API worker's loop goes on serving meanwhile, and the file is healed."""
    path = tmp_path / "c.sqlite3"
    store = SQLiteStore(path)
    store.put("k", b"v")
    store.close()
    path.write_bytes(b"this is not a database, just garbage " * 200)
    for suffix in ("-wal", "-shm"):
        (tmp_path / f"c.sqlite3{suffix}").unlink(missing_ok=True)
    lock = open(path.with_name(path.name + ".rebuild-lock"), "w")
    fcntl.flock(lock, fcntl.LOCK_EX)  # as a process in the middle of a rebuild holds it
    # released after a while in any case, so a read that blocks the loop fails the test, not hangs it
    safety = threading.Timer(10, lock.close)
    safety.start()
    try:
        value, ticks = asyncio.run(read_while_ticking(store, "k", then=lock.close))  # then the other process is done
    finally:
        safety.cancel()
        lock.close()
    assert value is None and ticks >= TICKS  # the loop ran all along; the broken file was a miss
    store.put("k", b"w")
    assert asyncio.run(store.aget("k")) == b"w"


def test_a_file_replaced_under_the_loops_connection_is_healed_off_the_loop(tmp_path, monkeypatch):
    monkeypatch.setattr(sqlite_module, "INODE_CHECK_S", 0.0)  # noticed at the next read
    path = tmp_path / "c.sqlite3"
    store = SQLiteStore(path)
    store.put("k", b"v")
    lock = open(path.with_name(path.name + ".rebuild-lock"), "w")
    safety = threading.Timer(10, lock.close)

    async def read_replace_read():
        assert await store.aget("k") == b"v"
        assert await store.aget("k") == b"v"  # on the loop's own connection now
        for suffix in ("", "-wal", "-shm"):
            (tmp_path / f"c.sqlite3{suffix}").unlink(missing_ok=True)
        path.write_bytes(b"this is not a database, just garbage " * 200)
        fcntl.flock(lock, fcntl.LOCK_EX)  # and another process is rebuilding it
        safety.start()
        return await read_while_ticking(store, "k", then=lock.close)

    try:
        value, ticks = asyncio.run(read_replace_read())
    finally:
        safety.cancel()
        lock.close()
    assert value is None and ticks >= TICKS
    store.put("k", b"w")
    assert asyncio.run(store.aget("k")) == b"w"
