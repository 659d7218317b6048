"""Every public uniform of a structural-named listing says what it binds to (issue 23): the source's
names (`u_n18_uv_offset`) no longer do, so a client binding by the listing needs each uniform's
element path, and the path must name something of the document. Checked over the corpus's
TestSuite and Examples, complete and reduced.

A path resolves to one of
- an element of the document (its includes read in): `graph/node/input`, `graph/input`;
- a node of the document and an input the document leaves unauthored, of its nodedef or one its
  implementation adds (image's uv_offset): `graph/node/input`;
- a nodedef's input, for the unauthored inputs of the element drawn: `ND_surfacematerial/backsurfaceshader`;
- a geompropdef, for a default geometric property the graph adds: `UV0`."""
import os
from pathlib import Path

import pytest

from shadergen.api import DocumentFile, Generator
from shadergen.errors import ShaderGenError
from shadergen.library import Scope

from tests.required_tools import missing

CORPUS = Path(os.environ.get("SHADERGEN_CORPUS", Path(__file__).resolve().parents[2] / ".." / "shared" / "corpus"))
MATERIALS = CORPUS / "resources" / "Materials"


def corpus_documents() -> list[Path]:
    return sorted(p for folder in ("TestSuite", "Examples") for p in (MATERIALS / folder).rglob("*.mtlx"))


def element_at(root, path: str):
    element = root
    for name in path.split("/"):
        element = element.child(name)
        if element is None:
            return None
    return element


def node_inputs(scope: Scope, node) -> set[str]:
    """The input names any nodedef of the node's category declares, inherited ones included, and
    those its implementations add (image's uv_offset)."""
    nodedefs = [d for nodedef in scope.nodedefs_for(node.category) for d in scope.inheritance(nodedef)]
    implementations = [i for d in nodedefs for layer in scope.layers for i in layer.implementations.get(d.name, ())]
    return {i.name for e in nodedefs + implementations for i in e.children_of("input")}


def resolves(path: str, root, scope: Scope) -> bool:
    if element_at(root, path) is not None or scope.geompropdef(path) is not None:
        return True
    head, _, name = path.rpartition("/")
    node = element_at(root, head) if head else None
    if node is not None and node.category not in ("input", "output", "nodegraph"):
        return name in node_inputs(scope, node)
    nodedef = scope.nodedef(head) if head else None
    return nodedef is not None and nodedef.child(name) is not None


def test_every_public_uniform_of_the_corpus_names_what_it_binds_to(gen: Generator):
    documents = corpus_documents()
    if not documents:
        missing(f"the MaterialX corpus at {MATERIALS}", "set SHADERGEN_CORPUS to the shared corpus")
    unbound, listed = [], 0
    for path in documents:
        try:
            doc = gen.load(DocumentFile(str(path)))
        except ShaderGenError:
            continue  # a document that names a file the corpus lacks has no listing to check
        scope = Scope(gen.library, doc.root)
        for interface in ("complete", "reduced"):
            for record in gen.records(doc, all=True, interface=interface):
                for variable in record.get("blocks", {}).get("pixel", {}).get("PublicUniforms", []):
                    listed += 1
                    if not variable.get("path") or not resolves(variable["path"], doc.root, scope):
                        unbound.append((path.name, record["element"], interface, variable["name"], variable.get("path")))
    assert not unbound, unbound[:20]
    assert listed > 5000  # the corpus was read and its listings made (9191 uniforms when written)
