"""Identifiers for any name a document gives: what every target's code may spell.

Document names are anything XML or USD allows (`Ω材質`, `a-b`, `texture`, `2nd`). One spelling
serves every target (GLSL, ESSL, WGSL), so a uniform has the same name in each and a client binds
it by the listing in any of them:

- ASCII letters, digits and `_` stay; another character becomes `u` and its code point between
  underscores (`Ω` -> `u03A9`), punctuation an underscore; runs of underscores collapse, since
  GLSL reserves `__` anywhere in a name and WGSL at its start;
- a name that would start with a digit, or with a prefix the targets' own names use, gets `v_`;
- a name past IDENTIFIER_LIMIT keeps its start and a hash of the whole (glslang's tokens end at
  1,024 characters);
- RESERVED holds the keywords and reserved words of each language, the built-in functions and
  types a name would shadow, and the names the targets and the libraries write themselves.
"""
import re
from functools import lru_cache

from ..digest import sha256
from .cfamily.reserved import RESERVED_WORDS as CFAMILY_RESERVED
from .wgsl.builtins import WGSL_RESERVED

IDENTIFIER_LIMIT = 96

GLSL_KEYWORDS = set("""
attribute const uniform varying buffer shared coherent volatile restrict readonly writeonly layout centroid flat
smooth noperspective patch sample break continue do for while switch case default if else subroutine in out inout
float double int void bool true false invariant precise discard return mat2 mat3 mat4 mat2x2 mat2x3 mat2x4 mat3x2
mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 vec2 vec3 vec4 ivec2 ivec3 ivec4 bvec2 bvec3 bvec4 dvec2 dvec3 dvec4 uint uvec2
uvec3 uvec4 lowp mediump highp precision sampler1D sampler2D sampler3D samplerCube sampler2DShadow struct common
partition active asm class union enum typedef template this resource goto inline noinline public static extern
external interface long short half fixed unsigned superp input output filter sizeof cast namespace using main
texture sample output input dmat2 dmat3 dmat4 dmat2x2 dmat2x3 dmat2x4 dmat3x2 dmat3x3 dmat3x4 dmat4x2 dmat4x3
dmat4x4 hvec2 hvec3 hvec4 fvec2 fvec3 fvec4 atomic_uint sampler1DShadow samplerCubeShadow sampler1DArray
sampler2DArray sampler1DArrayShadow sampler2DArrayShadow isampler1D isampler2D isampler3D isamplerCube
isampler1DArray isampler2DArray usampler1D usampler2D usampler3D usamplerCube usampler1DArray usampler2DArray
sampler2DRect sampler2DRectShadow isampler2DRect usampler2DRect samplerBuffer isamplerBuffer usamplerBuffer
sampler2DMS isampler2DMS usampler2DMS sampler2DMSArray isampler2DMSArray usampler2DMSArray samplerCubeArray
samplerCubeArrayShadow isamplerCubeArray usamplerCubeArray sampler3DRect image1D image2D image3D imageCube
iimage1D iimage2D iimage3D iimageCube uimage1D uimage2D uimage3D uimageCube imageBuffer image2DArray
row_major packed
""".split())

# Built-in functions of GLSL 4.00 and ESSL 3.00: a variable of that name hides the function
GLSL_BUILTINS = set("""
radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh pow exp log exp2 log2 sqrt
inversesqrt abs sign floor trunc round roundEven ceil fract mod modf min max clamp mix step smoothstep isnan
isinf floatBitsToInt floatBitsToUint intBitsToFloat uintBitsToFloat fma frexp ldexp packUnorm2x16
packSnorm2x16 packUnorm4x8 packSnorm4x8 unpackUnorm2x16 unpackSnorm2x16 unpackUnorm4x8 unpackSnorm4x8
packHalf2x16 unpackHalf2x16 packDouble2x32 unpackDouble2x32 length distance dot cross normalize faceforward
reflect refract matrixCompMult outerProduct transpose determinant inverse lessThan lessThanEqual greaterThan
greaterThanEqual equal notEqual any all not uaddCarry usubBorrow umulExtended imulExtended bitfieldExtract
bitfieldInsert bitfieldReverse bitCount findLSB findMSB textureSize textureQueryLod texture textureProj
textureLod textureOffset texelFetch texelFetchOffset textureProjOffset textureLodOffset textureProjLod
textureProjLodOffset textureGrad textureGradOffset textureProjGrad textureProjGradOffset textureGather
textureGatherOffset textureGatherOffsets texture1D texture2D texture3D textureCube shadow2D dFdx dFdy fwidth
interpolateAtCentroid interpolateAtSample interpolateAtOffset noise1 noise2 noise3 noise4 EmitVertex
EndPrimitive EmitStreamVertex EndStreamPrimitive barrier memoryBarrier
""".split())

