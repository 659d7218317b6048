"""The HLSL target: the C-family assembler (targets/cfamily/target.py) with HLSL's syntax."""
from ..cfamily.target import CFamilyTarget
from .printer import SYNTAX


class HlslTarget(CFamilyTarget):
    name = "hlsl"
    syntax = SYNTAX
