import json
from pathlib import Path

from shadergen.api import Generator
from shadergen.library import CHECKSUM_SIZE, Library, cache_dir

from .conftest import doc

VERSIONED = '''
<nodedef name="ND_tint_v1" node="tint" version="1.0"><input name="in" type="float" value="1"/><output name="out" type="float"/></nodedef>
<nodedef name="ND_tint_v2" node="tint" version="2.0" isdefaultversion="true"><input name="in" type="float" value="1"/><output name="out" type="float"/></nodedef>
<implementation name="IM_tint_v1" nodedef="ND_tint_v1" target="genglsl" sourcecode="{{in}} * 0.5" />
<implementation name="IM_tint_v2" nodedef="ND_tint_v2" target="genglsl" sourcecode="{{in}} * 2.0" />
'''


def test_default_version_and_explicit_version(gen):
    default = gen.prepare(doc(VERSIONED + '<tint name="t" type="float"/><output name="o" type="float" nodename="t"/>'), names="document").emit()
    v1 = gen.prepare(doc(VERSIONED + '<tint name="t" type="float" version="1.0"/><output name="o" type="float" nodename="t"/>'), names="document").emit()
    assert "t_in * 2.0" in default["stages"]["pixel"] and "t_in * 0.5" in v1["stages"]["pixel"]


def test_nodedef_attribute_wins(gen):
    rec = gen.prepare(doc(VERSIONED + '<tint name="t" type="float" nodedef="ND_tint_v1"/><output name="o" type="float" nodename="t"/>'), names="document").emit()
    assert "t_in * 0.5" in rec["stages"]["pixel"]


def test_resolution_by_input_types(gen):
    rec = gen.prepare(doc('<multiply name="m" type="color3"><input name="in1" type="color3" value="1,1,1"/>'
                          '<input name="in2" type="float" value="2"/></multiply><output name="o" type="color3" nodename="m"/>')).emit()
    assert {v["path"]: v["type"] for v in rec["blocks"]["pixel"]["PublicUniforms"]}["m/in2"] == "float"


def test_nodedef_inheritance(gen):
    text = doc('<nodedef name="ND_base" node="basenode"><input name="a" type="float" value="3"/><output name="out" type="float"/></nodedef>'
               '<nodedef name="ND_child" node="childnode" inherit="ND_base"><input name="b" type="float" value="4"/><output name="out" type="float"/></nodedef>'
               '<implementation name="IM_child" nodedef="ND_child" target="genglsl" sourcecode="{{a}} + {{b}}" />'
               '<childnode name="c" type="float"/><output name="o" type="float" nodename="c"/>')
    rec = gen.prepare(text, names="document").emit()
    assert "c_a + c_b" in rec["stages"]["pixel"]


def test_parsed_library_is_cached_on_disk_and_rebuilt_when_corrupt(tmp_path, monkeypatch):
    monkeypatch.setenv("SHADERGEN_CACHE_DIR", str(tmp_path))
    first = Library.load()
    cached = list(Path(cache_dir()).glob("library-*.jsonl"))
    assert len(cached) == 1 and cached[0].name.startswith(f"library-{first.content_hash[:24]}")
    text = cached[0].read_text()
    lines = [json.loads(line) for line in text.splitlines()]  # JSON Lines, never a pickle
    # the checksum, the index (every library file), the nodedefs' output types, then each definition's children
    assert len(lines[0]) == CHECKSUM_SIZE and len(lines[1]) == len(first.roots) and lines[2] == first.output_types
    assert len(lines) > 500
    cached[0].write_text("{corrupt")
    again = Library.load()
    assert again.content_hash == first.content_hash and len(again.nodedefs) == len(first.nodedefs)
    assert Generator(again).prepare(doc('<sin name="s" type="float"/><output name="o" type="float" nodename="s"/>')).emit()
    # Damage that is still JSON (a definition's children, decoded only when read) is caught by the
    # file's checksum up front: the library is rebuilt, never broken later.
    assert cached[0].read_text() == text
    damaged = text.replace('"name":"in"', '"name":"im"', 1)
    assert damaged != text
    [json.loads(line) for line in damaged.splitlines()]
    cached[0].write_text(damaged)
    rebuilt = Library.load()
    assert [i.name for i in rebuilt.nodedefs["ND_sin_float"].children] == \
        [i.name for i in first.nodedefs["ND_sin_float"].children]
    assert cached[0].read_text() == text