# GL_KHR_vulkan_glsl's types (textures and samplers apart, subpass inputs) and GLSL 4.50's built-ins
VULKAN_GLSL_NAMES = set("""
sampler samplerShadow texture1D texture2D texture3D textureCube texture2DRect texture1DArray texture2DArray
textureBuffer texture2DMS texture2DMSArray textureCubeArray itexture1D itexture2D itexture3D itextureCube
itexture2DRect itexture1DArray itexture2DArray itextureBuffer itexture2DMS itexture2DMSArray itextureCubeArray
utexture1D utexture2D utexture3D utextureCube utexture2DRect utexture1DArray utexture2DArray utextureBuffer
utexture2DMS utexture2DMSArray utextureCubeArray subpassInput isubpassInput usubpassInput subpassInputMS
isubpassInputMS usubpassInputMS subpassLoad textureSamples textureQueryLevels imageSize imageSamples
""".split())

# WGSL's predeclared functions and types (a declaration of that name hides them)
WGSL_BUILTINS = set("""
all any select arrayLength abs acos acosh asin asinh atan atanh atan2 ceil clamp cos cosh countLeadingZeros
countOneBits countTrailingZeros cross degrees determinant distance dot dot4U8Packed dot4I8Packed exp exp2
extractBits faceForward firstLeadingBit firstTrailingBit floor fma fract frexp insertBits inverseSqrt ldexp
length log log2 max min mix modf normalize pow quantizeToF16 radians reflect refract reverseBits round saturate
sign sin sinh smoothstep sqrt step tan tanh transpose trunc dpdx dpdxCoarse dpdxFine dpdy dpdyCoarse dpdyFine
fwidth fwidthCoarse fwidthFine textureDimensions textureGather textureGatherCompare textureLoad textureNumLayers
textureNumLevels textureNumSamples textureSample textureSampleBias textureSampleCompare
textureSampleCompareLevel textureSampleGrad textureSampleLevel textureSampleBaseClampToEdge textureStore
atomicLoad atomicStore atomicAdd atomicSub atomicMax atomicMin atomicAnd atomicOr atomicXor atomicExchange
atomicCompareExchangeWeak pack4x8snorm pack4x8unorm pack4xI8 pack4xU8 pack4xI8Clamp pack4xU8Clamp pack2x16snorm
pack2x16unorm pack2x16float unpack4x8snorm unpack4x8unorm unpack4xI8 unpack4xU8 unpack2x16snorm
unpack2x16unorm unpack2x16float storageBarrier textureBarrier workgroupBarrier workgroupUniformLoad bitcast
vec2f vec3f vec4f vec2i vec3i vec4i vec2u vec3u vec4u vec2h vec3h vec4h mat2x2f mat2x3f mat2x4f mat3x2f mat3x3f
mat3x4f mat4x2f mat4x3f mat4x4f mat2x2h mat2x3h mat2x4h mat3x2h mat3x3h mat3x4h mat4x2h mat4x3h mat4x4h
mat2x3 mat2x4 mat3x2 mat3x4 mat4x2 mat4x3 atomic sampler_comparison texture_1d texture_2d_array texture_3d
texture_cube texture_cube_array texture_multisampled_2d texture_depth_2d texture_depth_2d_array
texture_depth_cube texture_depth_cube_array texture_depth_multisampled_2d texture_external texture_storage_1d
texture_storage_2d texture_storage_2d_array texture_storage_3d
""".split())

