"""What one API worker process holds for its lifetime: the store, its generation pool, the job
back end. Built in the app's lifespan, from settings, never at import time."""
from dataclasses import dataclass

from .batches import BatchService
from .cache import GuardedStore, open_store
from .config import Settings
from .generation import GenerationService
from .jobs import JobBackend, open_jobs
from .thumbnails import ThumbnailService
from .workers.pool import ProcessPool


@dataclass
class Services:
    settings: Settings
    store: GuardedStore
    generation: GenerationService
    jobs: JobBackend
    thumbnails: ThumbnailService
    batches: BatchService

    @classmethod
    async def start(cls, settings: Settings) -> "Services":
        store = open_store(settings.cache, settings.cache_max_bytes)
        pool = ProcessPool("service.workers.gen_worker", size=settings.generate_processes,
                           queue_size=settings.generate_queue_size, timeout_s=settings.generate_timeout_s,
                           env=settings.to_env(), limits=settings.child_limits(settings.generate_memory_mib),
                           name="generator")
        await pool.start()
        generation = GenerationService(pool, store, settings.retry_after_s, settings.include_roots)
        try:
            jobs = await open_jobs(settings)
        except BaseException:
            await pool.close()
            raise
        thumbnails = ThumbnailService(generation, jobs, store, settings.texture_roots, settings.retry_after_s)
        batches = BatchService(thumbnails, store, settings.batch_concurrency, settings.retry_after_s,
                               settings.batch_lease_s)
        return cls(settings, store, generation, jobs, thumbnails, batches)

    async def stop(self) -> None:
        await self.jobs.close()
        await self.generation.pool.close()
        await self.store.aclose()
        self.store.close()
