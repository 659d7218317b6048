"""A shader record of the JSON contract (../shared/DESIGN.md), checked before anything touches GL:
whoever produced it (our generator, the reference oracle, a hand-written test), a record must
name a target the renderer draws and carry both stage sources; uniform listings are optional (GLSL initialisers
then supply the values)."""
from collections.abc import Iterator

from ..digest import sha256
from .errors import RenderError

RENDERABLE_TARGETS = ("glsl", "essl")  # ESSL 3.00 compiles on desktop GL 4.3+ (ARB_ES3_compatibility)
UNIFORM_BLOCKS = ("PublicUniforms", "PrivateUniforms")


def check_record(record, targets: tuple[str, ...] = RENDERABLE_TARGETS) -> tuple[str, str]:
    """(vertex source, pixel source) of a record of one of `targets`, or RenderError saying what is wrong."""
    if not isinstance(record, dict):
        raise RenderError("invalid_record", f"a shader record is a JSON object, not {type(record).__name__}")
    where = record.get("element")
    if "error" in record:
        error = record["error"] if isinstance(record["error"], dict) else {"message": record["error"]}
        raise RenderError("invalid_record", "the record is an error record, nothing to render: "
                          f"{error.get('code', 'error')}: {error.get('message', '')}", where)
    target = record.get("target", "glsl")
    if target not in targets:
        hint = {"wgsl": " (wgsl records are drawn by the wgpu backend)",
                "vulkan": " (vulkan records are drawn by the vulkan backend)"}.get(target, "")
        raise RenderError("unsupported_target", f"this renderer draws {' or '.join(targets)}, not {target!r}{hint}",
                          where)
    stages = record.get("stages")
    if not isinstance(stages, dict):
        raise RenderError("invalid_record", "the record has no 'stages' object", where)
    sources = []
    for stage in ("vertex", "pixel"):
        source = stages.get(stage)
        if not isinstance(source, str) or not source.strip():
            raise RenderError("invalid_record", f"the record has no {stage} stage source "
                              "(generated with source omitted?)", where)
        sources.append(source)
    blocks = record.get("blocks", {})
    if not isinstance(blocks, dict) or not all(isinstance(b, dict) and all(isinstance(v, list) for v in b.values())
                                               for b in blocks.values()):
        raise RenderError("invalid_record", "'blocks' must map stage -> block name -> list of variables", where)
    return sources[0], sources[1]


def source_digest(vertex: str, pixel: str) -> str:
    """The key of a compiled program: exactly what the program depends on, its source, so records
    of different interface modes or generators never share a program by accident."""
    return sha256(vertex.encode() + b"\0" + pixel.encode()).hexdigest()


def uniform_variables(record: dict) -> Iterator[dict]:
    """Every uniform variable the record lists (both stages, public then private), well-formed ones only."""
    for stage in record.get("blocks", {}).values():
        for block in UNIFORM_BLOCKS:
            for variable in stage.get(block, []):
                if isinstance(variable, dict) and isinstance(variable.get("name"), str):
                    yield variable
