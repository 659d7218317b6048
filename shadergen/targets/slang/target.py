"""The Slang target: the C-family assembler (targets/cfamily/target.py) with Slang's syntax."""
from ..cfamily.target import CFamilyTarget
from .printer import SYNTAX


class SlangTarget(CFamilyTarget):
    name = "slang"
    syntax = SYNTAX
