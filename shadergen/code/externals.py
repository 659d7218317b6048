"""The variables library code reads that the generator declares: the environment's uniforms and
the light rig's. Library sources are checked against these (code/library.py); a surface declares
them (nodes/surface.py)."""
from .types import ir_type

ENVIRONMENT_UNIFORMS = (  # (name, MaterialX type)
    ("u_envMatrix", "matrix44"), ("u_envRadiance", "filename"), ("u_envLightIntensity", "float"),
    ("u_envRadianceMips", "integer"), ("u_envRadianceSamples", "integer"), ("u_envIrradiance", "filename"),
    ("u_refractionTwoSided", "boolean"), ("u_viewPosition", "vector3"),
)
EXTERNALS = {**{name: ir_type(t) for name, t in ENVIRONMENT_UNIFORMS},
             "u_numActiveLightSources": "int", "u_lightData": "LightData[MAX_LIGHT_SOURCES]"}
