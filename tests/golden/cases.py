"""The golden shaders: the complete and specialized source of a few materials, and the
thumbnail's (specialized for environment lighting by importance sampling and no lights, as
`shadergen render` and the service's thumbnails generate it), both stages in every target (GLSL,
ESSL, WGSL, Vulkan GLSL, HLSL, Slang, MSL; OSL's one shader), committed so that any change to generated code shows up in review.

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


TARGETS = ("glsl", "essl", "wgsl", "vulkan", "hlsl", "slang", "msl", "osl")
STAGES = ("vertex", "pixel")
SUFFIXES = {("glsl", "vertex"): "vert", ("glsl", "pixel"): "frag", ("essl", "vertex"): "essl.vert",
            ("essl", "pixel"): "essl.frag", ("wgsl", "vertex"): "vert.wgsl", ("wgsl", "pixel"): "frag.wgsl",
            ("vulkan", "vertex"): "vulkan.vert", ("vulkan", "pixel"): "vulkan.frag",
            ("hlsl", "vertex"): "vert.hlsl", ("hlsl", "pixel"): "frag.hlsl", ("slang", "vertex"): "vert.slang",
            ("slang", "pixel"): "frag.slang", ("msl", "vertex"): "vert.metal", ("msl", "pixel"): "frag.metal",
            ("osl", "pixel"): "osl"}
CASES = [(name, variant, target, stage) for name in DOCUMENTS for variant in VARIANTS for target in TARGETS
         for stage in STAGES if (target, stage) in SUFFIXES]  # (OSL has no vertex stage)


def golden_path(name: str, variant: str, target: str = "glsl", stage: str = "pixel") -> Path:
    return HERE / f"{name}.{variant}.{SUFFIXES[(target, stage)]}"


def generate(generator, name: str, variant: str, target: str = "glsl", stage: str = "pixel") -> str:
    return generator.prepare(DOCUMENTS[name], target=target, **VARIANTS[variant]).emit()["stages"][stage]


def main() -> None:
    from shadergen.api import Generator
    generator = Generator()
    for case in CASES:
        golden_path(*case).write_text(generate(generator, *case))
        print(golden_path(*case).relative_to(ROOT))


if __name__ == "__main__":
    main()
