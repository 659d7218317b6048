"""One router per resource; each route parses, calls a service function, responds."""
from . import editor, generate, health, jobs, nodedefs, preview, shaders, thumbnails

routers = [generate.router, shaders.router, thumbnails.router, jobs.router, nodedefs.router, preview.router, health.router,
           editor.router]
