"""What the C-family targets (HLSL, Slang, MSL) share: one printer of the IR (printer.py) and one
stage assembler (target.py), each language a table of its spellings (syntax.py); the folders
targets/hlsl, targets/slang and targets/msl hold the tables, the targets and their checkers."""
