"""POST /v1/generate: a JSON body, or the raw document (MaterialX XML, a USD layer or usdz
package) with the parameters in the query."""
from typing import Annotated

from fastapi import APIRouter, Query, Request, Response
from pydantic import ValidationError

from ..deps import GenerationDep
from ..errors import ServiceError, from_validation_error
from ..generation import GenerateParams
from ..models import (CMS_DOC, NAMES_DOC, OCIO_CONFIG_DOC, OCIO_CONFIG_PATTERN, VALUES_DOC, Cms, GenerateRequest, Interface, Names,
                      ShaderRecord, Values)
from .common import ERRORS, USD_TYPES, json_bytes, media_type_of

router = APIRouter(prefix="/v1", tags=["generate"])

XML_TYPES = ("application/xml", "text/xml")
QUERY = ("target, element (a material's prim path, for USD), interface, values, names, cms, ocio_config and source "
         "come from the query")
BODY = {"requestBody": {"required": True, "content": {
    "application/json": {"schema": GenerateRequest.model_json_schema()},
    "application/xml": {"schema": {"type": "string", "minLength": 1, "description": f"the MaterialX document; {QUERY}"}},
    "model/vnd.usda": {"schema": {"type": "string", "minLength": 1, "description": "a USD layer (text) that refers to "
                                  f"no other file; one record per material, of the first or the named one; {QUERY}"}},
    "model/vnd.usdz+zip": {"schema": {"type": "string", "format": "binary", "description": "a usdz package; assets "
                                      f"and layers must lie inside it; {QUERY}"}},
}}}


@router.post("/generate", response_model=ShaderRecord, responses=ERRORS, openapi_extra=BODY,
             summary="Generate a shader and its variable listings")
async def generate(
    request: Request,
    generation: GenerationDep,
    target: Annotated[str, Query(max_length=64, description="with an XML or USD body")] = "glsl",
    element: Annotated[str | None, Query(max_length=1024, description="with an XML or USD body")] = None,
    interface: Annotated[Interface, Query(description="with an XML or USD body")] = "complete",
    source: Annotated[bool, Query(description="with an XML or USD body")] = True,
    values: Annotated[Values, Query(description=f"with an XML or USD body; {VALUES_DOC}")] = "listing",
    names: Annotated[Names, Query(description=f"with an XML or USD body; {NAMES_DOC}")] = "structural",
    cms: Annotated[Cms | None, Query(description=f"with an XML or USD body; {CMS_DOC}")] = None,
    ocio_config: Annotated[str | None, Query(max_length=256, pattern=OCIO_CONFIG_PATTERN,
                                             description=f"with an XML or USD body; {OCIO_CONFIG_DOC}")] = None,
) -> Response:
    media_type = media_type_of(request)
    body = await request.body()
    if media_type in XML_TYPES:
        document, params = body, GenerateParams(target, element, interface, source, values=values, names=names,
                                                cms=cms, ocio_config=ocio_config)
    elif media_type in USD_TYPES:
        document, params = body, GenerateParams(target, element, interface, source, USD_TYPES[media_type],
                                                values=values, names=names, cms=cms, ocio_config=ocio_config)
    elif media_type == "application/json":
        try:
            req = GenerateRequest.model_validate_json(body)
        except ValidationError as exc:
            raise from_validation_error(exc) from None
        document, params = req.document.encode(), GenerateParams(req.target, req.element, req.interface, req.source,
                                                                 keep=tuple(req.keep), values=req.values,
                                                                 names=req.names, cms=req.cms,
                                                                 ocio_config=req.ocio_config)
    else:
        raise ServiceError("unsupported_media_type", "send application/json, application/xml, model/vnd.usda or "
                           f"model/vnd.usdz+zip, not {media_type}")
    return json_bytes(await generation.generate(document, params))
