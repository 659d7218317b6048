"""The variables library code reads that the generator declares: the environment's uniforms and
the light rig's. Library sources are checked against these (code/library.py); a surface declares
them (nodes/surface.py). And the macros of the library's ways of lighting by the environment, which
a shader generated for one of them decides (code/library.py resolves the library's sections for
each)."""
from .types import ir_type

ENVIRONMENT_UNIFORMS = (  # (name, MaterialX type)
    ("u_envMatrix", "matrix44"), ("u_envRadiance", "filename"), ("u_envLightIntensity", "float"),
    ("u_envRadianceMips", "integer"), ("u_envRadianceSamples", "integer"), ("u_envIrradiance", "filename"),
    ("u_refractionTwoSided", "boolean"), ("u_viewPosition", "vector3"),
)
# Ways of environment lighting, each with the compiler macros a renderer defines for it: filtered
# importance sampling; a prefiltered map, one lookup; that lookup corrected by a few samples.
ENVIRONMENT_MACROS = {"fis": (), "prefilter": ("MX_ENV_PREFILTER",), "hybrid": ("MX_ENV_PREFILTER", "MX_ENV_HYBRID")}
EXTERNALS = {**{name: ir_type(t) for name, t in ENVIRONMENT_UNIFORMS},
             "u_numActiveLightSources": "int", "u_lightData": "LightData[MAX_LIGHT_SOURCES]"}


def environment_macros(environment: str | None) -> frozenset[tuple[str, bool]]:
    """The compiler macros a shader for `environment` (ENVIRONMENT_MACROS, None: either) has decided."""
    if environment is None:
        return frozenset()
    defined = ENVIRONMENT_MACROS[environment]
    return frozenset((macro, macro in defined) for macros in ENVIRONMENT_MACROS.values() for macro in macros)
