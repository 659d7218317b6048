"""What a browser needs to draw a record exactly as the thumbnails are drawn: the renderer's own
scene and environment uniforms, its sphere's vertex streams and its environment maps. Built once
per API process, from the renderer's code (nothing here restates a camera or a sky)."""
from functools import lru_cache

import numpy as np

THUMBNAIL_MESH = "sphere"


@lru_cache(maxsize=1)
def preview_assets() -> tuple[dict, dict[str, bytes]]:
    """(the scene description, its arrays by name as raw little-endian bytes)."""
    from shadergen.render.environment import Environment
    from shadergen.render.geometry import load_mesh
    from shadergen.render.imageio import BACKGROUND
    from shadergen.render.inputs import fixed_uniforms

    environment = Environment.procedural()
    mesh = load_mesh(THUMBNAIL_MESH)
    uniforms = {name: np.frombuffer(value, "<f4").tolist() if isinstance(value, bytes) else value
                for name, value in fixed_uniforms(environment).items()}
    uniforms["u_numActiveLightSources"] = [0.0]  # thumbnails are lit by the environment alone
    arrays = {name: np.ascontiguousarray(data, "<f4") for name, data in mesh.streams.items()}
    arrays["indices"] = np.ascontiguousarray(mesh.indices, "<u4")
    maps = {"u_envRadiance": environment.radiance, "u_envIrradiance": environment.irradiance}
    arrays.update({name: np.ascontiguousarray(image, "<f4") for name, image in maps.items()})
    scene = {
        "uniforms": uniforms,
        "background": BACKGROUND,
        "mesh": {"name": THUMBNAIL_MESH, "vertices": len(mesh.streams["i_position"]),
                 "indices": len(mesh.indices),
                 "streams": {name: int(data.shape[1]) for name, data in mesh.streams.items()}},
        "environment": {name: {"height": int(image.shape[0]), "width": int(image.shape[1]),
                               "channels": int(image.shape[2])} for name, image in maps.items()},
    }
    return scene, {name: data.tobytes() for name, data in arrays.items()}
