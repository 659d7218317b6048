"""The generate fast path accepts only what the route's models accept unchanged; anything
else (None) goes on to the route, which words the error."""
import json
import time

import pytest

from service.fastpath import parse
from service.generation import GenerateParams
from service_testing import document

JSON = b"application/json"


def body(**fields) -> bytes:
    return json.dumps({"document": "<materialx/>", **fields}).encode()


def test_plain_json_and_xml_requests_are_read_like_the_route():
    assert parse(JSON, b"", body()) == (b"<materialx/>", GenerateParams())
    assert parse(b"application/json; charset=utf-8", b"", body(target="essl", element="M", interface="reduced",
                                                                  source=False)) == \
        (b"<materialx/>", GenerateParams("essl", "M", "reduced", False))
    assert parse(b"application/xml", b"target=essl&source=false", b"<x/>") == \
        (b"<x/>", GenerateParams("essl", None, "complete", False))


@pytest.mark.parametrize("content_type, query, raw", [
    (JSON, b"", body(interface={})),  # unhashable: found by schemathesis
    (JSON, b"", body(interface="bogus")),
    (JSON, b"", body(source="true")),  # pydantic would coerce it: let the route do so
    (JSON, b"", body(target=1)),
    (JSON, b"", body(target="x" * 65)),
    (JSON, b"", body(element=["a"])),
    (JSON, b"", body(extra=1)),
    (JSON, b"", b"[1, 2]"),
    (JSON, b"", b"{not json"),
    (JSON, b"", json.dumps({"document": 5}).encode()),
    (JSON, b"", json.dumps({"document": ""}).encode()),  # the model's min_length words the refusal
    (JSON, b"", body().decode().encode("utf-16")),  # the model reads UTF-8 only

    (b"application/xml", b"source=1", b"<x/>"),
    (b"application/xml", b"target=a&target=b", b"<x/>"),
    (b"application/xml", b"unknown=1", b"<x/>"),
    (b"text/plain", b"", b"<x/>"),
])
def test_anything_else_goes_to_the_route(content_type, query, raw):
    assert parse(content_type, query, raw) is None


CYCLE = ('<?xml version="1.0"?><materialx version="1.39"><nodedef name="ND_a" node="a" inherit="ND_a">'
         '<output name="out" type="float"/></nodedef><a name="n" type="float"/>'
         '<output name="o" type="float" nodename="n"/></materialx>')


@pytest.mark.parametrize("kind", ["fresh", "cycle", "malformed"])
def test_fast_path_answers_as_the_route_does(client, kind):
    """The same request through the fast path and through the route (`keep: []` sends it there:
    a field the fast path leaves to the model), new to the server and then repeated."""
    doc = {"fresh": document("ramp.mtlx").replace('value="0.5"', f'value="{time.time_ns() % 10**6 / 10**6}"'),
           "cycle": CYCLE, "malformed": "<materialx version="}[kind]
    fast = client.post("/v1/generate", json={"document": doc})
    routed = client.post("/v1/generate", json={"document": doc, "keep": []})
    again = client.post("/v1/generate", json={"document": doc})
    assert fast.status_code == routed.status_code == again.status_code == {"fresh": 200, "cycle": 422,
                                                                            "malformed": 400}[kind]
    if kind == "fresh":
        assert not fast.json()["cached"] and routed.json()["cached"] and again.json()["cached"]
        for field in ("hash", "stages", "blocks", "element", "interface"):
            assert fast.json()[field] == routed.json()[field] == again.json()[field]
    else:
        assert fast.json() == routed.json() == again.json()
