import pytest

from shadergen.document import parse_document, read_document
from shadergen.errors import ShaderGenError

from .conftest import doc


def test_entity_expansion_is_refused():
    bomb = ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;">]>'
            '<materialx version="1.39"><input name="x" type="string" value="&b;"/></materialx>')
    with pytest.raises(ShaderGenError) as e:
        parse_document(bomb)
    assert e.value.code == "unsafe_xml"


def test_external_entity_is_refused():
    xxe = ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
           '<materialx version="1.39"><input name="x" type="string" value="&x;"/></materialx>')
    with pytest.raises(ShaderGenError) as e:
        parse_document(xxe)
    assert e.value.code == "unsafe_xml"


def test_malformed_xml_names_the_line():
    with pytest.raises(ShaderGenError) as e:
        parse_document('<?xml version="1.0"?>\n<materialx>\n<add name="a" type="float">\n</materialx>')
    assert e.value.code == "invalid_document"
    assert e.value.where.startswith("<document>:4")


def test_xinclude_resolves_relative_to_the_document(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "defs.mtlx").write_text(doc('<constant name="c" type="float"><input name="value" type="float" value="2"/></constant>'))
    main = tmp_path / "main.mtlx"
    main.write_text(doc('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="sub/defs.mtlx"/>'))
    d = read_document(str(main))
    assert d.root.child("c").category == "constant"


def test_xinclude_refused_for_uploads():
    text = doc('<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="/etc/passwd"/>')
    with pytest.raises(ShaderGenError) as e:
        parse_document(text, allow_includes=False)
    assert e.value.code == "include_refused"


def test_udim_token_in_attribute_is_accepted():
    d = parse_document(doc('<image name="i" type="color3"><input name="file" type="filename" value="a.<UDIM>.png"/></image>'))
    assert d.root.child("i").child("file").get("value") == "a.<UDIM>.png"


def test_upgrade_from_1_38_renames_swizzle():
    d = parse_document(doc('<swizzle name="s" type="float"><input name="in" type="color3" value="1,2,3"/>'
                           '<input name="channels" type="string" value="g"/></swizzle>', version="1.38"))
    s = d.root.child("s")
    assert s.category == "extract" and s.child("index").get("value") == "1"
