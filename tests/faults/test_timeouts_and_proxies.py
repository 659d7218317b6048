"""Issue 21, item 5: a server-side time-out is 504 with Retry-After and costs the client nothing in
the failure ledger (service/fairness.py); X-Forwarded-For names the client only when it comes
from a proxy the operator named (SHADERGEN_TRUSTED_PROXIES), never by default, even from
127.0.0.1. One API worker per server: one ledger."""
import pytest

from service_testing import Server, assert_error
from test_api import nested_document

BAD = {"document": '<?xml version="1.0"?><materialx version="1.39"><nodedef'}  # 400 invalid_document
BURST = 2
LEDGER = {"SHADERGEN_CLIENT_FAILURE_BURST": str(BURST), "SHADERGEN_CLIENT_FAILURE_RATE": "0.02",
          "SHADERGEN_CLIENT_HOLD_S": "0.05"}  # two failures, then one every 50 s: nothing refills during a test


@pytest.fixture(scope="module")
def proxied(tmp_path_factory):
    """Behind a proxy on 127.0.0.1 that the operator named."""
    srv = Server(tmp_path_factory.mktemp("proxied"), workers=1, env={
        **LEDGER, "SHADERGEN_TRUSTED_PROXIES": "127.0.0.1", "SHADERGEN_GENERATE_TIMEOUT_S": "1"})
    yield srv
    srv.close()


@pytest.fixture(scope="module")
def direct(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("direct"), workers=1, env=LEDGER)
    yield srv
    srv.close()


def bad(client, address: str):
    return client.post("/v1/generate", json=BAD, headers={"X-Forwarded-For": address})


def test_generation_time_out_is_504_and_not_the_clients_failure(proxied):
    client, me = proxied.client, {"X-Forwarded-For": "198.51.100.7"}
    for _ in range(BURST + 1):  # more time-outs than the ledger allows failures
        r = client.post("/v1/generate", json={"document": nested_document(16), "element": "out"}, headers=me)
        assert_error(r, 504, "timeout")
        assert int(r.headers["Retry-After"]) > 0
    for _ in range(BURST):  # the whole burst is still there
        assert_error(bad(client, "198.51.100.7"), 400, "invalid_document")
    refused = assert_error(bad(client, "198.51.100.7"), 429, "too_many_failures")  # and the ledger is on
    assert "198.51.100.7" in refused["message"]


def test_forwarded_for_from_a_named_proxy_is_the_client(proxied):
    client = proxied.client
    for _ in range(BURST):
        assert_error(bad(client, "203.0.113.5"), 400, "invalid_document")
    assert "203.0.113.5" in assert_error(bad(client, "203.0.113.5"), 429, "too_many_failures")["message"]
    assert_error(bad(client, "203.0.113.6"), 400, "invalid_document")  # another client, its own ledger


def test_forwarded_for_is_not_believed_unless_the_proxy_is_named(direct):
    client = direct.client
    answers = [bad(client, f"203.0.113.{i}") for i in range(1, BURST + 2)]  # a new address every time
    for r in answers[:BURST]:
        assert_error(r, 400, "invalid_document")
    refused = assert_error(answers[BURST], 429, "too_many_failures")
    assert "127.0.0.1" in refused["message"] and "203.0.113" not in refused["message"]
