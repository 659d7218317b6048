"""Value-free source (complete, reduced): materials that differ only in values share one source and
one topology hash; the values live in the listing, and `values: "source"` writes them into the code."""
import pytest

from shadergen import hashing
from shadergen.api import Generator
from shadergen.errors import ShaderGenError

GEN = Generator()


def material(base_color="0.1, 0.25, 0.7", roughness="0.35", coat_connection=False) -> str:
    coat = ('<input name="coat" type="float" nodename="coat_amount" />' if coat_connection
            else '<input name="coat" type="float" value="0.8" />')
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <multiply name="coat_amount" type="float">
    <input name="in1" type="float" value="0.8" /><input name="in2" type="float" value="0.5" />
  </multiply>
  <standard_surface name="SR" type="surfaceshader">
    <input name="base_color" type="color3" value="{base_color}" />
    <input name="specular_roughness" type="float" value="{roughness}" />
    {coat}
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR" />
  </surfacematerial>
</materialx>"""


def listing_value(record: dict, path: str):
    return next(v["value"] for v in record["blocks"]["pixel"]["PublicUniforms"] if v["path"] == path)


def uniform_name(record: dict, path: str) -> str:
    return next(v["name"] for v in record["blocks"]["pixel"]["PublicUniforms"] if v["path"] == path)


def test_value_only_differences_share_source_and_topology_hash():
    a = GEN.prepare(material()).emit()
    b = GEN.prepare(material(base_color="0.9, 0.5, 0.1", roughness="0.6")).emit()
    assert a["stages"] == b["stages"]
    assert a["topology_hash"] == b["topology_hash"]
    assert a["hash"] != b["hash"]
    assert listing_value(a, "SR/specular_roughness") == 0.35
    assert listing_value(b, "SR/specular_roughness") == 0.6


def test_reduced_topology_hash_follows_what_decides_the_source():
    """In `reduced` the drawn element's inputs are uniforms (value-free); the values of the nodes
    behind it are constants of the code, so they are part of its topology."""
    drawn = dict(element="SR", interface="reduced")
    a = GEN.prepare(material(), **drawn).emit()
    b = GEN.prepare(material(roughness="0.6"), **drawn).emit()
    assert a["stages"] == b["stages"] and a["topology_hash"] == b["topology_hash"] and a["hash"] != b["hash"]
    constants = GEN.prepare(material(), interface="reduced").emit(), GEN.prepare(material(roughness="0.6"),
                                                                                interface="reduced").emit()
    assert constants[0]["stages"] != constants[1]["stages"]
    assert constants[0]["topology_hash"] != constants[1]["topology_hash"]


def test_a_record_of_the_same_topology_rebinds_to_what_emission_gives():
    first = GEN.prepare(material()).emit()
    edited = GEN.prepare(material(base_color="0.9, 0.5, 0.1", roughness="0.6"))
    rebound, emitted = edited.rebind(first), edited.emit()
    assert rebound is not None
    assert {**rebound, "timings_ms": None} == {**emitted, "timings_ms": None}
    other_topology = GEN.prepare(material(coat_connection=True))
    assert other_topology.rebind(first) is None


def test_value_free_initializers_are_the_nodedef_defaults():
    record = GEN.prepare(material(roughness="0.6")).emit()
    declaration = f"uniform float {uniform_name(record, 'SR/specular_roughness')} = 0.2;"
    assert declaration in record["stages"]["pixel"]  # standard_surface's default, not 0.6


def test_a_connection_changes_the_topology_hash():
    a = GEN.prepare(material()).emit()
    b = GEN.prepare(material(coat_connection=True)).emit()
    assert a["topology_hash"] != b["topology_hash"]


def test_values_in_source_are_written_into_initializers():
    a = GEN.prepare(material(roughness="0.6"), values="source").emit()
    b = GEN.prepare(material(roughness="0.7"), values="source").emit()
    assert f"uniform float {uniform_name(a, 'SR/specular_roughness')} = 0.6;" in a["stages"]["pixel"]
    assert a["stages"] != b["stages"] and a["topology_hash"] != b["topology_hash"]
    listing = GEN.prepare(material(roughness="0.6")).emit()
    assert a["hash"] != listing["hash"]  # the same document with a different source is another record


def test_unknown_values_option_is_an_error():
    with pytest.raises(ShaderGenError) as err:
        GEN.prepare(material(), values="inline")
    assert err.value.code == "unsupported_values"


@pytest.mark.parametrize("interface", ["complete", "reduced", "specialized"])
def test_elements_alike_but_for_their_names_have_records_of_their_own(interface):
    """A cache keyed by the hash must not answer one element's request with another's record."""
    graph = ('<?xml version="1.0"?><materialx version="1.39"><nodegraph name="{}">'
             '<constant name="c" type="color3"><input name="value" type="color3" value="0.2, 0.3, 0.4"/></constant>'
             '<output name="out" type="color3" nodename="c"/></nodegraph></materialx>')
    a, b = (GEN.prepare(graph.format(name), interface=interface).emit() for name in ("A", "B"))
    assert (a["element"], b["element"]) == ("A/out", "B/out")
    assert a["hash"] != b["hash"] and a["stages"] == b["stages"]


def scaled(attributes: str) -> str:
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <multiply name="m" type="float"><input name="in1" type="float" value="0.8" {attributes}/></multiply>
  <output name="o" type="float" nodename="m" />
</materialx>"""


@pytest.mark.parametrize("names", ["structural", "document"])
def test_the_hashes_follow_metadata_not_the_order_of_its_attributes(names):
    """A port's metadata (ui hints) is hashed by name and value, whatever order the document wrote
    its attributes in, or code merged them in (hashing.py's `_ordered`: the bytes hashed write a
    dict in its order)."""
    assert hashing._canonical(hashing._ordered({"b": 1, "a": {"d": (2, 3), "c": "x"}})) == \
        hashing._canonical(hashing._ordered({"a": {"c": "x", "d": (2, 3)}, "b": 1}))
    assert hashing._canonical({"b": 1, "a": 2}) != hashing._canonical({"a": 2, "b": 1})
    def hashes(attributes):
        record = GEN.prepare(scaled(attributes), names=names).emit()
        return record["hash"], record["topology_hash"]
    ordered = hashes('uimin="0" uimax="2" uisoftmax="1" uiname="Amount"')
    assert hashes('uiname="Amount" uisoftmax="1" uimax="2" uimin="0"') == ordered
    other = hashes('uimin="0" uimax="3" uisoftmax="1" uiname="Amount"')
    assert other[0] != ordered[0]  # the listing says it: the record differs
    assert (other[1] == ordered[1]) == (names == "structural")  # the source holds it only by document names


def test_a_target_that_writes_ui_into_its_source_keeps_it_in_the_topology_hash():
    """OSL writes a parameter's ui metadata as its hints: two materials whose ui differ have
    sources of their own, so one's record must not be rebound to the other (the service rebinds
    by topology hash); GLSL leaves ui to the listing and shares one source."""
    twins = [scaled(f'uimin="{low}"').replace('value="0.8"', f'value="{value}"')
             for low, value in (("0", "0.8"), ("0.25", "0.3"))]
    for target, shared in (("glsl", True), ("osl", False)):
        a, b = (GEN.prepare(twin, target=target) for twin in twins)
        first, second = a.emit(), b.emit()
        assert (first["stages"] == second["stages"]) == shared == (a.topology_hash == b.topology_hash)
        rebound = b.rebind(first)
        assert (rebound["stages"] == second["stages"]) if shared else rebound is None
