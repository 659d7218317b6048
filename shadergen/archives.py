"""usdz packages read within the bounds of their own bytes.

The USDZ specification stores every member uncompressed (zip method 0, its data 64-byte aligned)
so that readers can map members in place, and usd-core refuses to open a compressed member
("compressed files are not supported"). A package holding a compressed member is therefore not a
valid usdz and is refused outright (invalid_document) instead of being inflated carefully: no
reader of ours decompresses anything, so a deflate bomb has nothing to expand into, and every
member's data is a slice of the package. The members together hold at most the package's own
size (for an upload, the request-body limit) and no member expands (its ratio is 1).

A zip's directory can lie, so before any member is read it is checked against the bytes. usd-core
walks the members' local headers from the start of the file; zipfile (the renderer's reader) goes
by the central directory. The package must read the same both ways: the members lie back to back
from the first byte to the directory, each local header agreeing with its directory entry on
method, sizes, checksum and name, and no two members share a name (zipfile finds the last of
them, usd-core the first). So no two members overlap (how a small zip claims a large total), no
member hides between others, and none runs past the package. Reading a member then
yields at most its checked size: zipfile stops at the directory's size and compares the CRC at the
end, so a directory that understates a member gives a checksum error, never more bytes. An upload
is read through once to compare every member with its checksum, which usd-core does not.

Alignment is not required: usd-core opens unaligned packages (what `zip -0` writes), and it only
makes mapping faster; it bounds nothing.
"""
import io
import os
import shutil
import struct
import zipfile
from contextlib import contextmanager

from .errors import ShaderGenError

# a local file header: signature, version, flags, method, time, date, crc, compressed size, size,
# name length, extra length
_LOCAL_HEADER = struct.Struct("<4sHHHHHLLLHH")
_LOCAL_SIGNATURE = b"PK\x03\x04"
_ZIP64_SIZE = 0xFFFFFFFF  # a local header's sizes when the real ones are in its zip64 extra field
_ENCRYPTED, _UTF8_NAME = 0x1, 0x800  # general purpose flags
# what zipfile and the checks raise on a malformed archive (UnicodeDecodeError is a ValueError;
# NotImplementedError for a directory entry that asks for a zip version zipfile does not know)
_MALFORMED = (zipfile.BadZipFile, zipfile.LargeZipFile, ValueError, EOFError, struct.error, NotImplementedError)


def _invalid(error: type[ShaderGenError], message: str, where: str) -> ShaderGenError:
    return error("invalid_document", f"not a valid usdz package: {message}", where)


def check_usdz(data: bytes, where: str = "<document>") -> None:
    """Refuse (invalid_document, at the member concerned) an uploaded package that is not a valid
    usdz: not a zip, a compressed or encrypted member, a directory that disagrees with the data,
    or a member whose bytes fail its checksum (usd-core reads members without checking it)."""
    with open_usdz(io.BytesIO(data), where) as archive, open(os.devnull, "wb") as sink:
        for info in archive.infolist():
            copy_member(archive, info.filename, sink)


@contextmanager
def open_usdz(file, where: str, error: type[ShaderGenError] = ShaderGenError):
    """The checked zipfile.ZipFile of a package (a path or a binary file object); `where` names
    the package in errors that concern it whole, raised as `error` (the caller's error type)."""
    try:
        archive = zipfile.ZipFile(file)
    except OSError as exc:
        raise error("invalid_document", f"cannot read the package: {exc.strerror or exc}", where) from None
    except _MALFORMED as exc:
        raise _invalid(error, str(exc), where) from None
    with archive:
        try:
            _check_members(archive, error)
        except (OSError, *_MALFORMED) as exc:
            raise _invalid(error, str(exc), where) from None
        yield archive


def _check_members(archive: zipfile.ZipFile, error: type[ShaderGenError]) -> None:
    file = archive.fp
    data_end, previous, names = 0, None, set()
    for info in sorted(archive.infolist(), key=lambda i: i.header_offset):
        name = info.filename
        # zipfile cuts a name at a NUL byte and finds the last of two members of one name; usd-core
        # keeps the whole name (and its file format registry raises on the NUL) and finds the first
        if "\x00" in info.orig_filename:
            raise _invalid(error, f"the name of the member {name}... holds a NUL byte", name)
        if name in names:
            raise _invalid(error, f"{name} is stored twice (readers differ on which one they read)", name)
        names.add(name)
        if info.compress_type != zipfile.ZIP_STORED:
            raise _invalid(error, f"{name} is compressed (zip method {info.compress_type}); a usdz stores its members "
                           "uncompressed", name)
        if info.flag_bits & _ENCRYPTED:
            raise _invalid(error, f"{name} is encrypted", name)
        if info.file_size != info.compress_size:
            raise _invalid(error, f"{name} is stored in {info.compress_size} bytes but declares {info.file_size}",
                           name)
        if info.header_offset < data_end:
            raise _invalid(error, f"{name} overlaps the member before it", name)
        if info.header_offset > data_end:
            raise _unlisted(error, info.header_offset - data_end, previous, name)
        file.seek(info.header_offset)
        header = file.read(_LOCAL_HEADER.size)
        if len(header) < _LOCAL_HEADER.size:
            raise _invalid(error, f"{name}'s header lies past the end of the package", name)
        signature, _, _, method, _, _, crc, *sizes, name_length, extra_length = _LOCAL_HEADER.unpack(header)
        raw_name = info.orig_filename.encode("utf-8" if info.flag_bits & _UTF8_NAME else "cp437")
        if (signature != _LOCAL_SIGNATURE or method != info.compress_type or crc != info.CRC
                or sizes not in ([info.compress_size, info.file_size], [_ZIP64_SIZE, _ZIP64_SIZE])
                or file.read(name_length) != raw_name):
            raise _invalid(error, f"the directory and {name}'s own header disagree (name, method, checksum "
                           "or size)", name)
        data_end = info.header_offset + _LOCAL_HEADER.size + name_length + extra_length + info.compress_size
        if data_end > archive.start_dir:
            raise _invalid(error, f"{name} declares {info.file_size} bytes, more than the package holds before its "
                           f"directory ({archive.start_dir} bytes)", name)
        previous = name
    if data_end < archive.start_dir:
        raise _unlisted(error, archive.start_dir - data_end, previous, "the directory")


def _unlisted(error: type[ShaderGenError], count: int, before: str | None, after: str) -> ShaderGenError:
    """Bytes between two members (or the last member and the directory) that the directory does
    not list: a member usd-core would find and zipfile would not, or one whose size is understated."""
    if before is None:
        return _invalid(error, f"{count} bytes the directory does not list precede {after}", after)
    return _invalid(error, f"{before} is followed by {count} bytes the directory does not list", before)


def copy_member(archive: zipfile.ZipFile, member: str, out, error: type[ShaderGenError] = ShaderGenError) -> None:
    """Copy a member of a checked package to the binary file `out`: at most its checked size,
    refused (invalid_document) when its bytes do not match the directory's checksum."""
    try:
        with archive.open(member) as source:
            shutil.copyfileobj(source, out, 1 << 20)
    except KeyError:
        raise error("invalid_document", "the package has no such file", member) from None
    except _MALFORMED as exc:
        raise _invalid(error, str(exc), member) from None
