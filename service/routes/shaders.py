"""GET /v1/shaders/{hash}: a record from the cache, by the graph hash a generate call returned."""
import json
from typing import Annotated

from fastapi import APIRouter, Path, Query, Response

from ..deps import GenerationDep
from ..errors import ServiceError
from ..models import ShaderRecord
from .common import ERRORS, json_bytes

router = APIRouter(prefix="/v1/shaders", tags=["shaders"])

GraphHash = Annotated[str, Path(pattern="^[0-9a-f]{8,128}$", description="the record's `hash`")]
Target = Annotated[str | None, Query(max_length=64, description="refuse a record of another target")]


@router.get("/{graph_hash}", response_model=ShaderRecord, responses=ERRORS, summary="A cached record")
async def get_shader(generation: GenerationDep, graph_hash: GraphHash, target: Target = None) -> Response:
    record = await generation.record(graph_hash)
    # the hash covers the target, so `target` can only confirm it: a mismatch is no such record
    if record is None or (target is not None and json.loads(record)["target"] != target):
        raise ServiceError("not_found", f"no cached shader {graph_hash}" + (f" for {target}" if target else ""))
    return json_bytes(record)
