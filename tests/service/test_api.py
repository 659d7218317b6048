"""The real server (`shadergen serve`, two API workers) on 127.0.0.1: every endpoint, the cache,
and bad input answered with the contract's error object, never a 500."""
import socket
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from service.models import ShaderRecord
from shadergen.fingerprint import output_key
from shadergen.library import library_root
from service_testing import HOST, assert_error, Server, document, receive_head

XML = {"content-type": "application/xml"}
MIB = 1024 * 1024


def generate(client, name_or_text: str, **params):
    text = document(name_or_text) if name_or_text.endswith(".mtlx") else name_or_text
    return client.post("/v1/generate", json={"document": text, **params})


# -- endpoints ---------------------------------------------------------------------------------
def test_healthz(client):
    body = client.get("/healthz").json()
    assert body["status"] == "ok" and body["library_hash"] == output_key(library_root())  # what request digests use
    assert body["cache"] == "SQLiteStore" and body["jobs"] == "local"


def test_generate_json_returns_the_contract_record(client):
    r = generate(client, "ramp.mtlx", target="essl", interface="reduced")
    assert r.status_code == 200, r.text
    rec = r.json()
    assert rec["document"] is None and rec["element"] == "NG_ramp/out"
    assert rec["target"] == "essl" and rec["interface"] == "reduced"
    assert "void main()" in rec["stages"]["pixel"]
    assert set(rec["blocks"]) == {"vertex", "pixel"}
    assert rec["timings_ms"]["generate"] >= 0


def test_generate_wgsl_returns_both_modules_and_the_buffer_layout(client):
    rec = generate(client, "ramp.mtlx", target="wgsl").json()
    assert rec["target"] == "wgsl", rec
    assert "@fragment" in rec["stages"]["pixel"] and "@vertex" in rec["stages"]["vertex"]
    members = {m["name"]: m for m in rec["layout"]["pixel"]["members"]}
    in2 = next(v["name"] for v in rec["blocks"]["pixel"]["PublicUniforms"] if v["path"].endswith("mul/in2"))
    assert in2 in members and members[in2]["offset"] % 4 == 0
    assert f"pu.{in2}" in rec["stages"]["pixel"]
    listed = client.post("/v1/generate?target=wgsl&source=false", content=document("ramp.mtlx"), headers=XML).json()
    assert listed["stages"] == {"vertex": None, "pixel": None} and listed["layout"] == rec["layout"]


def test_generate_raw_xml_with_query_parameters(client):
    r = client.post("/v1/generate?target=glsl&element=NG_ramp/out", content=document("ramp.mtlx"), headers=XML)
    assert r.status_code == 200, r.text
    assert r.json()["element"] == "NG_ramp/out"


def test_source_false_gives_listings_only(client):
    rec = generate(client, "ramp.mtlx", source=False).json()
    assert rec["stages"] == {"vertex": None, "pixel": None}
    ShaderRecord.model_validate(rec)  # the response model (and so openapi.yaml) says a stage may be null
    names = [v["name"] for v in rec["blocks"]["pixel"]["PublicUniforms"]]
    assert any(name.endswith("_in2") for name in names)


def test_names_document_keeps_the_documents_names_in_the_source(client):
    """Structural names by default (issue 23); `names: "document"` in the JSON body or the query
    keeps the node names, and is another record."""
    structural = generate(client, "ramp.mtlx").json()
    named = generate(client, "ramp.mtlx", names="document").json()
    queried = client.post("/v1/generate?names=document", content=document("ramp.mtlx"), headers=XML).json()
    assert "mul_in2" not in structural["stages"]["pixel"] and "mul_in2" in named["stages"]["pixel"]
    assert queried["stages"] == named["stages"] and named["hash"] != structural["hash"]
    assert_error(generate(client, "ramp.mtlx", names="anonymous"), 422, "invalid_request")


