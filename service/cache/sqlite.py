"""The embedded cache: one SQLite file in WAL mode shared by every process on the machine.

WAL lets readers run while one process writes; writers serialise on SQLite's own lock with a
busy timeout. From an event loop (an API worker) nothing may wait: see `aget` for reads, and
writes go to a thread (`Store.aput`). The total size is kept in a meta row by triggers, so bounding the store never scans
the table, and eviction removes the least recently used entries. A file that is corrupt, not a
database, or deleted under us is rebuilt empty: a cache may always be lost, never be fatal."""
import asyncio
import fcntl
import logging
import os
import sqlite3
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from types import SimpleNamespace

from .base import Store

log = logging.getLogger(__name__)

# recency is recorded at most this often per entry: a write on every hit would make 32 concurrent
# readers queue on SQLite's single write lock for the sake of a finer LRU order
TOUCH_INTERVAL_S = 10.0
EVICT_BATCH = 64
# after eviction the store is this fraction of its bound, so a full store does not evict on every put
LOW_WATERMARK = 0.9
BUSY_TIMEOUT_S = 10.0
INODE_CHECK_S = 1.0
_CORRUPT = {sqlite3.SQLITE_CORRUPT, sqlite3.SQLITE_NOTADB}

SCHEMA = """
CREATE TABLE IF NOT EXISTS entries (
    key TEXT PRIMARY KEY, value BLOB NOT NULL, size INTEGER NOT NULL, accessed REAL NOT NULL
) WITHOUT ROWID;
CREATE INDEX IF NOT EXISTS entries_accessed ON entries (accessed);
CREATE TABLE IF NOT EXISTS meta (name TEXT PRIMARY KEY, value INTEGER NOT NULL);
INSERT OR IGNORE INTO meta VALUES ('total_bytes', 0);
CREATE TRIGGER IF NOT EXISTS entries_ins AFTER INSERT ON entries BEGIN
    UPDATE meta SET value = value + new.size WHERE name = 'total_bytes'; END;
CREATE TRIGGER IF NOT EXISTS entries_del AFTER DELETE ON entries BEGIN
    UPDATE meta SET value = value - old.size WHERE name = 'total_bytes'; END;
CREATE TRIGGER IF NOT EXISTS entries_upd AFTER UPDATE OF size ON entries BEGIN
    UPDATE meta SET value = value + new.size - old.size WHERE name = 'total_bytes'; END;
"""


def _is_corrupt(exc: sqlite3.Error) -> bool:
    return getattr(exc, "sqlite_errorcode", None) in _CORRUPT


