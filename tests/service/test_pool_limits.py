"""The pool's bounds on its children, on real child processes (tests/service/pool_child.py): the
memory limit, heartbeats (a stopped child against one busy in C), and the private temporary
folder that goes with each child."""
import asyncio
import os
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from service.workers import scratch
from service.workers.pool import ChildLimits, ProcessPool, Unavailable

HERE = Path(__file__).parent
CHILD_ENV = {"PYTHONPATH": os.pathsep.join([str(HERE), str(HERE.parents[1])]), "SHADERGEN_HEARTBEAT_S": "0.1"}


def run(coro):
    return asyncio.run(asyncio.wait_for(coro, 60))


async def started_pool(limits: ChildLimits, timeout_s: float = 10.0) -> ProcessPool:
    pool = ProcessPool("pool_child", size=1, queue_size=4, timeout_s=timeout_s, env=CHILD_ENV, limits=limits,
                       name="test")
    await pool.start()
    return pool


async def until(predicate, timeout_s: float = 10.0) -> None:
    async with asyncio.timeout(timeout_s):
        while not predicate():
            await asyncio.sleep(0.02)


def test_child_over_its_memory_limit_answers_too_large_alone_and_is_replaced():
    async def main():
        pool = await started_pool(ChildLimits(memory_bytes=200 << 20))
        try:
            first = pool.children[0].pid
            job = pool.submit({"action": "allocate", "mib": 400})
            reply, _ = await job.future
            assert reply["error"]["code"] == "too_large" and "limit of 200 MiB" in reply["error"]["message"]
            assert job.attempts == 1  # not tried again on the fresh child
            reply, _ = await pool.run({"action": "allocate", "mib": 50, "seconds": 0})  # within the limit
            assert "error" not in reply and reply["pid"] != first
        finally:
            await pool.close()

    run(main())


def test_job_holding_the_gil_is_busy_not_hung_and_a_stopped_child_is():
    async def main():
        pool = await started_pool(ChildLimits(silent_s=0.5))
        try:
            job = pool.submit({"action": "hold_gil", "seconds": 2})
            seen = set()
            while not job.future.done():  # no heartbeat for 2 s, four deadlines: busy, so answering
                seen.add(pool.answering)
                await asyncio.sleep(0.05)
            assert seen == {1} and "error" not in (await job.future)[0]
            child = pool.children[0]
            os.kill(child.pid, signal.SIGSTOP)
            try:
                await until(lambda: pool.answering == 0)
                with pytest.raises(Unavailable, match="no test process answered within 0.5 s"):
                    pool.submit({"echo": 1})
            finally:
                os.kill(child.pid, signal.SIGCONT)
            await until(lambda: pool.answering == 1)
            reply, _ = await pool.run({"echo": 2})
            assert reply["echo"] == 2 and reply["pid"] == child.pid  # the same child, heard from again
        finally:
            await pool.close()

    run(main())


def test_jobs_queued_behind_a_child_that_stops_are_refused_and_it_is_replaced():
    async def main():
        pool = await started_pool(ChildLimits(silent_s=0.5), timeout_s=2.0)
        try:
            child = pool.children[0]
            running = pool.submit({"action": "sleep", "seconds": 1})
            queued = pool.submit({"echo": 1})
            os.kill(child.pid, signal.SIGSTOP)
            with pytest.raises(Unavailable):
                await queued.future  # refused once the child is silent, not at the time limit
            assert not running.future.done()
            await until(lambda: pool.children[0].pid != child.pid and pool.answering == 1)  # killed at the limit
            reply, _ = await pool.run({"echo": 2})
            assert reply["echo"] == 2
        finally:
            await pool.close()

    run(main())


def test_a_childs_temporary_folder_goes_with_it_and_dead_owners_folders_are_swept():
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    leftover = Path(tempfile.mkdtemp(prefix=f"{scratch.PREFIX}{dead.pid}-"))
    (leftover / "upload.usdz").write_bytes(b"from a pool killed before it could clean up")

    async def main():
        pool = await started_pool(ChildLimits())
        try:
            assert not leftover.exists()
            reply, _ = await pool.run({"action": "write_temp"})
            written = Path(reply["path"])
            assert written.exists() and written.parent.name.startswith(f"{scratch.PREFIX}{os.getpid()}-")
            os.kill(reply["pid"], signal.SIGKILL)
            await until(lambda: not written.parent.exists())
            await until(lambda: pool.answering == 1)
        finally:
            await pool.close()
        assert not any(Path(tempfile.gettempdir()).glob(f"{scratch.PREFIX}{os.getpid()}-*"))

    run(main())


def test_a_readiness_deadline_within_two_heartbeats_is_refused():
    from pydantic import ValidationError

    from service.config import Settings

    with pytest.raises(ValidationError, match="at least twice heartbeat_s"):
        Settings.from_env({"SHADERGEN_HEARTBEAT_S": "1", "SHADERGEN_READY_DEADLINE_S": "1.5"})
    assert Settings.from_env({"SHADERGEN_HEARTBEAT_S": "0.25", "SHADERGEN_READY_DEADLINE_S": "2"}).ready_deadline_s == 2
