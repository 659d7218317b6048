"""Values folded at generation time (shadergen/evaluate.py, `specialized`) are what the GPU
computes from the same values as uniforms (`complete`): the Python evaluators follow the library's
GLSL, guards against division by zero included."""
import numpy as np
import pytest

from shadergen.api import Generator

GEN = Generator()

CASES = [  # (node, output type, inputs)
    ("burn", "float", {"fg": "0.4", "bg": "0.3", "mix": "0.7"}),
    ("burn", "float", {"fg": "0", "bg": "0.5", "mix": "0.5"}),
    ("burn", "color3", {"fg": "0.5, 0, 1", "bg": "0.5, 0.75, 0", "mix": "0.5"}),
    ("dodge", "float", {"fg": "1", "bg": "0.5", "mix": "0.5"}),
    ("dodge", "color4", {"fg": "0, 0.2, 1, 0", "bg": "0.5, 0.8, 0, 1", "mix": "0.5"}),
    ("overlay", "color3", {"fg": "0.3, 0.6, 0.9", "bg": "0.2, 0.5, 0.8", "mix": "0.8"}),
    ("premult", "color4", {"in": "1, 0.5, 0.25, 0.5"}),
    ("unpremult", "color4", {"in": "1, 0.5, 0.25, 0.5"}),
    ("unpremult", "color4", {"in": "1, 0.5, 0.25, 0"}),
    ("in", "color4", {"fg": "0.8, 0.6, 0.4, 0.5", "bg": "0.2, 0.3, 0.4, 0.75", "mix": "0.6"}),
    ("out", "color4", {"fg": "0.8, 0.6, 0.4, 0.5", "bg": "0.2, 0.3, 0.4, 0.75", "mix": "0.6"}),
    ("mask", "color4", {"fg": "0.8, 0.6, 0.4, 0.5", "bg": "0.2, 0.3, 0.4, 0.75", "mix": "0.6"}),
    ("matte", "color4", {"fg": "0.8, 0.6, 0.4, 0.5", "bg": "0.2, 0.3, 0.4, 0.75", "mix": "0.6"}),
    ("over", "color4", {"fg": "0.8, 0.6, 0.4, 0.5", "bg": "0.2, 0.3, 0.4, 0.75", "mix": "0.6"}),
    ("disjointover", "color4", {"fg": "0.8, 0.6, 0.4, 0.5", "bg": "0.2, 0.3, 0.4, 0.75", "mix": "0.6"}),
    ("disjointover", "color4", {"fg": "0.8, 0.6, 0.4, 1.5", "bg": "0.2, 0.3, 0.4, 0", "mix": "1"}),
]


def document(category: str, type_name: str, inputs: dict) -> str:
    values = "".join(f'<input name="{n}" type="{"float" if n == "mix" else type_name}" value="{v}"/>'
                     for n, v in inputs.items())
    return (f'<?xml version="1.0"?><materialx version="1.39"><nodegraph name="g">'
            f'<{category} name="n" type="{type_name}">{values}</{category}>'
            f'<output name="out" type="{type_name}" nodename="n"/></nodegraph></materialx>')


@pytest.mark.parametrize("category,type_name,inputs", CASES, ids=[f"{c[0]}-{c[2].get('fg', c[2].get('in'))}" for c in CASES])
def test_a_folded_value_is_what_the_gpu_computes(renderer, category, type_name, inputs):
    text = document(category, type_name, inputs)
    folded = GEN.prepare(text, interface="specialized").emit()
    assert folded["passes"]["fold"] == 1 and not folded["blocks"]["pixel"]["PublicUniforms"]
    live = GEN.prepare(text, interface="complete").emit()
    assert live["blocks"]["pixel"]["PublicUniforms"]  # computed by the shader from uniforms
    images = [renderer.render(record, size=8).rgba[4, 4] for record in (folded, live)]
    np.testing.assert_allclose(images[0], images[1], atol=2e-6)
