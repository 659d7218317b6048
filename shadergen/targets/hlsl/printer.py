"""HLSL as the C-family printer writes it (targets/cfamily/printer.py): this table says how."""
from ..cfamily.syntax import HLSL as SYNTAX  # noqa: F401 (the target's table)
