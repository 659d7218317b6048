"""shadergen.archives on real zip files: packages usd-core and zipfile write pass; a compressed member,
overlapping members and every truncation and byte flip of a real package are refused as
invalid_document or pass, never another exception."""
from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

import io
import random
import struct
import zipfile

import pytest
from pxr import Sdf

from hostile_packages import LAYER, png, textured_layer, usdz
from shadergen.archives import check_usdz, copy_member, open_usdz
from shadergen.errors import ShaderGenError

TEXTURE = "textures/wood.png"


@pytest.fixture(scope="module")
def usd_core_package(tmp_path_factory) -> bytes:
    """A package as usd-core writes it (members stored, their data 64-byte aligned)."""
    folder = tmp_path_factory.mktemp("package")
    (folder / LAYER).write_text(textured_layer(TEXTURE))
    (folder / "textures").mkdir()
    (folder / TEXTURE).write_bytes(png(16, 16, (10, 200, 30)))
    writer = Sdf.ZipFileWriter.CreateNew(str(folder / "scene.usdz"))
    writer.AddFile(str(folder / LAYER), LAYER)
    writer.AddFile(str(folder / TEXTURE), TEXTURE)
    writer.Save()
    return (folder / "scene.usdz").read_bytes()


def refusal(data: bytes) -> ShaderGenError:
    with pytest.raises(ShaderGenError) as caught:
        check_usdz(data)
    assert caught.value.code == "invalid_document"
    return caught.value


def test_packages_written_by_usd_core_and_by_zipfile_pass(usd_core_package):
    check_usdz(usd_core_package)
    check_usdz(usdz([(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(4, 4, (1, 2, 3)))]))
    with open_usdz(io.BytesIO(usd_core_package), "scene.usdz") as archive:
        copy = io.BytesIO()
        copy_member(archive, TEXTURE, copy)
    assert copy.getvalue() == png(16, 16, (10, 200, 30))


def test_a_compressed_member_is_refused_at_that_member():
    error = refusal(usdz([(LAYER, textured_layer(TEXTURE).encode()), (TEXTURE, png(4, 4, (1, 2, 3)))],
                         compressed=(TEXTURE,)))
    assert error.where == TEXTURE and "compressed" in error.message


def test_overlapping_members_are_refused():
    """A second directory entry pointing at the first member's data: how a small zip claims a
    large total without compressing anything."""
    package = bytearray(usdz([("a.usda", b"#usda 1.0\n" * 100), ("b.usda", b"#usda 1.0\n" * 100)]))
    start = zipfile.ZipFile(io.BytesIO(bytes(package))).start_dir
    first_entry_length = 46 + len("a.usda")
    second = start + first_entry_length
    assert package[second:second + 4] == b"PK\x01\x02"
    struct.pack_into("<L", package, second + 42, 0)  # b.usda's entry at a.usda's offset
    error = refusal(bytes(package))
    assert error.where == "b.usda" and "overlaps" in error.message


def test_a_member_missing_from_a_checked_package_is_named():
    with open_usdz(io.BytesIO(usdz([(LAYER, b"#usda 1.0\n")])), "scene.usdz") as archive:
        with pytest.raises(ShaderGenError) as caught:
            copy_member(archive, "textures/none.png", io.BytesIO())
    assert caught.value.code == "invalid_document" and caught.value.where == "textures/none.png"


def test_truncations_and_byte_flips_are_refused_or_pass(usd_core_package):
    """2,000 corruptions of a real package (fixed seed): each one passes or is invalid_document, and
    a package that passes yields each member's stated bytes or invalid_document when copied."""
    rng = random.Random(21)
    outcomes = {"passed": 0, "refused": 0}
    for case in range(2000):
        data = bytearray(usd_core_package)
        if case % 4 == 0:
            data = data[:rng.randrange(len(data))]
        else:
            for _ in range(rng.randint(1, 4)):
                data[rng.randrange(len(data))] = rng.randrange(256)
        try:
            with open_usdz(io.BytesIO(bytes(data)), "scene.usdz") as archive:
                for info in archive.infolist():
                    out = io.BytesIO()
                    copy_member(archive, info.filename, out)
                    assert len(out.getvalue()) == info.file_size
            outcomes["passed"] += 1
        except ShaderGenError as exc:
            assert exc.code == "invalid_document", exc
            outcomes["refused"] += 1
    assert outcomes["refused"] > 1000 and outcomes["passed"] > 0, outcomes


def test_an_upload_whose_member_fails_its_checksum_is_refused(usd_core_package):
    with zipfile.ZipFile(io.BytesIO(usd_core_package)) as archive:
        info = archive.getinfo(LAYER)
        data_start = info.header_offset + 30 + len(LAYER) + struct.unpack_from(
            "<H", usd_core_package, info.header_offset + 28)[0]
    flipped = bytearray(usd_core_package)
    flipped[data_start + 3] ^= 0x20  # "#usda" -> "#usDa": a layer usd-core would read as it is
    error = refusal(bytes(flipped))
    assert error.where == LAYER and "CRC" in error.message