def test_specialized_with_keep_leaves_chosen_inputs_live(client):
    folded = generate(client, "ramp.mtlx", interface="specialized").json()
    kept = generate(client, "ramp.mtlx", interface="specialized", keep=["NG_ramp/mul/in2"]).json()
    assert folded["interface"] == "specialized" and folded["passes"]["fold"] >= 0
    assert [v["path"] for v in kept["blocks"]["pixel"]["PublicUniforms"]] == ["NG_ramp/mul/in2"]
    assert folded["blocks"]["pixel"]["PublicUniforms"] == [] and kept["hash"] != folded["hash"]


ACES_DOC = ('<?xml version="1.0"?><materialx version="1.39" colorspace="acescg"><nodegraph name="g">'
            '<constant name="c" type="color3"><input name="value" type="color3" value="0.5, 0.5, 0.5" '
            'colorspace="{space}" /></constant><output name="out" type="color3" nodename="c" /></nodegraph>'
            '</materialx>')
CG_CONFIG = "ocio://cg-config-v2.1.0_aces-v1.3_ocio-v2.3"


def test_ocio_colour_management_by_json_and_query(client):
    """cms and ocio_config reach the generator and its cache key; a space the config lacks is a 422
    unknown_colorspace; a config file a request names is refused (the server reads none)."""
    text = ACES_DOC.format(space="ACEScc")
    managed = generate(client, text, cms="ocio", ocio_config=CG_CONFIG)
    assert managed.status_code == 200, managed.text
    rec = managed.json()
    assert rec["luts"] and "cm_acescc_to_acescg" in rec["stages"]["pixel"]
    builtin = generate(client, text).json()
    assert builtin["hash"] != rec["hash"] and "luts" not in builtin
    query = client.post(f"/v1/generate?cms=ocio&ocio_config={CG_CONFIG}", content=text, headers=XML).json()
    assert query["hash"] == rec["hash"]
    assert_error(generate(client, ACES_DOC.format(space="Made Up"), cms="ocio"), 422, "unknown_colorspace")
    assert_error(generate(client, text, cms="ocio", ocio_config="/etc/passwd"), 422, "invalid_request")


def test_get_shader_by_hash(client):
    rec = generate(client, "ramp.mtlx", target="essl").json()
    got = client.get(f"/v1/shaders/{rec['hash']}", params={"target": "essl"})
    assert got.status_code == 200 and got.json()["stages"] == rec["stages"] and got.json()["cached"] is True
    assert_error(client.get(f"/v1/shaders/{rec['hash']}", params={"target": "glsl"}), 404, "not_found")
    assert_error(client.get("/v1/shaders/" + "0" * 64), 404, "not_found")
    assert_error(client.get("/v1/shaders/not-a-hash"), 422, "invalid_request")


def test_nodedefs(client):
    defs = client.get("/v1/nodedefs").json()
    add = next(d for d in defs if d["name"] == "ND_add_float")
    assert add["node"] == "add" and [i["name"] for i in add["inputs"]] == ["in1", "in2"]


def test_metrics(client):
    generate(client, "ramp.mtlx")
    text = client.get("/metrics").text
    for name in ("shadergen_requests_total", "shadergen_request_seconds_bucket", "shadergen_cache_total",
                 "shadergen_queue_depth", "shadergen_render_seconds", "shadergen_generate_seconds"):
        assert name in text
    assert 'route="/v1/generate"' in text


# -- the cache ---------------------------------------------------------------------------------
def test_second_identical_request_is_cached(client):
    text = document("ramp.mtlx").replace("0.5", "0.125")  # a graph no other test generates
    first, second = generate(client, text).json(), generate(client, text).json()
    assert first["cached"] is False and second["cached"] is True
    assert first["hash"] == second["hash"] and first["stages"] == second["stages"]


def test_equivalent_xml_hits_and_changed_value_misses(client):
    base = generate(client, "ramp.mtlx", target="glsl", interface="complete").json()
    same = generate(client, "ramp_equivalent.mtlx", target="glsl", interface="complete").json()
    assert same["cached"] is True and same["hash"] == base["hash"] and same["stages"] == base["stages"]
    changed = generate(client, "ramp_changed.mtlx").json()
    assert changed["hash"] != base["hash"] and changed["cached"] is False
    other_mode = generate(client, "ramp.mtlx", interface="reduced").json()
    assert other_mode["hash"] != base["hash"]


