"""The GLSL 4.00 and ESSL 3.00 targets: the printer of the IR (printer.py) and the stage
assembler (target.py). Floats are spelled here, for WGSL's printer too: one spelling of a value
in every target."""
import math
from functools import lru_cache


def _float(x: float) -> str:
    """A float as GLSL and WGSL read it back exactly: Python's shortest repr, with a `.0` where it
    has no point, NaN as 0 and the infinities as the largest 32-bit floats."""
    if x and x == x:  # (0.0 == -0.0 and NaN != NaN: those are spelled each time)
        return _spelled_once(x)
    return _spelled(x)


def _spelled(x: float) -> str:
    if math.isnan(x):
        return "0.0"
    if math.isinf(x):
        return "3.402823e38" if x > 0 else "-3.402823e38"
    text = repr(float(x))
    if "e" in text or "E" in text:
        mantissa, exp = text.lower().split("e")
        if "." not in mantissa:
            mantissa += ".0"
        return f"{mantissa}e{int(exp)}"
    return text


_spelled_once = lru_cache(maxsize=65536)(_spelled)  # requests print the same values again and again
