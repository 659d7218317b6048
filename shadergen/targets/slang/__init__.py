"""Slang: the shared C-family printer and assembler (targets/cfamily) with Slang's syntax table;
checked by the Slang compiler PyPI's slangpy ships (check.py)."""