def test_cache_is_shared_by_all_workers(server, client):
    text = document("ramp.mtlx").replace("0.5", "0.375")
    generate(client, text)
    # new connections land on either worker; every answer comes from the one store
    from httpx import Client

    with ThreadPoolExecutor(8) as pool:
        recs = list(pool.map(lambda _: Client(base_url=server.url, timeout=60).post(
            "/v1/generate", json={"document": text}).json(), range(16)))
    assert all(r["cached"] for r in recs)


# -- bad input ---------------------------------------------------------------------------------
BOMB = """<?xml version="1.0"?>
<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
<!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">]>
<materialx version="1.39"><nodegraph name="&lol3;"/></materialx>"""
EXTERNAL_ENTITY = """<?xml version="1.0"?>
<!DOCTYPE m [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>
<materialx version="1.39"><nodegraph name="&xxe;"/></materialx>"""
INCLUDE = """<?xml version="1.0"?>
<materialx version="1.39" xmlns:xi="http://www.w3.org/2001/XInclude">
  <xi:include href="/etc/passwd" parse="text"/>
</materialx>"""


@pytest.mark.parametrize("doc", [BOMB, EXTERNAL_ENTITY])
def test_xml_bombs_and_external_entities_are_refused(client, doc):
    assert_error(generate(client, doc), 400, "unsafe_xml")
    assert_error(client.post("/v1/generate", content=doc, headers=XML), 400, "unsafe_xml")


def test_xinclude_never_reads_server_files(client):
    err = assert_error(generate(client, INCLUDE), 400, "include_refused")
    assert "root:" not in err["message"]


def test_body_over_the_limit_is_refused_before_reading(client):
    r = client.post("/v1/generate", content=b"<" + b" " * (2 * MIB), headers=XML)
    assert_error(r, 413, "too_large")


@pytest.mark.parametrize("route", ["/v1/generate", "/v1/thumbnails"])  # thumbnails: issue 8
def test_chunked_body_over_the_limit_is_cut_off_while_streaming(server, route):
    head = (f"POST {route} HTTP/1.1\r\nHost: {HOST}\r\nContent-Type: application/json\r\n"
            "Transfer-Encoding: chunked\r\n\r\n").encode()
    chunk = b" " * 65536
    with socket.create_connection((HOST, server.port), timeout=30) as s:
        s.sendall(head)
        try:
            for _ in range(64):  # 4 MiB at most: the server answers before the end
                s.sendall(b"%x\r\n%s\r\n" % (len(chunk), chunk))
            s.sendall(b"0\r\n\r\n")
        except (BrokenPipeError, ConnectionResetError):
            pass
        response = receive_head(s)
    assert response.startswith(b"HTTP/1.1 413"), response[:200]


@pytest.mark.parametrize("params, status, code", [
    ({"target": "nope"}, 422, "unsupported_target"),
    ({"target": "x" * 65}, 422, "invalid_request"),
    ({"element": "NoSuchElement"}, 422, "unknown_element"),
    ({"interface": "bogus"}, 422, "invalid_request"),
    ({"keep": "NG_ramp/mul/in2"}, 422, "invalid_request"),  # a list of inputs
    ({"keep": [""]}, 422, "invalid_request"),
    ({"unknown_field": 1}, 422, "invalid_request"),
])
def test_bad_parameters(client, params, status, code):
    assert_error(generate(client, "ramp.mtlx", **params), status, code)


