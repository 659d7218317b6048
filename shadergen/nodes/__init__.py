"""Node implementations: the three data-driven kinds and the registry of dynamic ones (seed 2.3).

`implementation_for` turns an <implementation> (or nodegraph) element into the object that
writes its code. Dynamic implementations are Python classes registered by implementation name;
their modules are imported here so that registering them is part of importing the package.
"""
from .base import REGISTRY, NodeImpl, implementation_for
from . import application, colortransform, convolution, geometric, material, modifier, surface, transform  # noqa: F401  (registration)

__all__ = ["NodeImpl", "implementation_for", "REGISTRY"]
