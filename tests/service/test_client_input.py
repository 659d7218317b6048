"""Client input that once escaped as a 500 (issue 8), and cheap requests that once cost a lot:
each answered by the live server with a 4xx and the contract's error object, or bounded."""
import json
import socket
import time

import pytest

from service_testing import HOST, assert_error, Server, document, receive_head

XML = {"content-type": "application/xml"}
JSON = {"content-type": "application/json"}


def with_declaration(encoding: str) -> str:
    body = document("ramp.mtlx").split("?>", 1)[1]
    return f'<?xml version="1.0" encoding="{encoding}"?>{body}'


@pytest.mark.parametrize("encoding", ["x-bogus", "utf-32", "utf-16"])
def test_declared_encoding_that_does_not_decode_the_body_is_invalid(client, encoding):
    assert_error(client.post("/v1/generate", content=with_declaration(encoding), headers=XML), 400,
                 "invalid_document")
    assert_error(client.post("/v1/generate", json={"document": with_declaration(encoding)}), 400,
                 "invalid_document")


@pytest.mark.parametrize("encoding", ["utf-7", "shift_jis", "latin-1"])
def test_ascii_compatible_declared_encodings_are_read(client, encoding):
    r = client.post("/v1/generate", content=with_declaration(encoding), headers=XML)
    assert r.status_code == 200, r.text
    assert r.json()["element"] == "NG_ramp/out"


LONE = "\ud800"


@pytest.mark.parametrize("route, field", [("/v1/generate", "document"), ("/v1/generate", "target"),
                                          ("/v1/generate", "element"), ("/v1/thumbnails", "document"),
                                          ("/v1/thumbnails", "element")])
def test_lone_surrogates_are_refused(client, route, field):
    body = {"document": document("ramp.mtlx"), field: LONE}
    # json.dumps escapes the surrogate as \ud800: valid JSON syntax, but no text
    assert_error(client.post(route, content=json.dumps(body).encode(), headers=JSON), 422, "invalid_request")


@pytest.mark.parametrize("route", ["/v1/generate", "/v1/thumbnails"])
def test_json_nested_100k_deep_is_refused(client, route):
    deep = b'{"document": ' + b"[" * 100_000 + b"]" * 100_000 + b"}"
    r = client.post(route, content=deep, headers=JSON)
    assert r.status_code in (400, 422), r.text
    assert_error(r, r.status_code, "invalid_request")


def test_xml_nested_200k_deep_is_refused_early(client):
    deep = b'<materialx version="1.39">' + b"<a>" * 200_000 + b"</a>" * 200_000 + b"</materialx>"
    started = time.monotonic()
    err = assert_error(client.post("/v1/generate", content=deep, headers=XML), 400, "invalid_document")
    assert "nested deeper" in err["message"]
    # refused while parsing: well under the generation time limit that used to stop it
    assert time.monotonic() - started < 5


@pytest.mark.parametrize("text", ["<!-- <!ENTITY x 'y'> -->", "<![CDATA[<!DOCTYPE m [<!ENTITY x 'y'>]>]]>"])
def test_entity_text_in_a_comment_or_cdata_is_not_a_doctype(client, text):
    doc = document("ramp.mtlx").replace("<nodegraph", text + "<nodegraph", 1)
    assert client.post("/v1/generate", content=doc, headers=XML).status_code == 200


def test_doctype_after_a_prolog_comment_is_still_refused(client):
    doc = '<?xml version="1.0"?>\n<!-- x -->\n<!DOCTYPE m [<!ENTITY x "y">]>' + document("ramp.mtlx").split("?>", 1)[1]
    assert_error(client.post("/v1/generate", content=doc, headers=XML), 400, "unsafe_xml")


