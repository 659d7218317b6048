"""The HLSL checker: the Slang compiler's front end reads HLSL (slang/check.py): each shader is a
module loaded from its source, its entry points marked `[shader("vertex")]` / `[shader("pixel")]`
as DXC reads them too; parsed and type-checked, a bad one refused with a location."""
from ..slang.check import errors  # noqa: F401 (the same compiler)
