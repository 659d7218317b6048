"""The golden shaders: the complete and specialized fragment source of a few materials, committed
so that any change to generated code shows up in review.

    python -m tests.golden.cases      # rewrite them after an intended change, and review the diff
"""
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
DOCUMENTS = {
    "marble_checker": ROOT / "examples" / "marble_checker.mtlx",
    "standard_surface_coated": HERE / "standard_surface_coated.mtlx",
    "glass": HERE / "glass.mtlx",
}
INTERFACES = ("complete", "specialized")


def golden_path(name: str, interface: str) -> Path:
    return HERE / f"{name}.{interface}.frag"


def generate(generator, name: str, interface: str) -> str:
    return generator.prepare(DOCUMENTS[name], interface=interface).emit()["stages"]["pixel"]


def main() -> None:
    from shadergen.api import Generator
    generator = Generator()
    for name in DOCUMENTS:
        for interface in INTERFACES:
            golden_path(name, interface).write_text(generate(generator, name, interface))
            print(golden_path(name, interface).relative_to(ROOT))


if __name__ == "__main__":
    main()
