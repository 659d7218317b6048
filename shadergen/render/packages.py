"""Files inside usdz packages, named as USD names them: `scene.usdz[textures/wood.png]`.

A package is checked whole each time it is opened (shadergen.archives: stored members only, a
directory that agrees with the data), so a member never expands and never yields more than the
package holds; one that is not a valid usdz refuses the render. OpenImageIO reads files, so a
member is copied to a temporary file to be read."""
import os
import re
import tempfile
from contextlib import contextmanager

from shadergen.archives import copy_member, open_usdz

from .errors import RenderError

_MEMBER = re.compile(r"(.+?\.usdz)\[(.+)\]", re.IGNORECASE)


def split_member(name: str) -> tuple[str, str | None]:
    """(package, member) of `package.usdz[member]`; (name, None) for a plain file name."""
    match = _MEMBER.fullmatch(name)
    return (match.group(1), match.group(2)) if match else (name, None)


def has_member(package: str, member: str) -> bool:
    with open_usdz(package, os.path.basename(package), RenderError) as archive:
        return member in archive.NameToInfo


@contextmanager
def member_file(package: str, member: str):
    """A temporary file holding one member of a package, removed afterwards."""
    with tempfile.NamedTemporaryFile(suffix=os.path.splitext(member)[1]) as f:
        with open_usdz(package, os.path.basename(package), RenderError) as archive:
            copy_member(archive, member, f, RenderError)
        f.flush()
        yield f.name
