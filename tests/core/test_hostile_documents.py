"""Hostile and unusual XML through the real CLI and the document reader: every refusal is a record
with a code and a place, one bad document does not stop the others, nothing outside the document is
read, and what XML allows around the elements (namespaces, comments, text) changes nothing."""
import json

from shadergen.document import MAX_NESTING, XINCLUDE, parse_document, read_document

from .conftest import doc
from .test_cli import SIN, run

SECRET = "the contents of a file no document may read"


def hostile_documents(folder) -> dict[str, tuple[str, str]]:
    """name -> (document text, the error code it must get)"""
    (folder / "secret.txt").write_text(SECRET)
    secret_uri = (folder / "secret.txt").as_uri()
    (folder / "with_dtd.mtlx").write_text('<!DOCTYPE materialx [<!ENTITY e "x">]>' + doc(""))
    nested = "<nodegraph name='g'>" * MAX_NESTING + "</nodegraph>" * MAX_NESTING
    return {
        "laughs": ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaaaaaaaa">'
                   + "".join(f'<!ENTITY {b} "{("&" + a + ";") * 10}">' for a, b in zip("abcdefgh", "bcdefghi"))
                   + ']><materialx version="1.39"><input name="x" type="string" value="&i;"/></materialx>',
                   "unsafe_xml"),
        "external_entity": (f'<!DOCTYPE m [<!ENTITY x SYSTEM "{secret_uri}">]>'
                            '<materialx version="1.39"><input name="x" type="string" value="&x;"/></materialx>',
                            "unsafe_xml"),
        "external_dtd": (f'<!DOCTYPE materialx SYSTEM "{secret_uri}"><materialx version="1.39"/>', "unsafe_xml"),
        "dtd_in_an_include": (doc('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="with_dtd.mtlx"/>'),
                              "unsafe_xml"),
        "undeclared_entity": (doc('<input name="x" type="string" value="&x;"/>'), "invalid_document"),
        "nested_too_deep": (doc(nested), "invalid_document"),
    }


def test_hostile_documents_are_error_records_and_the_others_still_generate(tmp_path):
    hostile = hostile_documents(tmp_path)
    paths = []
    for name, (text, _) in hostile.items():
        paths.append(tmp_path / f"{name}.mtlx")
        paths[-1].write_text(text)
    (tmp_path / "fine.mtlx").write_text(SIN)
    p = run("generate", *map(str, paths), str(tmp_path / "fine.mtlx"))
    assert p.returncode == 1 and "Traceback" not in p.stderr
    records = [json.loads(line) for line in p.stdout.splitlines()]
    assert [(r["document"], r["error"]["code"]) for r in records[:-1]] == [
        (str(path), code) for path, (_, code) in zip(paths, hostile.values())]
    assert all(r["error"]["message"] and r["error"]["where"] for r in records[:-1])
    assert "stages" in records[-1] and records[-1]["document"] == str(tmp_path / "fine.mtlx")
    assert SECRET not in p.stdout + p.stderr
    by_name = dict(zip(hostile, records))
    # expat places an error inside an attribute value at the start of its element
    assert by_name["undeclared_entity"]["error"]["where"] == f"{tmp_path / 'undeclared_entity.mtlx'}:3:0"
    assert by_name["nested_too_deep"]["error"]["where"].startswith(f"{tmp_path / 'nested_too_deep.mtlx'}:3:")
    assert "with_dtd.mtlx" in by_name["dtd_in_an_include"]["error"]["where"]


def test_an_include_is_known_by_its_namespace_not_its_prefix(tmp_path):
    (tmp_path / "defs.mtlx").write_text(doc('<constant name="c" type="float"/>'))
    main = tmp_path / "main.mtlx"
    main.write_text(doc('<inc:include xmlns:inc="http://www.w3.org/2001/XInclude" href="defs.mtlx"/>'
                        '<xi:include xmlns:xi="urn:not-xinclude" href="defs.mtlx"/>'))
    root = read_document(str(main)).root
    assert [(c.category, c.name) for c in root.children] == [("constant", "c"), ("{urn:not-xinclude}include", "")]
    assert root.children[1].category != XINCLUDE and root.children[0].source == str(tmp_path / "defs.mtlx")


def test_comments_text_and_instructions_change_nothing_and_attributes_keep_their_order():
    plain = doc('<constant type="float" name="c" uiname="C"><input value="1" name="value" type="float"/></constant>')
    noisy = doc('<!-- a comment --><?editor layout="grid"?>some text<constant type="float" name="c" uiname="C">'
                '<![CDATA[<input name="not_an_element"/>]]>&amp;&#65;<input value="1" name="value" type="float"/>'
                '<!-- <input name="commented_out"/> --></constant>')

    def tree(e):
        return e.category, list(e.attrs.items()), [tree(c) for c in e.children]

    assert tree(parse_document(noisy).root) == tree(parse_document(plain).root)
    constant = parse_document(noisy).root.child("c")
    assert list(constant.attrs) == ["type", "name", "uiname"]
    assert list(constant.children[0].attrs) == ["value", "name", "type"]