def test_request_head_over_the_limit_is_431_without_reading_it_all(server):
    with socket.create_connection((HOST, server.port), timeout=30) as s:
        s.sendall(f"GET /healthz HTTP/1.1\r\nHost: {HOST}\r\nX-Big: ".encode())
        sent = 0
        try:
            for _ in range(3200):  # 200 MiB offered; the server stops reading long before
                s.sendall(b"a" * 65536)
                sent += 65536
        except (BrokenPipeError, ConnectionResetError):
            pass
        response = receive_head(s)
    assert response.startswith(b"HTTP/1.1 431"), response[:200]
    assert sent < 64 * 1024 * 1024


# -- deadlines and disconnects (a server with short deadlines) ----------------------------------
@pytest.fixture(scope="module")
def strict_server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("strict"), workers=1, render_workers=1,
                 env={"SHADERGEN_BODY_TIMEOUT_S": "1", "SHADERGEN_HEAD_TIMEOUT_S": "1"})
    yield srv
    srv.close()


def test_stalled_body_gets_408_within_the_deadline(strict_server):
    with socket.create_connection((HOST, strict_server.port), timeout=30) as s:
        s.sendall(f"POST /v1/generate HTTP/1.1\r\nHost: {HOST}\r\nContent-Type: application/xml\r\n"
                  "Content-Length: 1000\r\n\r\n<materialx".encode())
        started = time.monotonic()
        response = receive_head(s)
    assert response.startswith(b"HTTP/1.1 408"), response[:200]
    assert time.monotonic() - started < 10


def test_stalled_head_is_closed_within_the_deadline(strict_server):
    with socket.create_connection((HOST, strict_server.port), timeout=30) as s:
        s.sendall(f"GET /healthz HTTP/1.1\r\nHost: {HOST}\r\nX-Slow: ".encode())
        started = time.monotonic()
        response = receive_head(s)
    assert response.startswith(b"HTTP/1.1 408"), response[:200]
    assert time.monotonic() - started < 10


def _disconnects(client) -> float:
    total = 0.0
    for line in client.get("/metrics").text.splitlines():
        if line.startswith("shadergen_requests_total{") and 'status="499"' in line:
            total += float(line.rsplit(" ", 1)[1])
    return total


def test_client_that_disconnects_mid_body_is_one_log_line_and_counted_as_such(strict_server):
    client = strict_server.client
    before = _disconnects(client)
    for _ in range(3):
        with socket.create_connection((HOST, strict_server.port), timeout=30) as s:
            s.sendall(f"POST /v1/generate HTTP/1.1\r\nHost: {HOST}\r\nContent-Type: application/xml\r\n"
                      "Content-Length: 100000\r\n\r\n<materialx".encode())
            time.sleep(0.2)
    time.sleep(0.5)
    assert _disconnects(client) - before == 3
    metrics = client.get("/metrics").text
    assert not any('status="500"' in line for line in metrics.splitlines()
                   if line.startswith("shadergen_requests_total{"))
    log = strict_server.log_text()
    assert log.count("disconnected while sending the body") == 3
    assert "Traceback" not in log


def _refusal_hits(client) -> float:
    series = 'shadergen_cache_total{kind="refusal",result="hit"}'
    line = next((line for line in client.get("/metrics").text.splitlines() if line.startswith(series)), None)
    return float(line.rsplit(" ", 1)[1]) if line else 0.0


def test_a_repeated_bad_document_is_refused_from_the_store(client):
    """A client repeating an expensive bad document costs a lookup, not a generation each time."""
    doc = ('<?xml version="1.0"?><materialx version="1.39"><nodedef name="ND_r" node="r" inherit="ND_r">'
           f'<output name="out" type="float"/></nodedef><r name="n" type="float"/>'
           f'<output name="o{time.time_ns()}" type="float" nodename="n"/></materialx>')
    first = client.post("/v1/generate", content=doc, headers=XML)
    before = _refusal_hits(client)
    again = [client.post("/v1/generate", content=doc, headers=XML) for _ in range(3)]
    assert first.status_code == 422 and first.json()["error"]["code"] == "cycle", first.text
    assert all(r.status_code == 422 and r.json() == first.json() for r in again)
    assert _refusal_hits(client) - before == 3
