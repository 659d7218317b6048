"""Slang as the C-family printer writes it (targets/cfamily/printer.py): HLSL's syntax, with
Slang's struct constructors, vector constructors from a scalar and select()."""
from ..cfamily.syntax import SLANG as SYNTAX  # noqa: F401 (the target's table)
