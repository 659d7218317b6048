"""The generate fast path accepts only what the route's models accept unchanged; anything
else (None) goes on to the route, which words the error."""
import json

import pytest

from service.fastpath import parse
from service.generation import GenerateParams

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
