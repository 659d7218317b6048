"""USD scenes (and their MaterialX equivalents) written once per session with usd-core (imported
by the test modules first, which skip, or fail under CI=true, without it)."""
from pathlib import Path

import pytest

from shadergen.api import Generator


class Scenes:
    def __init__(self, folder: Path):
        from .scenes import (PREVIEW_SURFACE_MTLX, STANDARD_SURFACE_MTLX, TEXTURE, preview_surface_stage,
                             standard_surface_stage, write_checker, write_mtlx, write_scene, write_usdz)

        self.folder = folder
        write_checker(folder)
        self.preview = write_scene(folder, "preview.usda", preview_surface_stage)
        self.preview_mtlx = write_mtlx(folder, "preview.mtlx", PREVIEW_SURFACE_MTLX)
        self.brick = write_scene(folder, "brick.usda", standard_surface_stage)
        self.brick_mtlx = write_mtlx(folder, "brick.mtlx", STANDARD_SURFACE_MTLX)
        package = folder / "package"
        package.mkdir()
        write_checker(package)
        layer = write_scene(package, "scene.usdc", preview_surface_stage)  # binary crate inside the package
        self.usdz = write_usdz(folder, "preview.usdz", layer, package / TEXTURE)


@pytest.fixture(scope="session")
def scenes(tmp_path_factory) -> Scenes:
    return Scenes(tmp_path_factory.mktemp("usd"))


@pytest.fixture(scope="session")
def gen() -> Generator:
    return Generator()
