"""MSL as the C-family printer writes it (targets/cfamily/printer.py): GLSL's matrix order, mix,
fract, `thread T&` out parameters, `S{...}` struct values, texture methods (`t.sample(s, uv)`)."""
from ..cfamily.syntax import MSL as SYNTAX  # noqa: F401 (the target's table)