# What the targets write themselves: main's locals, the stages' structs, blocks and entry points,
# the light loop's functions (glsl_target.py, wgsl/target.py), the structs of glsl.STRUCTS, and
# the libraries' global names outside the mx_/MX_ prefixes (a test reads every library file)
TARGET_NAMES = set("""
N V P L occlusion surfaceOpacity pointData closureData lightShader activeLightIndex hPositionWorld vd pu vu vin
vertexData vertexMain fragmentMain numActiveLightSources sampleLightSource MAX_LIGHT_SOURCES AppData VertexData
VertexUniforms PixelUniforms front_facing front_facing_in
surfaceshader volumeshader displacementshader lightshader BSDF EDF VDF material LightData
ClosureData FresnelData LobeFresnel SpecularLobe AIRY_FRESNEL_ITERATIONS CLOSURE_TYPE_DEFAULT
CLOSURE_TYPE_EMISSION CLOSURE_TYPE_INDIRECT CLOSURE_TYPE_REFLECTION CLOSURE_TYPE_TRANSMISSION
FRESNEL_MODEL_CONDUCTOR FRESNEL_MODEL_DIELECTRIC FRESNEL_MODEL_SCHLICK M_PI M_PI_INV M_FLOAT_EPS
""".split())
# the seed's uniforms and app data with fixed names (renderers bind them by name)
SEED_NAMES = {f"u_{space}{form}Matrix" for space in ("world", "view", "projection", "viewProjection")
              for form in ("", "Inverse", "Transpose", "InverseTranspose")} | set("""
u_viewPosition u_viewDirection u_envMatrix u_envRadiance u_envRadianceMips u_envRadianceSamples u_envIrradiance
u_envLightIntensity u_refractionTwoSided u_numActiveLightSources u_lightData u_time u_frame
i_position i_normal i_tangent i_bitangent
""".split())

RESERVED = frozenset(GLSL_KEYWORDS | GLSL_BUILTINS | VULKAN_GLSL_NAMES | WGSL_RESERVED | WGSL_BUILTINS | CFAMILY_RESERVED
                     | TARGET_NAMES
                     | SEED_NAMES)
# gl_ is GLSL's; the seed's numbered and named streams and ESSL's vertex data (`vd_<member>`) are
# named by the targets; mx_ and MX_ begin the libraries' functions and constants
RESERVED_PREFIXES = ("gl_", "__", "vd_", "i_texcoord_", "i_color_", "i_geomprop_", "u_geomprop_", "mx_", "MX_")
# WGSL passes a texture with its sampler, `<name>_sampler` (wgsl/target.py)
RESERVED_SUFFIXES = ("_sampler",)

_NOT_IDENTIFIER = re.compile(r"[^A-Za-z0-9_]")
_UNDERSCORES = re.compile(r"__+")


@lru_cache(maxsize=8192)  # a pure function, asked for the same names request after request
def identifier(wanted: str) -> str:
    """`wanted` spelled as an identifier every target accepts (not yet checked against RESERVED)."""
    name = wanted
    if _NOT_IDENTIFIER.search(name):
        name = _NOT_IDENTIFIER.sub(_spell, name)
        if not wanted.endswith("_"):
            name = name.rstrip("_")
    if "__" in name:
        name = _UNDERSCORES.sub("_", name)
    if not name.strip("_"):
        return "v"
    if len(name) > IDENTIFIER_LIMIT:
        digest = sha256(name.encode()).hexdigest()[:8]
        name = f"{name[:IDENTIFIER_LIMIT - 9].rstrip('_')}_{digest}"
    if name[0].isdigit():
        name = "v_" + name
    return name


def _spell(match: re.Match) -> str:
    c = match.group()
    return f"_u{ord(c):04X}_" if ord(c) > 127 else "_"

