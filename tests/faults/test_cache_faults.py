"""Issue 8, faults 2, 3 and 5: a cache file truncated under a running server, a Redis that goes
away and comes back, garbage under a cache key. Each request is answered (fresh, uncached) or
refused with 503 and Retry-After; never a 500, never a hang; readiness says what is broken."""
import time

import pytest
import redis

from faults_testing import readiness, wait_ready
from service.cache import SQLiteStore
from service.cache.redis import PREFIX
from service_testing import RedisServer, Server, document, stop, wait_until


def uncached(value: float) -> str:
    return document("ramp.mtlx").replace("0.5", repr(value))


def generate(client, text: str):
    started = time.monotonic()
    r = client.post("/v1/generate", json={"document": text}, timeout=60)
    assert time.monotonic() - started < 30, "a request hung on the cache"
    assert r.status_code == 200, r.text
    return r.json()


# -- SQLite ------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def sqlite_server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("sqlitefaults"), workers=2, render_workers=1)
    yield srv
    srv.close()


def test_cache_file_truncated_to_zero_heals_without_a_500(sqlite_server):
    client = sqlite_server.client
    text = uncached(0.61)
    assert generate(client, text)["cached"] is False
    # ~16 records of 400 KB, so that SQLite checkpoints its WAL into the main file
    filler = SQLiteStore(sqlite_server.cache_path)
    for i in range(16):
        filler.put(f"filler:{i}", bytes([i]) * 400_000)
    filler.close()
    for _ in range(8):  # both API workers and their generators hold connections now
        assert generate(client, text)["cached"] is True
    with open(sqlite_server.cache_path, "r+b") as f:
        f.truncate(0)
    answers = [generate(client, t) for t in (text, uncached(0.62), text, uncached(0.63))]
    assert all(a["stages"]["pixel"] for a in answers)
    # the store is rebuilt: what is generated now is cached again
    wait_until(lambda: generate(client, uncached(0.64))["cached"] is False and
               generate(client, uncached(0.64))["cached"] is True, 30, "the cache working again")
    assert "Traceback" not in sqlite_server.log_text()
    assert "rebuilding it empty" in sqlite_server.log_text()
    wait_ready(client)


def test_readiness_reports_a_cache_that_cannot_be_opened(sqlite_server):
    client = sqlite_server.client
    path = sqlite_server.cache_path
    for suffix in ("", "-wal", "-shm"):
        path.with_name(path.name + suffix).unlink(missing_ok=True)
    path.mkdir()  # a directory where the file was: nothing can open it, nothing can rebuild it
    try:
        time.sleep(1.1)  # processes look for a replaced file at most once a second
        body = wait_until(lambda: (r := readiness(client))[0] == 503 and r[1], 10, "readiness 503")
        assert not body["cache"]["ready"] and body["generator"]["ready"] and body["render"]["ready"]
        assert generate(client, uncached(0.65))["cached"] is False  # answered without the cache
        assert generate(client, uncached(0.65))["cached"] is False
    finally:
        path.rmdir()
    time.sleep(1.1)
    wait_ready(client)
    assert generate(client, uncached(0.66))["cached"] is False
    assert generate(client, uncached(0.66))["cached"] is True


# -- Redis -------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def redis_cache(tmp_path_factory):
    server = RedisServer(tmp_path_factory.mktemp("redisfaults"))
    yield server
    stop(server.proc)


@pytest.fixture(scope="module")
def redis_server(tmp_path_factory, redis_cache):
    srv = Server(tmp_path_factory.mktemp("redisserve"), workers=2, render_workers=1,
                 env={"SHADERGEN_CACHE": redis_cache.url})
    yield srv
    srv.close()


@pytest.fixture(scope="module")
def celery_server(tmp_path_factory, redis_cache):
    """Redis as the cache and as Celery's broker (the several-machines configuration)."""
    srv = Server(tmp_path_factory.mktemp("celeryserve"), workers=1,
                 env={"SHADERGEN_CACHE": redis_cache.url, "SHADERGEN_BROKER": redis_cache.url})
    yield srv
    srv.close()


def test_garbage_under_a_cache_key_is_a_miss_and_is_overwritten(redis_server, redis_cache):
    client = redis_server.client
    text = uncached(0.71)
    record = generate(client, text)
    key = PREFIX + "rec:" + record["hash"]
    direct = redis.Redis.from_url(redis_cache.url)
    direct.set(key, b"not json {{{")
    again = generate(client, text)
    assert again["hash"] == record["hash"] and again["stages"] == record["stages"]
    assert direct.get(key).startswith(b"{")  # overwritten by the fresh record
    shader = client.get(f"/v1/shaders/{record['hash']}")
    assert shader.status_code == 200 and shader.json()["stages"] == record["stages"]
    # the request level too: its value must be a graph hash
    for req_key in direct.scan_iter(PREFIX + "req:*"):
        direct.set(req_key, b"not json {{{")
    assert generate(client, text)["hash"] == record["hash"]
    direct.close()


@pytest.mark.usefixtures("renderer_required")
def test_redis_down_serves_uncached_and_answers_503_where_it_must(redis_server, celery_server, redis_cache):
    client = redis_server.client
    known = generate(client, uncached(0.72))
    stop(redis_cache.proc)
    try:
        # the broker is away too: thumbnails cannot be queued, and say so
        assert generate(celery_server.client, uncached(0.77))["cached"] is False
        for path in ("/v1/thumbnails", "/v1/thumbnails?async=true"):
            thumb = celery_server.client.post(path, json={"document": uncached(0.78), "size": 32})
            assert thumb.status_code == 503 and thumb.headers["Retry-After"], thumb.text
            assert thumb.json()["error"]["code"] == "unavailable"
        status, body = readiness(celery_server.client)
        assert status == 503 and not body["render"]["ready"] and not body["cache"]["ready"]
        for value in (0.73, 0.73, 0.74):
            assert generate(client, uncached(value))["cached"] is False
        shader = client.get(f"/v1/shaders/{known['hash']}")
        assert shader.status_code == 503 and shader.headers["Retry-After"], shader.text
        assert shader.json()["error"]["code"] == "unavailable"
        status, body = readiness(client)
        assert status == 503 and not body["cache"]["ready"] and body["generator"]["ready"]
        thumb = client.post("/v1/thumbnails", json={"document": uncached(0.75), "size": 32}, timeout=120)
        assert thumb.status_code == 200 and thumb.content.startswith(b"\x89PNG"), thumb.text
        metrics = client.get("/metrics").text
        assert 'status="500"' not in metrics
    finally:
        redis_cache.start()
    wait_ready(client)
    assert generate(client, uncached(0.76))["cached"] is False
    assert generate(client, uncached(0.76))["cached"] is True  # the cache is used again
    # the broker and the cache are back; no `shadergen worker` runs beside this server, so its
    # render back end is not ready (no render process sends heartbeats), and says so
    body = wait_until(lambda: (r := readiness(celery_server.client))[1]["cache"]["ready"] and r[1], 30, "cache back")
    assert body["generator"]["ready"] and not body["render"]["ready"], body
    assert body["render"]["detail"].startswith("0 render processes answering"), body
    for srv in (redis_server, celery_server):
        assert "Traceback" not in srv.log_text()
