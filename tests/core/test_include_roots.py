"""An upload's xi:include read from the configured include roots only (document.IncludeRoots):
relative hrefs inside the root they are found in, nested includes relative to their file and
confined to the same root, an included file's relative fileprefix made absolute from its own
folder; anything leaving the roots refused before it is read."""
import os

import pytest

from shadergen.document import parse_document
from shadergen.errors import ShaderGenError

from .conftest import doc

XI = 'xmlns:xi="http://www.w3.org/2001/XInclude"'


def include(href: str) -> str:
    return doc(f'<xi:include {XI} href="{href}"/>')


def constant(name: str, value: str = "2") -> str:
    return doc(f'<constant name="{name}" type="float"><input name="value" type="float" value="{value}"/></constant>')


@pytest.fixture
def roots(tmp_path):
    """Two roots (the second holds what the first lacks) and a secret beside them."""
    first, second = tmp_path / "first", tmp_path / "second"
    (first / "looks").mkdir(parents=True)
    second.mkdir()
    (tmp_path / "secret.mtlx").write_text(constant("secret"))
    (first / "looks" / "base.mtlx").write_text(constant("base"))
    (second / "other.mtlx").write_text(constant("other"))
    return [os.path.realpath(first), os.path.realpath(second)]


def refused(text: str, roots, code: str = "include_refused") -> ShaderGenError:
    with pytest.raises(ShaderGenError) as e:
        parse_document(text, allow_includes=False, include_roots=roots)
    assert e.value.code == code and e.value.where
    return e.value


def test_an_upload_includes_files_from_any_root(roots):
    d = parse_document(include("looks/base.mtlx") + "", allow_includes=False, include_roots=roots)
    assert d.root.child("base").category == "constant"
    d = parse_document(include("other.mtlx"), allow_includes=False, include_roots=roots)
    assert d.root.child("other").category == "constant"


def test_without_roots_an_upload_still_may_include_nothing(roots):
    refused(include("looks/base.mtlx"), ())


@pytest.mark.parametrize("href", ["../secret.mtlx", "looks/../../secret.mtlx", "/etc/passwd",
                                  "file:///etc/passwd", "looks\\..\\..\\secret.mtlx"])
def test_an_href_leaving_the_roots_is_refused_before_it_is_read(roots, href):
    error = refused(include(href), roots)
    assert "secret" not in error.message.replace(href, "")


def test_a_link_out_of_the_root_is_refused(roots, tmp_path):
    os.symlink(tmp_path / "secret.mtlx", os.path.join(roots[0], "link.mtlx"))
    refused(include("link.mtlx"), roots)


def test_a_missing_file_is_invalid(roots):
    refused(include("looks/none.mtlx"), roots, "invalid_document")


def test_nested_includes_are_relative_to_their_file_and_stay_in_its_root(roots):
    looks = os.path.join(roots[0], "looks")
    with open(os.path.join(looks, "look.mtlx"), "w") as f:
        f.write(include("base.mtlx"))
    d = parse_document(include("looks/look.mtlx"), allow_includes=False, include_roots=roots)
    assert d.root.child("base").category == "constant"
    # the second root's file, from the first root's folder, is outside that root
    with open(os.path.join(looks, "escape.mtlx"), "w") as f:
        f.write(include("../../second/other.mtlx"))
    refused(include("looks/escape.mtlx"), roots)


def test_an_included_files_relative_fileprefix_is_made_absolute_from_its_folder(roots):
    looks = os.path.join(roots[0], "looks")
    with open(os.path.join(looks, "textured.mtlx"), "w") as f:
        f.write('<?xml version="1.0"?>\n<materialx version="1.39" fileprefix="../images/">'
                '<image name="i" type="color3"><input name="file" type="filename" value="a.png"/></image>'
                '<nodegraph name="g" fileprefix="maps/"/></materialx>')
    d = parse_document(include("looks/textured.mtlx"), allow_includes=False, include_roots=roots)
    assert d.root.child("i").get("fileprefix") == os.path.join(roots[0], "images", "")
    assert d.root.child("g").get("fileprefix") == os.path.join(looks, "maps", "")
