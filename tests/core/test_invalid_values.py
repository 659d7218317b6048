"""A NaN or infinite value in a document is bad input: an `invalid_value` error naming the input."""
import pytest

from .conftest import doc

BODY = ('<dielectric_bsdf name="coat" type="BSDF"><input name="weight" type="float" value="{weight}"/>'
        '<input name="tint" type="color3" value="{tint}"/></dielectric_bsdf>'
        '<surface name="surf" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="coat"/></surface>'
        '<surfacematerial name="mat" type="material"><input name="surfaceshader" type="surfaceshader" nodename="surf"/>'
        '</surfacematerial>')


@pytest.mark.parametrize("weight,tint,where", [("nan", "1, 1, 1", "coat/weight"), ("inf", "1, 1, 1", "coat/weight"),
                                               ("1", "1, -inf, 1", "coat/tint"), ("1", "NaN, 0, 0", "coat/tint")])
def test_non_finite_values_are_refused_naming_the_input(gen, weight, tint, where):
    records = list(gen.records(doc(BODY.format(weight=weight, tint=tint))))
    assert len(records) == 1 and "error" in records[0]
    error = records[0]["error"]
    assert error["code"] == "invalid_value"
    assert error["where"] == where


def test_finite_values_still_generate(gen):
    records = list(gen.records(doc(BODY.format(weight="1e30", tint="0, 0.5, 1"))))
    assert "stages" in records[0]
