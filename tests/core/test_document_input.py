"""What the document reader makes of encodings and nesting (issue 8): every declared encoding
Python knows is read, any other is an invalid document, and deep nesting is refused while parsing."""
import pytest

from shadergen.document import MAX_NESTING, parse_document
from shadergen.errors import ShaderGenError

DOC = '<?xml version="1.0" encoding="{}"?><materialx version="1.39"><nodegraph name="グラフ"/></materialx>'


@pytest.mark.parametrize("encoding", ["shift_jis", "utf-32", "utf-16", "euc-jp", "utf-8"])
def test_multibyte_encodings_are_decoded_as_declared(encoding):
    doc = parse_document(DOC.format(encoding).encode(encoding))
    assert doc.root.children[0].get("name") == "グラフ"


def test_text_ignores_the_encoding_its_declaration_names():
    assert parse_document(DOC.format("utf-32")).root.children[0].get("name") == "グラフ"


@pytest.mark.parametrize("raw, message", [
    (DOC.format("x-bogus").encode(), "unknown encoding 'x-bogus'"),
    (b'<?xml version="1.0" encoding="utf-32"?><materialx version="1.39"/>', "not valid utf-32"),
    ('<materialx version="1.39" a="\ud800"/>', "unpaired surrogate"),
])
def test_undecodable_documents_are_invalid(raw, message):
    with pytest.raises(ShaderGenError) as err:
        parse_document(raw)
    assert err.value.code == "invalid_document" and message in err.value.message


def test_nesting_is_bounded_while_parsing():
    ok = b"<materialx>" + b"<a>" * (MAX_NESTING - 1) + b"</a>" * (MAX_NESTING - 1) + b"</materialx>"
    parse_document(ok)
    deep = b"<materialx>" + b"<a>" * 200_000 + b"</a>" * 200_000 + b"</materialx>"
    with pytest.raises(ShaderGenError) as err:
        parse_document(deep)
    assert err.value.code == "invalid_document" and err.value.where.startswith("<document>:1:")