@pytest.mark.parametrize("body, headers, status, code", [
    (b"<materialx><bad", XML, 400, "invalid_document"),
    (b"", XML, 400, "invalid_document"),
    (b"/etc/passwd", XML, 400, "invalid_document"),  # a path is not a document
    (b"\xff\xfe<materialx/>", XML, 400, "invalid_document"),
    (b"{not json", {"content-type": "application/json"}, 422, "invalid_request"),
    (b'{"target": "glsl"}', {"content-type": "application/json"}, 422, "invalid_request"),
    (b"[1, 2]", {"content-type": "application/json"}, 422, "invalid_request"),
    (b"hello", {"content-type": "text/plain"}, 415, "unsupported_media_type"),
])
def test_bad_bodies(client, body, headers, status, code):
    assert_error(client.post("/v1/generate", content=body, headers=headers), status, code)


MX = '<?xml version="1.0"?><materialx version="1.39">{}</materialx>'
SELF_INHERITING = ('<nodedef name="ND_a" node="a" inherit="ND_a"><output name="out" type="float"/></nodedef>'
                   '<a name="n" type="float"/><output name="o" type="float" nodename="n"/>')
SELF_INSTANTIATING = ('<nodedef name="ND_t" node="t"><input name="in" type="float" value="1"/>'
                      '<output name="out" type="float"/></nodedef><nodegraph name="NG_t" nodedef="ND_t">'
                      '<t name="again" type="float"><input name="in" type="float" interfacename="in"/></t>'
                      '<output name="out" type="float" nodename="again"/></nodegraph>'
                      '<t name="n" type="float"/><output name="o" type="float" nodename="n"/>')
HUGE_INTEGER = ('<switch name="s" type="float"><input name="which" type="integer" value="1' + "0" * 400 + '"/>'
                '</switch><output name="o" type="float" nodename="s"/>')
COLOR_INTO_FLOAT = ('<constant name="c" type="color3"><input name="value" type="color3" value="1,0,0"/></constant>'
                    '<add name="a" type="float"><input name="in1" type="float" nodename="c"/></add>'
                    '<output name="o" type="float" nodename="a"/>')


@pytest.mark.parametrize("body, code, where", [
    (SELF_INHERITING, "cycle", "ND_a"),
    (SELF_INSTANTIATING, "cycle", "NG_t"),
    (HUGE_INTEGER, "invalid_value", "s/which"),
    (COLOR_INTO_FLOAT, "type_mismatch", "a/in1"),
])
def test_cheap_documents_that_cannot_generate_are_refused(client, body, code, where):
    error = assert_error(client.post("/v1/generate", content=MX.format(body), headers=XML), 422, code)
    assert error["where"] == where


def test_json_document_naming_a_server_file_is_not_read(client):
    assert_error(generate(client, "/etc/passwd"), 400, "invalid_document")


def test_unknown_routes_and_methods(client):
    assert_error(client.get("/v1/nope"), 404, "not_found")
    assert_error(client.get("/v1/generate"), 405, "method_not_allowed")


def test_texture_outside_the_roots_is_refused(client):
    err = assert_error(client.post("/v1/thumbnails", json={"document": document("texture_outside.mtlx")}),
                       403, "path_not_allowed")
    assert err["where"] == "NG_tex/img/file"


def test_unknown_job(client):
    assert_error(client.get("/v1/jobs/" + "0" * 32), 404, "not_found")
    assert_error(client.get("/v1/jobs/" + "0" * 32 + "/thumbnail"), 404, "not_found")


def chain_document(n: int) -> str:
    nodes = ['<constant name="n0" type="float"><input name="value" type="float" value="0.5"/></constant>']
    nodes += [f'<add name="n{i}" type="float"><input name="in1" type="float" nodename="n{i - 1}"/>'
              f'<input name="in2" type="float" value="{i}"/></add>' for i in range(1, n)]
    return ('<?xml version="1.0"?><materialx version="1.39"><nodegraph name="NG_chain">' + "\n".join(nodes)
            + f'<output name="out" type="float" nodename="n{n - 1}"/></nodegraph></materialx>')


