"""One router per resource; each route parses, calls a service function, responds."""
from . import editor, generate, health, images, jobs, nodedefs, preview, shaders, textures, thumbnails

routers = [generate.router, shaders.router, thumbnails.router, jobs.router, nodedefs.router, preview.router,
           textures.router, images.router, health.router, editor.router]
