"""The golden shaders: the complete and specialized fragment source of a few materials, and the
thumbnail's (specialized for environment lighting by importance sampling and no lights, as
`shadergen render` and the service's thumbnails generate it), committed so that any change to
generated code shows up in review.

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
# variant -> generation options; a variant's name ends the golden file's name
VARIANTS = {"complete": {"interface": "complete"}, "specialized": {"interface": "specialized"},
            "thumbnail": {"interface": "specialized", "environment": "fis", "lights": False}}


def golden_path(name: str, variant: str) -> Path:
    return HERE / f"{name}.{variant}.frag"


def generate(generator, name: str, variant: str) -> str:
    return generator.prepare(DOCUMENTS[name], **VARIANTS[variant]).emit()["stages"]["pixel"]


def main() -> None:
    from shadergen.api import Generator
    generator = Generator()
    for name in DOCUMENTS:
        for variant in VARIANTS:
            golden_path(name, variant).write_text(generate(generator, name, variant))
            print(golden_path(name, variant).relative_to(ROOT))


if __name__ == "__main__":
    main()
