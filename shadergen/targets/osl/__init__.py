"""The OSL target (OSL 1.13): the printer of the IR (printer.py), the shader assembler
(target.py), the closure convention (closures.py) and the checker that compiles with oslc
(check.py)."""
