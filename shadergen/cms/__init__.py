"""Colour management systems (seed 3.4): what turns a value or texture given in one colour space
into the document's working space.

A system answers `transform(builder, name, source, working, type, where)` with a transform node
for the graph (or None where nothing is to be done); `identity` is what it adds to the cache key
(hashing.py). Two systems: `builtin` (cms/builtin.py: the library's `*_to_lin_rec709` nodes, the
default) and `ocio` (cms/ocio.py: any colour space of an OpenColorIO config, its code from OCIO's
GPU shader generator). `system_for` makes one from the caller's options.
"""
import os

from ..errors import ShaderGenError
from .builtin import BuiltinCMS

__all__ = ["CMS_NAMES", "BuiltinCMS", "system_for", "display_encoder", "OCIO_CONFIG_ENV"]

CMS_NAMES = ("builtin", "ocio")
OCIO_CONFIG_ENV = "SHADERGEN_OCIO_CONFIG"
DEFAULT_OCIO_CONFIG = "ocio://default"  # OCIO's built-in CG config: no file needed
BUILTIN = BuiltinCMS()


def system_for(cms: str | None = None, ocio_config: str | None = None):
    """The system a request names: `cms` builtin | ocio (None: ocio when a config is named, by
    `ocio_config` or $SHADERGEN_OCIO_CONFIG, else builtin). A config is a path or `ocio://NAME`."""
    if cms is None:
        cms = "ocio" if ocio_config else "builtin"
    if cms not in CMS_NAMES:
        raise ShaderGenError("unsupported_cms", f"unknown colour management system '{cms}'; supported: "
                             + ", ".join(CMS_NAMES), "cms")
    if cms == "builtin":
        if ocio_config:
            raise ShaderGenError("invalid_option", "an OCIO config is given but the colour management system is "
                                 "builtin", "ocio_config")
        return BUILTIN
    from .ocio import OcioCMS  # OpenColorIO is imported only by those who ask for it
    return OcioCMS.for_config(ocio_config or os.environ.get(OCIO_CONFIG_ENV) or DEFAULT_OCIO_CONFIG)


def display_encoder(display: dict | None):
    """The PNG encoding a render request asks for (service thumbnails): `display` is None (sRGB of
    linear Rec.709, the built-in system's) or `{"ocio_config", "working", "view"}`, the working
    space of an OCIO record shown through the config's default display and `view` (None: that
    display's default view), as `shadergen render --cms ocio` writes its PNG."""
    if display is None:
        return None
    return system_for("ocio", display.get("ocio_config")).display_encoder(display.get("working"),
                                                                          view=display.get("view"))
