"""What an upload composes to is counted from its specs before usd-core composes it
(shadergen/usd_budget.py): the count is usd-core's own where the scene has no variants, an upper
bound where it has, and an upload of exponentially many prims is refused before it composes."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import time

import pytest

from hostile_packages import nested_references
from shadergen.errors import ShaderGenError
from shadergen.usd_budget import MAX_COMPOSED_PRIMS, ComposedSize, check_composed_size

SHAPES = {
    "nested references": nested_references(8),
    "inherits and specializes": """#usda 1.0
class "Base"
{
    def "a"
    {
    }
    def "b"
    {
    }
}
def "X" (
    inherits = </Base>
)
{
    def "own"
    {
    }
}
def "Y" (
    specializes = </X>
)
{
}
""",
    "an internal reference to the default prim, a payload, a cycle": """#usda 1.0
(
    defaultPrim = "Root"
)
def "Root"
{
    def "kid"
    {
    }
}
def "R" (
    references = <>
)
{
}
def "P" (
    payload = </Root/kid>
)
{
}
def "C1" (
    references = </C2>
)
{
    def "x"
    {
    }
}
def "C2" (
    references = </C1>
)
{
    def "y"
    {
    }
}
""",
    "a cycle under prims referenced many times": nested_references(5) + """def "X" (
    references = </A>
)
{
}
def "A" (
    references = </L5>
)
{
    def "back" (
        references = </X>
    )
    {
    }
}
""" + "".join(f"""def "M{m}"
{{
    def "one" (
        references = </{'M' + str(m - 1) if m else 'X'}>
    )
    {{
    }}
    def "two" (
        references = </{'M' + str(m - 1) if m else 'X'}>
    )
    {{
    }}
}}
""" for m in range(6)),
}


def composed(text: str) -> tuple[int, int]:
    """(prims counted from the specs, prims of usd-core's stage), pseudo-root and classes included."""
    from pxr import Sdf, Usd

    layer = Sdf.Layer.CreateAnonymous(".usda")
    layer.ImportFromString(text)
    counted = ComposedSize([layer], MAX_COMPOSED_PRIMS).of_stack(layer)
    stage = Usd.Stage.Open(layer)
    prims = list(stage.TraverseAll()) + [p for p in stage.GetPseudoRoot().GetAllChildren() if p.IsAbstract()]
    return counted, len({p.GetPath() for p in prims})


@pytest.mark.parametrize("shape", SHAPES)
def test_the_count_is_usd_cores_own(shape):
    counted, stage = composed(SHAPES[shape])
    assert counted >= stage, (counted, stage)
    if "cycle" not in shape:  # a cycle is a composition error: usd-core cuts it where it closes, which
        # depends on where the walk entered it; a count kept from one entry may be larger than another's
        assert counted == stage, (counted, stage)


def test_variants_count_as_their_largest():
    text = """#usda 1.0
def "V" (
    variants = {
        string size = "small"
    }
    prepend variantSets = "size"
)
{
    variantSet "size" = {
        "small" {
            def "one"
            {
            }
        }
        "large" {
            def "one"
            {
            }
            def "two"
            {
            }
            def "three"
            {
            }
        }
    }
}
"""
    counted, stage = composed(text)
    assert (counted, stage) == (4, 2)  # V and the large variant's three; the stage selected small


def test_an_upload_of_exponentially_many_prims_is_refused_before_it_composes():
    from pxr import Sdf

    layer = Sdf.Layer.CreateAnonymous(".usda")
    layer.ImportFromString(nested_references(40))  # 2 ** 40 prims: usd-core would never finish
    started = time.monotonic()
    with pytest.raises(ShaderGenError) as refused:
        check_composed_size(layer, [layer])
    assert refused.value.code == "too_large" and str(MAX_COMPOSED_PRIMS) in refused.value.message
    assert time.monotonic() - started < 5  # a bound on a hang, not a speed: the walk is linear in the specs
    layer.ImportFromString(nested_references(11))  # 12,280 prims: within the budget
    check_composed_size(layer, [layer])


def test_the_errors_of_a_cycle_composed_many_times_are_listed_a_few_times():
    """A cycle under a prim referenced 64 times: usd-core reports it for every copy (128 errors,
    79 kB of warnings from a 2 kB layer); the record lists the first ten and how many more."""
    from shadergen.api import Generator
    from shadergen.usd import MAX_COMPOSITION_WARNINGS, parse_usd

    doc = parse_usd(SHAPES["a cycle under prims referenced many times"].encode(), "usda", Generator().library)
    composition = [w for w in doc.warnings if w.startswith("USD composition:")]
    assert len(composition) == MAX_COMPOSITION_WARNINGS + 1
    assert composition[-1] == f"USD composition: {128 - MAX_COMPOSITION_WARNINGS} more errors not listed"
    assert all("Cycle detected" in w for w in composition[:-1])

