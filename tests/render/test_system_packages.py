"""The renderer's shared libraries come from packages scripts/system-packages.sh installs, and a
missing one is named with its package."""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from shadergen.render.context import install_hint

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "system-packages.sh"
LOADED_BY_THE_EGL_BACK_END = ("libEGL.so.1", "libGL.so.1")


def installed_packages() -> set[str]:
    return set(re.search(r"pkgs=\(([^)]*)\)", SCRIPT.read_text()).group(1).split())


@pytest.mark.parametrize("library", LOADED_BY_THE_EGL_BACK_END)
def test_every_library_the_renderer_loads_is_installed_by_the_script(library, require_tool):
    require_tool("dpkg"), require_tool("ldconfig")
    cache = subprocess.run(["ldconfig", "-p"], capture_output=True, text=True).stdout
    path = re.search(rf"{re.escape(library)} \(libc6,x86-64\) => (\S+)", cache)
    assert path, f"{library} is not installed"
    owner = subprocess.run(["dpkg", "-S", str(Path(path.group(1)).resolve())], capture_output=True, text=True)
    package = owner.stdout.split(":")[0]
    assert package in installed_packages(), f"{library} comes from {package}, which the script does not install"


def test_a_missing_library_names_its_package():
    hint = install_hint("libGL.so.1: cannot open shared object file: No such file or directory")
    assert "libgl1" in hint and "libgl1" in installed_packages()
    assert "libegl1" in install_hint("no EGL display")  # nothing named: the whole stack
