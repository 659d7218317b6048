"""USD as the field writes it (bench/documents/usd_field, in the shapes exporters and converters
write): every material generates but the one in a render context we do not translate (MDL), and
what the field does that a plain reading would lose is kept: 1.38 nodedef ids, animated values."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

from pathlib import Path

import pytest

FIELD = Path(__file__).resolve().parents[2] / "bench" / "documents" / "usd_field"


def field_records(gen, name: str) -> dict[str, dict]:
    return {r["element"]: r for r in gen.records(FIELD / name, all=True)}


@pytest.mark.parametrize("name", sorted(p.name for p in FIELD.glob("*.usda")))
def test_field_materials_generate(gen, name):
    records = field_records(gen, name)
    assert records and None not in records  # materials were found, and no document-level refusal
    refused = {element: r["error"] for element, r in records.items() if "error" in r}
    if name == "mdl_only.usda":  # MDL-only: refused, naming the render context it has
        assert list(refused) == ["/Looks/Concrete_MDL"]
        assert "outputs:mdl:surface" in refused["/Looks/Concrete_MDL"]["message"]
    else:
        assert refused == {}


def test_a_materialx_1_38_nodedef_id_reads_as_its_1_39_nodedef(gen):
    record = field_records(gen, "mtlx_nodes.usda")["/materials/Worn_Gold"]
    assert "error" not in record and "mx_normalmap" in record["stages"]["pixel"]


def test_an_animated_value_is_read_at_its_first_time_sample_with_a_warning(gen):
    record = field_records(gen, "preview_options.usda")["/Looks/Animated_Roughness"]
    [roughness] = [v for v in record["blocks"]["pixel"]["PublicUniforms"]
                   if v["path"] == "/Looks/Animated_Roughness/Surface.inputs:roughness"]
    assert roughness["value"] == pytest.approx(0.1)
    assert any("first time sample" in w for w in record["warnings"])


def test_opacity_mode_tokens_read_as_the_nodedef_enum(gen):
    record = field_records(gen, "preview_options.usda")["/Looks/Frosted_Presence"]
    [mode] = [v for v in record["blocks"]["pixel"]["PublicUniforms"]
              if v["path"] == "/Looks/Frosted_Presence/Surface.inputs:opacityMode"]
    assert mode["value"] == 1


def test_an_unknown_opacity_mode_token_is_an_invalid_value(gen, tmp_path):
    text = (FIELD / "preview_options.usda").read_text().replace('opacityMode = "presence"', 'opacityMode = "ghostly"')
    (tmp_path / "bad.usda").write_text(text)
    record = {r["element"]: r for r in gen.records(tmp_path / "bad.usda", all=True)}["/Looks/Frosted_Presence"]
    assert record["error"]["code"] == "invalid_value"
    assert record["error"]["where"] == "/Looks/Frosted_Presence/Surface.inputs:opacityMode"
