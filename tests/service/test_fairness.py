"""Clients whose requests keep failing are rationed (service/fairness.py): the ledger on its own,
and a live server with one API worker (one ledger), each test speaking from its own loopback
address (127.0.0.2, ...) as another machine would."""
import socket
import time

import httpx
import pytest

from service.fairness import FailureLedger
from service_testing import HOST, Server, document, receive_head

BAD = {"document": '<?xml version="1.0"?><materialx version="1.39"><nodedef'}  # 400 invalid_document
BURST, RATE, HOLD_S = 2, 0.2, 2.0  # two failures, then one every 5 s; a request waits at most 2 s for its turn


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self) -> float:
        return self.now


# -- the ledger ---------------------------------------------------------------------------------
def test_ledger_allows_a_burst_then_a_rate():
    clock = Clock()
    ledger = FailureLedger(burst=2, rate=0.5, clock=clock)
    assert ledger.take("a") == (False, 0.0)  # never failed: nothing to take
    ledger.settle("a", False, True)
    held, wait = ledger.take("a")
    assert held and wait == 0.0
    ledger.settle("a", held, True)  # two failures: the burst is spent
    assert ledger.take("a") == (False, 2.0)  # one token back in 1 / 0.5 s
    clock.now = 1.5
    assert ledger.take("a") == (False, pytest.approx(0.5))
    clock.now = 2.0
    held, wait = ledger.take("a")
    assert held and wait == 0.0
    assert ledger.take("b") == (False, 0.0)  # by address


def test_ledger_gives_back_the_token_of_a_success_and_forgets_a_full_bucket():
    clock = Clock()
    ledger = FailureLedger(burst=2, rate=1.0, clock=clock)
    ledger.settle("a", False, True)
    held, _ = ledger.take("a")
    ledger.settle("a", held, False)  # succeeded: the token comes back
    held, _ = ledger.take("a")
    assert held
    ledger.settle("a", held, True)
    assert ledger.take("a")[1] > 0
    clock.now = 10.0  # refilled: the client is forgotten
    ledger.settle("a", True, False)
    assert "a" not in ledger._buckets


def test_ledger_debt_is_at_most_a_burst_deep():
    clock = Clock()
    ledger = FailureLedger(burst=2, rate=1.0, clock=clock)
    for _ in range(100):  # requests in flight that all fail
        ledger.settle("a", False, True)
    assert ledger.take("a") == (False, 3.0)  # from -2 to 1


# -- a live server --------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def fair_server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("fair"), workers=1, render_workers=1,
                 env={"SHADERGEN_CLIENT_FAILURE_BURST": str(BURST), "SHADERGEN_CLIENT_FAILURE_RATE": str(RATE),
                      "SHADERGEN_CLIENT_HOLD_S": str(HOLD_S)})
    yield srv
    srv.close()


def client_at(server, address: str) -> httpx.Client:
    return httpx.Client(base_url=server.url, timeout=60,
                        transport=httpx.HTTPTransport(local_address=address))


def rationed(server, outcome: str) -> float:
    for line in server.client.get("/metrics").text.splitlines():
        if line.startswith(f'shadergen_rationed_total{{outcome="{outcome}"}}'):
            return float(line.rsplit(" ", 1)[1])
    return 0.0


def fail_burst(client) -> None:
    for _ in range(BURST):
        r = client.post("/v1/generate", json=BAD)
        assert r.status_code == 400 and r.json()["error"]["code"] == "invalid_document", r.text


def test_client_that_keeps_failing_gets_429_then_is_served_after_retry_after(fair_server):
    good = {"document": document("ramp.mtlx")}
    with client_at(fair_server, "127.0.0.2") as client:
        fail_burst(client)
        refused = rationed(fair_server, "refused")
        r = client.post("/v1/generate", json=good)  # even a good document waits for the client's turn
        assert r.status_code == 429, r.text
        body = r.json()
        assert set(body) == {"document", "element", "target", "error"}
        assert body["error"]["code"] == "too_many_failures" and "127.0.0.2" in body["error"]["message"]
        retry_after = int(r.headers["retry-after"])
        assert 1 <= retry_after <= 1 / RATE
        assert rationed(fair_server, "refused") == refused + 1
        # meanwhile another address is served at once, and probes always answer
        assert fair_server.client.post("/v1/generate", json=good).status_code == 200
        assert client.get("/healthz").status_code == 200
        time.sleep(retry_after)
        r = client.post("/v1/generate", json=good)
        assert r.status_code == 200, r.text


def test_client_in_debt_whose_turn_comes_within_the_hold_is_served(fair_server):
    with client_at(fair_server, "127.0.0.3") as client:
        fail_burst(client)
        # its token is back 1 / RATE s after the burst: from here, a little less than a hold away
        time.sleep(1 / RATE - HOLD_S + 0.25)
        served = rationed(fair_server, "served")
        r = client.post("/v1/generate", json={"document": document("ramp.mtlx")})
        assert r.status_code == 200, r.text
        assert rationed(fair_server, "served") == served + 1


def test_successes_and_not_found_answers_never_ration_a_client(fair_server):
    refused = rationed(fair_server, "refused")
    with client_at(fair_server, "127.0.0.4") as client:
        for i in range(3 * BURST):
            assert client.post("/v1/generate", json={"document": document("ramp.mtlx")}).status_code == 200
            assert client.get(f"/v1/shaders/{i:064x}").status_code == 404
        assert client.post("/v1/generate", json={"document": document("ramp.mtlx")}).status_code == 200
    assert rationed(fair_server, "refused") == refused


def test_refusal_of_an_upload_does_not_read_it_and_closes_the_connection(fair_server):
    with client_at(fair_server, "127.0.0.5") as client:
        fail_burst(client)
    with socket.create_connection((HOST, fair_server.port), timeout=30, source_address=("127.0.0.5", 0)) as s:
        # a large body announced, a few bytes of it sent: the answer comes without the rest
        s.sendall(f"POST /v1/generate HTTP/1.1\r\nHost: {HOST}\r\nContent-Type: application/xml\r\n"
                  "Content-Length: 1000000\r\n\r\n<materialx".encode())
        head = receive_head(s)
        assert head.startswith(b"HTTP/1.1 429"), head[:300]
        assert b"connection: close" in head.lower()
        s.settimeout(10)
        rest = head.split(b"\r\n\r\n", 1)[1]
        while data := s.recv(65536):
            rest += data
        assert b"too_many_failures" in rest  # and then the server closed the connection