class SQLiteStore(Store):
    def __init__(self, path: str | os.PathLike, max_bytes: int = 512 * 1024 * 1024):
        self.path = Path(path)
        self.max_bytes = max_bytes
        # one connection per thread: a writer waiting on the lock must not hold up the loop's reads
        self._local = threading.local()
        self._generation = 0  # bumped on rebuild so every thread reopens
        self._lock = threading.Lock()
        # for reads from an event loop: a connection that never waits, and the thread that does what may wait
        self._loop_reads = SimpleNamespace(conn=None, inode=None, generation=-1)
        self._waiting_reads: ThreadPoolExecutor | None = None
        try:
            self._connect()  # creates the file now, before the service's processes share it
        except sqlite3.Error as exc:  # later operations try again (and fail as misses meanwhile)
            log.warning("cache file %s not usable yet: %s", self.path, exc)

    # -- connections ------------------------------------------------------------------------
    def _connect(self) -> sqlite3.Connection:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        try:
            conn = self._open()
        except sqlite3.DatabaseError as exc:
            if not _is_corrupt(exc):
                raise
            self._rebuild(reason=str(exc))
            conn = self._open()
        local = self._local
        local.conn, local.inode, local.generation = conn, self._inode(), self._generation
        return conn

    def _open(self) -> sqlite3.Connection:
        conn = sqlite3.connect(self.path, timeout=BUSY_TIMEOUT_S, isolation_level=None, check_same_thread=False)
        try:
            conn.execute("PRAGMA journal_mode=WAL")
            conn.execute("PRAGMA synchronous=NORMAL")
            # a schema change by another process needs the write lock: take it like any writer
            if conn.execute("SELECT count(*) FROM sqlite_master WHERE name='entries'").fetchone()[0] == 0:
                conn.executescript("BEGIN IMMEDIATE;" + SCHEMA + "COMMIT;")
        except BaseException:
            conn.close()
            raise
        return conn

    def _inode(self) -> int | None:
        try:
            return self.path.stat().st_ino
        except FileNotFoundError:
            return None

    def _conn(self) -> sqlite3.Connection:
        local = self._local
        conn = getattr(local, "conn", None)
        if conn is not None and local.generation == self._generation and not self._replaced(local):
            return conn
        if conn is not None:
            conn.close()
        return self._connect()

    def _replaced(self, local) -> bool:
        """Whether the file was deleted or replaced under us (this process would otherwise go on
        with an orphan). Checked at most every INODE_CHECK_S: a stat per lookup is measurable."""
        now = time.monotonic()
        if now - getattr(local, "checked", 0.0) < INODE_CHECK_S:
            return False
        local.checked = now
        return self._inode() != local.inode

    def _rebuild(self, reason: str) -> None:
        """Replace a broken file by an empty store. A file lock keeps two processes from
        rebuilding at once; whoever comes second finds a sound file and keeps it. Either way every
        connection of this process is reopened: the ones it holds saw the broken file."""
        lock_path = self.path.with_name(self.path.name + ".rebuild-lock")
        with open(lock_path, "w") as lock_file:
            fcntl.flock(lock_file, fcntl.LOCK_EX)
            try:
                if not self._sound():
                    log.warning("cache file %s unusable (%s): rebuilding it empty", self.path, reason)
                    for suffix in ("", "-wal", "-shm"):
                        Path(str(self.path) + suffix).unlink(missing_ok=True)
            finally:
                with self._lock:
                    self._generation += 1

    def _sound(self) -> bool:
        """Whether the file is a store: a truncated (empty) file passes quick_check but has no table."""
        try:
            probe = sqlite3.connect(self.path, timeout=BUSY_TIMEOUT_S)
            try:
                return (probe.execute("PRAGMA quick_check").fetchone()[0] == "ok" and
                        probe.execute("SELECT count(*) FROM sqlite_master WHERE name='entries'").fetchone()[0] == 1)
            finally:
                probe.close()
        except sqlite3.DatabaseError:
            return False

    def _run(self, op):
        """Run op(conn); on corruption rebuild the file and try once more."""
        try:
            return op(self._conn())
        except sqlite3.DatabaseError as exc:
            if not _is_corrupt(exc):
                raise
            self._rebuild(reason=str(exc))
            return op(self._conn())

    # -- the Store interface -----------------------------------------------------------------
    def get(self, key: str) -> bytes | None:
        return self._run(lambda conn: self._read(conn, key))

    def _read(self, conn: sqlite3.Connection, key: str) -> bytes | None:
        row = conn.execute("SELECT value, accessed FROM entries WHERE key = ?", (key,)).fetchone()
        if row is None:
            return None
        now = time.time()
        if now - row[1] > TOUCH_INTERVAL_S:
            self._touch(conn, key, now)
        return bytes(row[0])

    @staticmethod
    def _touch(conn: sqlite3.Connection, key: str, now: float) -> None:
        """Record a read for the LRU order, unless a writer holds the lock: a read must never wait
        up to the busy timeout for the sake of recency."""
        busy_timeout_ms = conn.execute("PRAGMA busy_timeout").fetchone()[0]
        conn.execute("PRAGMA busy_timeout = 0")
        try:
            conn.execute("UPDATE entries SET accessed = ? WHERE key = ?", (now, key))
        except sqlite3.OperationalError as exc:
            if exc.sqlite_errorcode not in (sqlite3.SQLITE_BUSY, sqlite3.SQLITE_LOCKED):
                raise
        finally:
            conn.execute(f"PRAGMA busy_timeout = {busy_timeout_ms}")

    async def aget(self, key: str) -> bytes | None:
        """A read from an event loop, which must never wait. On an open connection in WAL mode a
        read takes no lock a writer holds, so the loop reads itself, on a connection with a busy
        timeout of 0: sending every read to a thread would cost more than the read (on a busy loop
        the GIL goes back and forth for each of SQLite's calls; cached generate lost about half its
        throughput that way). Whatever may wait is done in the store's own thread: opening or
        reopening the file, rebuilding a broken one (which heals it as for any caller), a read
        that found a lock. The thread then opens the loop a fresh connection, handed over here, so
        only the loop's thread ever uses or closes it."""
        reads = self._loop_reads
        if reads.conn is not None and reads.generation == self._generation and not self._replaced(reads):
            try:
                return self._read(reads.conn, key)
            except sqlite3.Error:  # busy, locked or broken: the thread finds out which, waits or heals
                pass
        if self._waiting_reads is None:
            self._waiting_reads = ThreadPoolExecutor(1, thread_name_prefix="sqlite-cache-read")
        value, fresh = await asyncio.get_running_loop().run_in_executor(self._waiting_reads, self._read_waiting, key)
        self._hand_over(fresh)
        return value

    def _read_waiting(self, key: str) -> tuple[bytes | None, SimpleNamespace | None]:
        """In the store's thread: the read, then a connection for the loop (None if the file
        cannot be opened now: the next read comes here again)."""
        value = self.get(key)
        generation = self._generation
        try:
            conn = self._open()
        except sqlite3.Error:
            return value, None
        conn.execute("PRAGMA busy_timeout = 0")
        conn.execute("PRAGMA wal_autocheckpoint = 0")  # a touch commits: the checkpoint is the writers' to do
        return value, SimpleNamespace(conn=conn, inode=self._inode(), generation=generation)

    def _hand_over(self, fresh: SimpleNamespace | None) -> None:
        if self._loop_reads.conn is not None:
            self._loop_reads.conn.close()
        self._loop_reads = fresh or SimpleNamespace(conn=None, inode=None, generation=-1)

    def put(self, key: str, value: bytes) -> None:
        if len(value) > self.max_bytes:
            return  # larger than the whole store: caching it would only evict everything else
        self._write("INSERT INTO entries (key, value, size, accessed) VALUES (?, ?, ?, ?) "
                    "ON CONFLICT (key) DO UPDATE SET value = excluded.value, size = excluded.size, "
                    "accessed = excluded.accessed", key, value)

    def add(self, key: str, value: bytes) -> bool:
        return self._write("INSERT OR IGNORE INTO entries (key, value, size, accessed) VALUES (?, ?, ?, ?)",
                           key, value) == 1

    def _write(self, statement: str, key: str, value: bytes) -> int:
        """One write of (key, value, size, accessed) in its own transaction, eviction included;
        the rows it changed."""
        def op(conn):
            conn.execute("BEGIN IMMEDIATE")
            try:
                changed = conn.execute(statement, (key, value, len(value), time.time())).rowcount
                self._evict(conn)
                conn.execute("COMMIT")
            except BaseException:
                conn.execute("ROLLBACK")
                raise
            return changed

        return self._run(op)

    def _evict(self, conn: sqlite3.Connection) -> None:
        total = self.total_bytes(conn)
        if total <= self.max_bytes:
            return
        excess = total - int(self.max_bytes * LOW_WATERMARK)
        while excess > 0:
            oldest = conn.execute("SELECT key, size FROM entries ORDER BY accessed LIMIT ?", (EVICT_BATCH,)).fetchall()
            if not oldest:
                break
            victims = []
            for key, size in oldest:
                if excess <= 0:
                    break
                victims.append((key,))
                excess -= size
            conn.executemany("DELETE FROM entries WHERE key = ?", victims)

    def delete(self, key: str) -> None:
        self._run(lambda conn: conn.execute("DELETE FROM entries WHERE key = ?", (key,)))

    def total_bytes(self, conn: sqlite3.Connection | None = None) -> int:
        conn = conn or self._conn()
        return conn.execute("SELECT value FROM meta WHERE name = 'total_bytes'").fetchone()[0]

    def __len__(self) -> int:
        return self._run(lambda conn: conn.execute("SELECT count(*) FROM entries").fetchone()[0])

    def close(self) -> None:
        conn = getattr(self._local, "conn", None)
        if conn is not None:
            conn.close()
            self._local.conn = None

    async def aclose(self) -> None:
        """Close what reads from the event loop opened: the loop's connection, the thread's."""
        self._hand_over(None)
        if self._waiting_reads is not None:
            await asyncio.get_running_loop().run_in_executor(self._waiting_reads, self.close)
            self._waiting_reads.shutdown()
            self._waiting_reads = None
