"""HLSL (shader model 5 and later): the shared C-family printer and assembler (targets/cfamily)
with HLSL's syntax table; checked by the Slang compiler's HLSL front end (check.py)."""