def nested_document(depth: int) -> str:
    """A small document whose graph doubles with each level: node definition lvl{k} is a nodegraph of
    two lvl{k-1} in a row, so its top node expands to 2^depth additions (a few kB of XML, work that no
    speed-up of the generator brings under a second at depth 16)."""
    defs = ['<nodedef name="ND_lvl0" node="lvl0"><input name="in" type="float" value="0.5"/>'
            '<output name="out" type="float"/></nodedef>'
            '<nodegraph name="NG_lvl0" nodedef="ND_lvl0"><add name="a" type="float">'
            '<input name="in1" type="float" interfacename="in"/><input name="in2" type="float" value="1.0"/></add>'
            '<output name="out" type="float" nodename="a"/></nodegraph>']
    for k in range(1, depth + 1):
        defs.append(f'<nodedef name="ND_lvl{k}" node="lvl{k}"><input name="in" type="float" value="0.5"/>'
                    f'<output name="out" type="float"/></nodedef>'
                    f'<nodegraph name="NG_lvl{k}" nodedef="ND_lvl{k}">'
                    f'<lvl{k - 1} name="x" type="float"><input name="in" type="float" interfacename="in"/></lvl{k - 1}>'
                    f'<lvl{k - 1} name="y" type="float"><input name="in" type="float" nodename="x"/></lvl{k - 1}>'
                    f'<output name="out" type="float" nodename="y"/></nodegraph>')
    return ('<?xml version="1.0"?><materialx version="1.39">' + "\n".join(defs)
            + f'<lvl{depth} name="top" type="float"><input name="in" type="float" value="0.25"/></lvl{depth}>'
            + '<output name="out" type="float" nodename="top"/></materialx>')


@pytest.fixture(scope="module")
def slow_server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("slow"), workers=1, render_workers=1,
                 env={"SHADERGEN_GENERATE_TIMEOUT_S": "1"})
    yield srv
    srv.close()


def test_runaway_generation_is_stopped_and_the_worker_replaced(slow_server):
    client = slow_server.client
    # a 10,000-node chain ran past the limit until generation got faster (742 ms): a doubling graph
    # keeps the test about the limit, not about the generator's speed
    r = client.post("/v1/generate", json={"document": nested_document(16), "element": "out"})
    err = assert_error(r, 504, "timeout")  # the server's limit, not the client's fault: try again later
    assert "time limit" in err["message"] and int(r.headers["Retry-After"]) > 0
    assert generate(client, "ramp.mtlx").status_code == 200  # a fresh generator took over


def test_deep_graph_is_generated_not_a_recursion_error(client):
    r = generate(client, chain_document(1500))
    assert r.status_code == 200, r.text


def test_cache_file_destroyed_under_a_running_server_is_rebuilt(slow_server):
    client = slow_server.client
    text = document("ramp.mtlx").replace("0.5", "0.875")
    assert generate(client, text).json()["cached"] is False
    path = slow_server.cache_path
    for suffix in ("", "-wal", "-shm"):
        path.with_name(path.name + suffix).unlink(missing_ok=True)
    path.write_bytes(b"garbage, not a database " * 1000)
    time.sleep(1.1)  # processes look for a replaced file at most once a second
    again = generate(client, text)
    assert again.status_code == 200 and again.json()["cached"] is False  # the entry went with the file
    assert generate(client, text).json()["cached"] is True


def test_a_changed_value_keeps_the_topology_and_source_unless_values_go_into_the_source(client):
    base = generate(client, "ramp.mtlx").json()
    changed = generate(client, "ramp_changed.mtlx").json()
    assert changed["topology_hash"] == base["topology_hash"] and changed["stages"] == base["stages"]
    values = [{v["path"]: v["value"] for v in r["blocks"]["pixel"]["PublicUniforms"]} for r in (base, changed)]
    assert values[0] != values[1] and 0.25 in values[1].values()  # the changed document's own value
    in_source = [generate(client, name, values="source").json() for name in ("ramp.mtlx", "ramp_changed.mtlx")]
    assert in_source[0]["hash"] != base["hash"] and in_source[0]["stages"] != in_source[1]["stages"]
    assert_error(generate(client, "ramp.mtlx", values="inline"), 422, "invalid_request")
