"""One router per resource; each route parses, calls a service function, responds."""
from . import generate, health, jobs, nodedefs, shaders, thumbnails

routers = [generate.router, shaders.router, thumbnails.router, jobs.router, nodedefs.router, health.router]
