"""Values as records and documents carry them (JSON numbers, booleans, arrays, or MaterialX value
strings such as "0.2, 0.4, 0.6" and "true") as the flat lists of numbers GL uniforms take."""

NON_NUMERIC_TYPES = {"string", "filename", "surfaceshader", "displacementshader", "volumeshader",
                     "lightshader", "material", "BSDF", "EDF", "VDF", "closure"}


def numbers(mx_type: str, value) -> list[float] | None:
    """The flat numbers of a value, or None when it has none (null, strings of non-numeric
    types, closures). Matrices stay in MaterialX's row order, which is also the order of GLSL's
    column-major storage for the generated code's convention (v * M)."""
    if value is None or mx_type in NON_NUMERIC_TYPES:
        return None
    if isinstance(value, bool):
        return [1.0 if value else 0.0]
    if isinstance(value, (int, float)):
        return [float(value)]
    if isinstance(value, str):
        text = value.strip().lower()
        if text in ("true", "false"):
            return [1.0 if text == "true" else 0.0]
        try:
            return [float(x) for x in text.replace(",", " ").split()] or None
        except ValueError:
            return None
    if isinstance(value, (list, tuple)):
        flat: list[float] = []
        for item in value:
            part = numbers(mx_type, item)
            if part is None:
                return None
            flat += part
        return flat or None
    return None
