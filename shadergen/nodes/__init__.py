"""Node implementations: the three data-driven kinds and the registry of dynamic ones (seed 2.3).

`implementation_for` turns an <implementation> (or nodegraph) element into the object that
writes its code. Dynamic implementations are Python classes registered by implementation name;
their modules are imported here so that registering them is part of importing the package.
"""
import re

from ..element import Element
from ..errors import ShaderGenError
from .base import REGISTRY, InlineImpl, NodeImpl, SourceFunctionImpl
from . import application, convolution, geometric, material, surface, transform  # noqa: F401  (registration)

__all__ = ["NodeImpl", "implementation_for", "REGISTRY"]
TARGET_SUFFIX = re.compile(r"_gen\w+$")


def implementation_for(elem: Element) -> NodeImpl:
    if elem.get("sourcecode") is not None:
        return InlineImpl(elem.get("sourcecode"))
    file = elem.get("file")
    if file:
        if file.endswith(".inline"):
            return InlineImpl.from_file(elem)
        return SourceFunctionImpl(elem)
    # dynamic classes are registered target-neutrally: IM_position_vector3 serves IM_position_vector3_genglsl
    cls = REGISTRY.get(elem.name) or REGISTRY.get(TARGET_SUFFIX.sub("", elem.name))
    if cls is None:
        raise ShaderGenError("unknown_implementation",
                             f"implementation '{elem.name}' has no source and no registered class", elem.name)
    impl = cls()
    impl.element = elem  # where its library files are (dynamic implementations may include some)
    return impl
