"""GET /v1/nodedefs: the library's node definitions, for editors' node palettes."""
from fastapi import APIRouter, Response

from ..deps import GenerationDep
from ..models import NodeDef
from .common import json_bytes

router = APIRouter(prefix="/v1", tags=["nodedefs"])


@router.get("/nodedefs", response_model=list[NodeDef], summary="Node definitions of the loaded libraries")
async def nodedefs(generation: GenerationDep) -> Response:
    return json_bytes(await generation.nodedefs())
