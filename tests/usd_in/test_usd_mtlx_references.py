"""References and payloads from USD to MaterialX documents, composed as usdMtlx composes them
(the usd-core wheel lacks that plugin): the referencing prim becomes the document's material, read
with our MaterialX reader, beside a file on the command line and inside an uploaded package."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import subprocess
import sys

import pytest

from shadergen.api import Generator

from .scenes import STANDARD_SURFACE_MTLX, TEXTURE, write_checker, write_mtlx

SCENE = """#usda 1.0
def Xform "World"
{
    def Scope "Looks"
    {
%s
    }
}
"""


def uniform_values(record: dict) -> dict:
    """Public uniforms by the element path they come from (their names carry the material's name)."""
    return {v["path"]: v["value"] for v in record["blocks"]["pixel"]["PublicUniforms"]
            if not (v["path"] or "").startswith("ND_surfacematerial/")}


@pytest.fixture
def folder(tmp_path):
    write_checker(tmp_path)
    write_mtlx(tmp_path, "brick.mtlx", STANDARD_SURFACE_MTLX)
    return tmp_path


def scene(folder, prims: str):
    path = folder / "scene.usda"
    path.write_text(SCENE % prims)
    return path


def test_reference_to_a_material_of_a_document_beside_the_file(gen: Generator, folder):
    path = scene(folder, '        def Material "Brick" '
                         '( prepend references = @./brick.mtlx@</MaterialX/Materials/Brick> ) { }')
    [record] = gen.records(path, all=True)
    assert "error" not in record, record
    assert record["element"] == "/World/Looks/Brick"
    [direct] = gen.records(folder / "brick.mtlx", all=True)
    assert uniform_values(record) == uniform_values(direct) and uniform_values(record)["image/file"] == TEXTURE


def test_payload_to_the_default_prim_brings_every_material_below_the_prim(gen: Generator, folder):
    path = scene(folder, '        def "Library" ( prepend payload = @brick.mtlx@ ) { }\n'
                         '        def "Named" ( prepend references = @brick.mtlx@</MaterialX/Materials> ) { }')
    records = list(gen.records(path, all=True))
    assert [r["element"] for r in records] == ["/World/Looks/Library/Materials/Brick", "/World/Looks/Named/Brick"]
    assert all("error" not in r for r in records), records


def test_reference_naming_no_material_is_an_error_at_the_prim(gen: Generator, folder):
    path = scene(folder, '        def Material "Brick" ( references = @./brick.mtlx@</MaterialX/Materials/Wood> ) { }')
    [record] = gen.records(path, all=True)
    assert record["error"]["code"] == "invalid_document" and record["error"]["where"] == "/World/Looks/Brick"
    assert "Wood" in record["error"]["message"]


def test_cli_generate_reads_the_document_beside_the_layer(folder):
    path = scene(folder, '        def Material "Brick" ( references = @./brick.mtlx@</MaterialX/Materials/Brick> ) { }')
    done = subprocess.run([sys.executable, "-m", "shadergen.cli", "generate", str(path), "--all"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert '"/World/Looks/Brick"' in done.stdout


def test_upload_package_holding_layer_and_document(gen: Generator, folder):
    from pxr import Sdf

    path = scene(folder, '        def Material "Brick" ( references = @./brick.mtlx@</MaterialX/Materials/Brick> ) { }')
    writer = Sdf.ZipFileWriter.CreateNew(str(folder / "brick.usdz"))
    for name in (path.name, "brick.mtlx", TEXTURE):
        writer.AddFile(str(folder / name), name)
    writer.Save()
    [record] = gen.records((folder / "brick.usdz").read_bytes(), document_format="usdz", all=True)
    assert "error" not in record, record
    assert record["element"] == "/World/Looks/Brick" and uniform_values(record)["image/file"] == TEXTURE


def test_document_in_a_folder_reads_its_textures_from_that_folder(gen: Generator, folder):
    (folder / "materials").mkdir()
    (folder / "materials" / "brick.mtlx").write_text(STANDARD_SURFACE_MTLX)
    (folder / TEXTURE).rename(folder / "materials" / TEXTURE)
    path = scene(folder, '        def Material "Brick" '
                         '( references = @materials/brick.mtlx@</MaterialX/Materials/Brick> ) { }')
    [record] = gen.records(path, all=True)
    assert "error" not in record, record
    assert uniform_values(record)["image/file"] == f"materials/{TEXTURE}"


LOOKS_IN_A_VARIANT_SET = '''        def Material "Look" (
            variants = { string look = "brick" }
            prepend variantSets = "look"
        )
        {
            variantSet "look" = {
                "brick" ( prepend references = @./brick.mtlx@</MaterialX/Materials/Brick> ) { }
                "plain" { }
            }
        }
        def Material "Plain" (
            variants = { string finish = "matte" }
            prepend variantSets = "finish"
        )
        {
            variantSet "finish" = {
                "matte" { }
            }
            token outputs:surface.connect = </World/Looks/Plain/Surface.outputs:surface>
            def Shader "Surface"
            {
                uniform token info:id = "UsdPreviewSurface"
                float inputs:roughness = 0.4
                token outputs:surface
            }
        }'''


def test_variant_sets_are_walked_by_their_variants(gen: Generator, folder):
    """A variant set's own path (`/Look{look=}`) holds no prim spec: the walk for MaterialX arcs
    reads its variants (`/Look{look=brick}`), on the command line and in an upload (the set's
    path was taken for a prim and raised AttributeError: a traceback, a 500 over HTTP)."""
    path = scene(folder, LOOKS_IN_A_VARIANT_SET)
    records = {r["element"]: r for r in gen.records(path, all=True)}
    assert set(records) == {"/World/Looks/Look", "/World/Looks/Plain"}
    assert all("error" not in r for r in records.values()), records
    [direct] = gen.records(folder / "brick.mtlx", all=True)
    assert uniform_values(records["/World/Looks/Look"]) == uniform_values(direct)
    uploaded = SCENE % ('        def Material "Plain"' + LOOKS_IN_A_VARIANT_SET.split('        def Material "Plain"')[1])
    [record] = gen.records(uploaded.encode(), all=True, document_format="usda")
    assert "error" not in record and record["element"] == "/World/Looks/Plain", record
