"""Prints, one a line, what pip installs for the image: the build requirements, the dependencies
and the extras the image has (IMAGE_EXTRAS), all read from pyproject.toml. The image installs them
in a layer of their own (rebuilt only when they change); docker/build.sh makes wheels of the same
list. Usage: python3 docker/requirements.py pyproject.toml"""
import sys
import tomllib

IMAGE_EXTRAS = ["service", "render", "usd", "ocio"]


def requirements(pyproject: dict, extras: list[str]) -> list[str]:
    project = pyproject["project"]
    found = list(pyproject["build-system"]["requires"]) + list(project.get("dependencies", []))
    for extra in extras:
        found += project["optional-dependencies"][extra]
    return found


if __name__ == "__main__":
    with open(sys.argv[1], "rb") as f:
        print("\n".join(requirements(tomllib.load(f), IMAGE_EXTRAS)))
