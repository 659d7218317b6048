"""`Annotated` dependencies: routes name what they need, the app state provides it. They are
`async def` on purpose: FastAPI runs a plain `def` dependency in a thread, a hop that costs more
than everything else a cached request does."""
from typing import Annotated

from fastapi import Depends, Request

from .batches import BatchService
from .generation import GenerationService
from .jobs import JobBackend
from .services import Services
from .thumbnails import ThumbnailService


async def get_services(request: Request) -> Services:
    return request.app.state.services


ServicesDep = Annotated[Services, Depends(get_services)]


async def get_generation(services: ServicesDep) -> GenerationService:
    return services.generation


async def get_jobs(services: ServicesDep) -> JobBackend:
    return services.jobs


async def get_thumbnails(services: ServicesDep) -> ThumbnailService:
    return services.thumbnails


GenerationDep = Annotated[GenerationService, Depends(get_generation)]
JobsDep = Annotated[JobBackend, Depends(get_jobs)]
ThumbnailsDep = Annotated[ThumbnailService, Depends(get_thumbnails)]


async def get_batches(services: ServicesDep) -> BatchService:
    return services.batches


BatchesDep = Annotated[BatchService, Depends(get_batches)]
