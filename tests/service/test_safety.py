"""Checks on uploads that run before any parser: DTDs refused, text decoded, texture paths confined."""
import pytest

from service.errors import ServiceError
from service.safety import check_document, check_texture_paths

BOMB = b"""<?xml version="1.0"?>
<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">]>
<materialx version="1.39">&lol2;</materialx>"""
EXTERNAL = b"""<?xml version="1.0"?>
<!DOCTYPE m [<!ENTITY xxe SYSTEM "file:///etc/passwd">]><materialx version="1.39">&xxe;</materialx>"""


@pytest.mark.parametrize("raw", [BOMB, EXTERNAL])
def test_dtds_are_refused(raw):
    with pytest.raises(ServiceError) as err:
        check_document(raw)
    assert err.value.code == "unsafe_xml" and err.value.status == 400


def test_text_must_be_utf8():
    assert check_document(b"\xef\xbb\xbf<materialx/>") == "<materialx/>"
    with pytest.raises(ServiceError) as err:
        check_document(b"<materialx name='\xff'/>")
    assert err.value.code == "invalid_document"


def _record(value):
    var = {"name": "img_file", "type": "filename", "value": value, "path": "NG/img/file"}
    return {"blocks": {"pixel": {"PublicUniforms": [var]}}}


def test_texture_paths_confined_to_roots(tmp_path):
    root = tmp_path / "textures"
    (root / "sub").mkdir(parents=True)
    (tmp_path / "secret.png").write_bytes(b"x")
    (root / "link.png").symlink_to(tmp_path / "secret.png")
    roots = [str(root)]
    for ok in ("a.png", "sub/b.png", str(root / "c.png"), ""):
        check_texture_paths(_record(ok), roots)
    for bad in ("/etc/passwd", "../secret.png", "sub/../../secret.png", "link.png", "file:///etc/passwd",
                "http://example.invalid/x.png", str(tmp_path / "secret.png")):
        with pytest.raises(ServiceError) as err:
            check_texture_paths(_record(bad), roots)
        assert err.value.code == "path_not_allowed" and err.value.where == "NG/img/file"


def test_no_roots_means_no_textures():
    with pytest.raises(ServiceError):
        check_texture_paths(_record("a.png"), [])


def test_a_root_configured_through_a_link_holds_textures_named_either_way(tmp_path):
    real = tmp_path / "store" / "textures"
    real.mkdir(parents=True)
    (real / "brick.png").write_bytes(b"x")
    (tmp_path / "secret.png").write_bytes(b"x")
    link = tmp_path / "textures"
    link.symlink_to(real)
    roots = [str(link)]
    for ok in (str(link / "brick.png"), str(real / "brick.png"), "brick.png"):
        check_texture_paths(_record(ok), roots)
    for bad in (str(link / ".." / "secret.png"), str(tmp_path / "secret.png"), "../secret.png"):
        with pytest.raises(ServiceError) as err:
            check_texture_paths(_record(bad), roots)
        assert err.value.code == "path_not_allowed"
