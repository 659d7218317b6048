"""The one test of folder confinement that documents, textures and the service share."""
import os


def inside(path: str | os.PathLike, folder: str | os.PathLike) -> bool:
    """Whether `path` is `folder` or lies under it; both absolute and made normal (or real) by the
    caller, which decides whether links are followed. Compared by components, so `/srv/data2`
    is not inside `/srv/data`."""
    path, folder = os.fspath(path), os.fspath(folder)
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)
