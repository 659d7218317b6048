"""Files inside usdz packages, named as USD names them: `scene.usdz[textures/wood.png]`.

A usdz is a zip archive (its members stored uncompressed); OpenImageIO reads files, so a member is
copied to a temporary file to be read."""
import os
import re
import tempfile
import zipfile
from contextlib import contextmanager

from .errors import RenderError

_MEMBER = re.compile(r"(.+?\.usdz)\[(.+)\]", re.IGNORECASE)
MAX_MEMBER_BYTES = 1 << 30  # a member's declared size is checked before any of it is read


def split_member(name: str) -> tuple[str, str | None]:
    """(package, member) of `package.usdz[member]`; (name, None) for a plain file name."""
    match = _MEMBER.fullmatch(name)
    return (match.group(1), match.group(2)) if match else (name, None)


def has_member(package: str, member: str) -> bool:
    try:
        with zipfile.ZipFile(package) as archive:
            return member in archive.namelist()
    except (OSError, zipfile.BadZipFile):
        return False


@contextmanager
def member_file(package: str, member: str):
    """A temporary file holding one member of a package, removed afterwards."""
    try:
        with zipfile.ZipFile(package) as archive:
            info = archive.getinfo(member)
            if info.file_size > MAX_MEMBER_BYTES:
                raise RenderError("invalid_image", f"{member} is larger than {MAX_MEMBER_BYTES} bytes", member)
            data = archive.read(info)
    except (OSError, KeyError, zipfile.BadZipFile) as exc:
        raise RenderError("invalid_image", f"cannot read {member} from {os.path.basename(package)}: {exc}",
                          member) from None
    with tempfile.NamedTemporaryFile(suffix=os.path.splitext(member)[1]) as f:
        f.write(data)
        f.flush()
        yield f.name
