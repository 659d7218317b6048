"""Hooks for schemathesis runs (SCHEMATHESIS_HOOKS=schemathesis_hooks): USD bodies are sent, and a
check that the server's own request validation never refuses a request its schema allows.

Schemathesis' positive_data_acceptance wants a 2xx for every schema-valid request, but no schema
can say which strings are valid MaterialX: a well-formed request whose document is not a
material is answered 400/422 with a document error (invalid_document, unknown_node, ...), which
is the contract. What must never happen is the server refusing the request itself (invalid_request,
413, 415, 405) while the schema accepts it: that is a disagreement between the two."""
import schemathesis

REQUEST_REFUSALS = {405, 413, 415}


@schemathesis.check
def schema_valid_request_not_refused(ctx, response, case):
    meta = case.meta
    if meta is None or not meta.generation.mode.is_positive:
        return None
    try:
        code = (response.json().get("error") or {}).get("code")
    except Exception:  # not a JSON object (a PNG, the metrics text): no error code to read
        code = None
    refused = response.status_code in REQUEST_REFUSALS or code == "invalid_request"
    assert not refused, f"schema-valid request refused by the server: {response.status_code} {code}"
    return None


@schemathesis.serializer("model/vnd.usda", "model/vnd.usdz+zip")
def usd_body(ctx, value) -> bytes:
    """USD bodies are sent as generated: text as UTF-8, binary as is (a package or not)."""
    return value if isinstance(value, bytes) else str(value).encode()
