"""The process pool on real child processes: results, time limits, crashes and retries,
the bounded queue."""
import asyncio
import os
from pathlib import Path

import pytest

from service.workers.pool import JobTimeout, PoolError, ProcessPool, QueueFull, WorkerCrashed

HERE = Path(__file__).parent
ROOT = HERE.parents[1]
CHILD_ENV = {"PYTHONPATH": os.pathsep.join([str(HERE), str(ROOT)])}


def run(coro):
    return asyncio.run(asyncio.wait_for(coro, 60))


async def started_pool(size=1, queue_size=4, timeout_s=5.0) -> ProcessPool:
    pool = ProcessPool("pool_child", size=size, queue_size=queue_size, timeout_s=timeout_s, env=CHILD_ENV)
    await pool.start()
    return pool


def test_answers_with_json_and_payload():
    async def main():
        pool = await started_pool()
        try:
            reply, blob = await pool.run({"echo": "hi"}, b"abc")
            assert reply["echo"] == "hi" and blob == b"cba"
            # stray prints in the child go to stderr, the protocol stream stays intact
            reply, _ = await pool.run({"action": "print", "echo": 2})
            assert reply["echo"] == 2
        finally:
            await pool.close()

    run(main())


def test_handler_exception_is_an_error_reply_and_the_child_lives():
    async def main():
        pool = await started_pool()
        try:
            reply, _ = await pool.run({"action": "raise"})
            assert reply["error"]["code"] == "internal_error"
            assert "ValueError" in reply["error"]["message"]
            pid = reply_pid = (await pool.run({}))[0]["pid"]
            assert pid == reply_pid == pool.children[0].pid
        finally:
            await pool.close()

    run(main())


def test_time_limit_kills_and_replaces_the_child():
    async def main():
        pool = await started_pool(timeout_s=0.5)
        try:
            first = pool.children[0].pid
            with pytest.raises(JobTimeout):
                await pool.run({"action": "sleep", "seconds": 30})
            reply, _ = await pool.run({})
            assert reply["pid"] != first
        finally:
            await pool.close()

    run(main())


def test_crashed_child_is_replaced_and_the_job_retried_once(tmp_path):
    async def main():
        pool = await started_pool()
        try:
            first = pool.children[0].pid
            job = pool.submit({"action": "crash_once", "marker": str(tmp_path / "marker")})
            reply, _ = await job.future
            assert job.attempts == 2 and reply["pid"] != first
        finally:
            await pool.close()

    run(main())


def test_job_that_crashes_twice_fails_clearly_and_the_pool_goes_on():
    async def main():
        pool = await started_pool()
        try:
            job = pool.submit({"action": "crash"})
            with pytest.raises(WorkerCrashed, match="twice"):
                await job.future
            assert job.attempts == 2 and job.state == "failed"
            reply, _ = await pool.run({"echo": "after"})
            assert reply["echo"] == "after"
        finally:
            await pool.close()

    run(main())


def test_full_queue_refuses_at_once():
    async def main():
        pool = await started_pool(queue_size=2)
        try:
            busy = pool.submit({"action": "sleep", "seconds": 1})
            while busy.state == "queued":  # the child has taken it; the queue is empty again
                await asyncio.sleep(0.01)
            waiting = [pool.submit({}) for _ in range(2)]
            assert pool.depth == 2
            with pytest.raises(QueueFull):
                pool.submit({})
            await asyncio.gather(busy.future, *(j.future for j in waiting))
        finally:
            await pool.close()

    run(main())


def test_jobs_spread_over_children_and_close_stops_them():
    async def main():
        pool = await started_pool(size=2, queue_size=8)
        pids = [c.pid for c in pool.children]
        jobs = [pool.submit({"action": "sleep", "seconds": 0.3}) for _ in range(4)]
        replies = await asyncio.gather(*(j.future for j in jobs))
        assert {r[0]["pid"] for r in replies} == set(pids)
        await pool.close()
        for pid in pids:
            with pytest.raises(ProcessLookupError):
                os.kill(pid, 0)

    run(main())


# -- supervision (issue 8): under uvloop as under `shadergen serve` --------------------------------
def run_on(loop: str, coro):
    if loop == "uvloop":
        import uvloop

        return uvloop.run(asyncio.wait_for(coro, 60))
    return run(coro)


@pytest.mark.parametrize("loop", ["asyncio", "uvloop"])
def test_idle_child_that_dies_is_replaced_and_the_next_job_answered(loop):
    async def main():
        pool = await started_pool()
        try:
            first = pool.children[0].pid
            os.kill(first, 9)
            reply, _ = await pool.run({"echo": "after"})
            assert reply["echo"] == "after" and reply["pid"] != first
            assert pool.alive == 1
        finally:
            await pool.close()

    run_on(loop, main())


@pytest.mark.parametrize("loop", ["asyncio", "uvloop"])
def test_job_sent_to_a_child_that_just_died_is_retried_on_a_fresh_one(loop):
    async def main():
        pool = await started_pool()
        try:
            child = pool.children[0]
            os.kill(child.pid, 9)
            await child.proc.wait()
            # straight to the dead child, as a job taken just before its death would be
            with pytest.raises(WorkerCrashed):
                await child.call({"echo": 1}, b"", 5)
            reply, _ = await pool.run({"echo": 2})
            assert reply["echo"] == 2
        finally:
            await pool.close()

    run_on(loop, main())


def test_a_slot_that_fails_is_started_again_and_its_job_failed():
    async def main():
        pool = await started_pool()
        try:
            original = pool._on_result

            def broken(job, seconds, reply):  # a bug in the pool's own code, while a job runs
                pool._on_result = original
                raise RuntimeError("bug")

            pool._on_result = broken
            with pytest.raises(PoolError, match="slot"):
                await pool.run({"echo": 1})
            reply, _ = await pool.run({"echo": 2})
            assert reply["echo"] == 2
        finally:
            await pool.close()

    run(main())


def test_every_wait_on_the_pool_has_a_deadline():
    async def main():
        pool = ProcessPool("pool_child", size=1, queue_size=4, timeout_s=30, env=CHILD_ENV, wait_s=0.5)
        await pool.start()
        try:
            with pytest.raises(PoolError, match="no answer within"):
                await pool.run({"action": "sleep", "seconds": 2})
        finally:
            await pool.close()

    run(main())
